# Scene chart: ms per step per scene for Tumble and its peers, from one run of scripts/bench.sh
# (engines stepped in turn in one process). Log scale, so a factor reads the same anywhere; a
# missing bar is a peer that refuses the scene or ran out of its time budget.
# Input: DATA (scene,tumble,box2d,box2d3,chipmunk, made by scripts/bench.sh), TITLE; output: OUT.
set terminal pngcairo size 1250,540 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set datafile missing NaN
set style data histogram
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set logscale y
set ylabel "ms per step (median of the rounds; lower is faster)"
set grid ytics
set key top left
set xtics rotate by -20
set title TITLE
plot DATA every ::1 using 2:xtic(1) title "Tumble" lc rgb "#1f77b4", '' every ::1 using 4 title "Box2D v3" lc rgb "#2ca02c", \
     '' every ::1 using 3 title "Box2D 2.4.1" lc rgb "#7f7f7f", '' every ::1 using 5 title "Chipmunk 7" lc rgb "#ff7f0e"
