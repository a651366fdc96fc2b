# Broad-phase chart: ms per step (proxy moves and the pair update) against body count, log-log, one
# panel per size mix, a line per method: Tumble's four and Box2D v3's own dynamic tree.
# Input: DATA (broadphase.csv: method,bodies,sizes,ms_per_step); output: OUT.
set terminal pngcairo size 1300,900 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set datafile missing NaN
set logscale xy
set xlabel "bodies (all moving)"
set ylabel "ms per step"
set grid
set key top left font ",9"
methods = "tree sort_and_sweep spatial_hash brute_force box2d3_tree"
names = "Tumble-tree Tumble-sort-and-sweep Tumble-spatial-hash Tumble-brute-force Box2D-v3-tree"
colours = "#1f77b4 #ff7f0e #9467bd #7f7f7f #2ca02c"
set multiplot layout 2,2 title "Broad phase: cost vs body count, the best of three rounds (lower is faster)"
do for [s in "uniform mixed wide sparse"] {
	set title (s eq "uniform" ? "uniform: 1 m boxes" : (s eq "mixed" ? "mixed: 0.2-2 m" : (s eq "wide" ? "wide: 0.1-10 m" : "sparse: 1 m boxes, one per 400 m2")))
	plot for [i=1:5] DATA every ::1 using 2:((strcol(1) eq word(methods, i) && strcol(3) eq s) ? $4 : 1/0) \
		with linespoints lw (i == 5 ? 2 : 1) pt 7 lc rgb word(colours, i) title word(names, i)
}
unset multiplot
