# Narrow-phase chart: ns per polygon pair against normal and depth error, SAT vs GJK/EPA.
# Input: DATA (narrowphase.csv); output: OUT.
set terminal pngcairo size 1200,480 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set logscale y
set xlabel "ns per pair"
set grid
set key top right
set offsets graph 0.1, graph 0.1, graph 0.1, graph 0.1
set multiplot layout 1,2 title "Narrow phase: cost vs error against a double-precision SAT reference (4,096 shallow overlaps)"
set title "normal error (rad)"
set ylabel "angle to reference normal (rad)"
plot DATA every ::1 using 4:($5 + 1e-9):(sprintf("%s %s mean", strcol(1), strcol(2))) with labels point pt 7 offset 1,0.5 left notitle, \
     DATA every ::1 using 4:($6 + 1e-9):(sprintf("%s %s max", strcol(1), strcol(2))) with labels point pt 6 offset 1,-0.5 left notitle, \
     DATA every ::1 using 4:((strcol(1) eq "sat") ? $5 + 1e-9 : 1/0) with points pt 6 ps 3.5 lw 2 lc rgb "#d62728" title "auto (SAT for polygons)"
set title "depth error (m)"
set ylabel "|depth − reference| (m)"
plot DATA every ::1 using 4:($7 + 1e-9):(sprintf("%s %s mean", strcol(1), strcol(2))) with labels point pt 7 offset 1,0.5 left notitle, \
     DATA every ::1 using 4:($8 + 1e-9):(sprintf("%s %s max", strcol(1), strcol(2))) with labels point pt 6 offset 1,-0.5 left notitle, \
     DATA every ::1 using 4:((strcol(1) eq "sat") ? $7 + 1e-9 : 1/0) with points pt 6 ps 3.5 lw 2 lc rgb "#d62728" title "auto (SAT for polygons)"
unset multiplot
