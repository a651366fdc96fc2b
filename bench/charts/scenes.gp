# Scene chart: ms per step per scene for Tumble and its peers (same run).
# Input: DATA (scenes_wide.csv: scene,tumble,box2d,box2d3,chipmunk, made by scripts/bench.sh); output: OUT.
set terminal pngcairo size 1250,520 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set style data histogram
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set logscale y
set ylabel "ms per step (median)"
set grid ytics
set key top left
set title "Scenes: Tumble vs Box2D 2.4.1 vs Box2D v3 vs Chipmunk 7 (one process, one run)"
plot DATA every ::1 using 2:xtic(1) title "Tumble", '' every ::1 using 3 title "Box2D 2.4.1", \
     '' every ::1 using 4 title "Box2D v3", '' every ::1 using 5 title "Chipmunk 7"
