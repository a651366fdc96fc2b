# Size sweep of tumble-bench-games --sweep: µs per step against bodies, log-log, for Tumble and
# Box2D v3.2 stepped in turn in one process; mixed boxes, circles and capsules falling into a box
# (awake, timed over the fall and the landing) and the same world once settled (asleep).
# Input: DATA (bodies,tumble_awake_us,box2d3_awake_us,awake_ratio,tumble_asleep_us,box2d3_asleep_us,...);
# output: OUT.
set terminal pngcairo size 1000,620 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set datafile missing NaN
set logscale xy
set xlabel "bodies"
set ylabel "µs per step (median of the rounds; lower is faster)"
set grid xtics ytics mxtics mytics
set key top left
set format x "%g"
set format y "%g"
set title "Game-scale size sweep: Tumble and Box2D v3.2 in one process (1/60 s, 4 sub-steps)"
plot DATA every ::1 using 1:2 with linespoints pt 7 lw 2 lc rgb "#1f77b4" title "Tumble, awake (falling)", \
     '' every ::1 using 1:3 with linespoints pt 5 lw 2 lc rgb "#2ca02c" title "Box2D v3.2, awake (falling)", \
     '' every ::1 using 1:5 with linespoints pt 6 lw 2 dt 2 lc rgb "#1f77b4" title "Tumble, asleep (settled)", \
     '' every ::1 using 1:6 with linespoints pt 4 lw 2 dt 2 lc rgb "#2ca02c" title "Box2D v3.2, asleep (settled)"
