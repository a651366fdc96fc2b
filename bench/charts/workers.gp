# Workers chart: ms per step on 1 and 2 workers for Tumble (reference task system) and Box2D v3
# (its own scheduler), stepped in turn in one process; the speed-ups are printed above the bars.
# Input: DATA (workers.csv: scene,tumble_1,tumble_2,box2d3_1,box2d3_2); output: OUT.
set terminal pngcairo size 1250,540 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set style data histogram
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set logscale y
set ylabel "ms per step (median of the rounds; lower is faster)"
set grid ytics
set key top left
set xtics rotate by -20
set title "Workers: Tumble and Box2D v3 on 1 and 2 workers (speed-up of 2 over 1 above each pair)"
plot DATA every ::1 using 2:xtic(1) title "Tumble, 1 worker" lc rgb "#aec7e8", \
     '' every ::1 using 3 title "Tumble, 2 workers" lc rgb "#1f77b4", \
     '' every ::1 using 4 title "Box2D v3, 1 worker" lc rgb "#98df8a", \
     '' every ::1 using 5 title "Box2D v3, 2 workers" lc rgb "#2ca02c", \
     '' every ::1 using ($0 - 0.2):(($2 > $3 ? $2 : $3) * 1.2):(sprintf("%.2fx", $2 / $3)) with labels font ",8" notitle, \
     '' every ::1 using ($0 + 0.2):(($4 > $5 ? $4 : $5) * 1.2):(sprintf("%.2fx", $4 / $5)) with labels font ",8" notitle
