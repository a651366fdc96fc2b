# Broad-phase chart: ms per step against body count, log–log, per method and size mix.
# Input: DATA (broadphase.csv: method,bodies,sizes,ms_per_step); output: OUT.
set terminal pngcairo size 900,600 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set datafile missing NaN
set logscale xy
set xlabel "bodies"
set ylabel "ms per step (moves + pair update)"
set key top left
set grid
set title "Broad phase: cost vs body count"
dash(s) = (s eq "mixed" ? 2 : 1)
plot for [m in "tree sort_and_sweep brute_force"] for [s in "uniform mixed"] \
	DATA every ::1 using 2:((strcol(1) eq m && strcol(3) eq s) ? $4 : 1/0) with linespoints \
	dt dash(s) title sprintf("%s, %s", m, s), \
	DATA every ::1 using ((($2 <= 4096 && strcol(1) eq "sort_and_sweep") || ($2 > 4096 && strcol(1) eq "tree")) ? $2 : 1/0):4 \
	with points pt 6 ps 3 lw 2 lc rgb "#d62728" title "auto (rule in world.c, every body moving)"
