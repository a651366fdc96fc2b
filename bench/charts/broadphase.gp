# Broad-phase chart: ms per step against body count, log–log; colour by method, dash by size mix.
# Input: DATA (broadphase.csv: method,bodies,sizes,ms_per_step); output: OUT.
set terminal pngcairo size 1100,700 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set datafile missing NaN
set logscale xy
set xlabel "bodies"
set ylabel "ms per step (moves + pair update)"
set key outside right
set grid
set title "Broad phase: cost vs body count (every body moving)"
dash(s) = (s eq "mixed" ? 2 : (s eq "wide" ? 3 : (s eq "sparse" ? 4 : 1)))
methods = "tree sort_and_sweep spatial_hash brute_force"
plot for [i=1:4] for [s in "uniform mixed wide sparse"] \
	DATA every ::1 using 2:((strcol(1) eq word(methods, i) && strcol(3) eq s) ? $4 : 1/0) with linespoints \
	lc i pt i dt dash(s) title sprintf("%s, %s", word(methods, i), s)
