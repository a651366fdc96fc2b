# Solver chart: time per step (210-box pyramid) against three error measures, one panel each.
# Tumble's soft step and Box2D v3 (also a soft step) each drawn as a curve through 1, 2, 4 and 8
# sub-steps, so the two engines' cost-for-accuracy can be read side by side.
# Input: DATA (solver.csv from `tumble-bench solver-chart`); output: OUT (PNG).
set terminal pngcairo size 1500,600 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set key below horizontal maxcols 3 font ",8"
set logscale xy
set xlabel "ms per step (210-box pyramid)"
set grid
set multiplot layout 1,3 title "Solver: cost vs error, Tumble and Box2D v3 at 1, 2, 4, 8 sub-steps (lower left is better)"
do for [col in "5 6 7"] {
	c = int(col)
	f = c + 3
	set title (c == 5 ? "stack drift after 10 s (m)" : (c == 6 ? "largest penetration, pyramid (m)" : "bounce apex error (relative)"))
	set ylabel (c == 5 ? "drift (m)" : (c == 6 ? "penetration (m)" : "|apex − e²h| / e²h"))
	plot DATA every ::1 using ($4):((strcol(2) eq "soft") ? column(c) + 1e-6 : 1/0) with linespoints pt 7 ps 1.2 lc rgb "#1f77b4" title "Tumble soft step (1,2,4,8 sub-steps)", \
	     DATA every ::1 using ($4):((strcol(2) eq "soft-scalar") ? column(c) + 1e-6 : 1/0) with points pt 4 ps 1.6 lc rgb "#1f77b4" title "soft, 4 sub-steps, scalar reference solver", \
	     DATA every ::1 using ($4):((strcol(2) eq "soft-point-friction") ? column(c) + 1e-6 : 1/0) with points pt 8 ps 1.6 lc rgb "#9467bd" title "soft, 4 sub-steps, a friction row per point", \
	     DATA every ::1 using ($4):((strcol(2) eq "baumgarte") ? column(c) + 1e-6 : 1/0) with points pt 5 ps 1.2 title "baumgarte (1,2,4,8 it.)", \
	     DATA every ::1 using ($4):((strcol(2) eq "ngs") ? column(c) + 1e-6 : 1/0) with points pt 9 ps 1.4 title "ngs (1,2,4,8 it.)", \
	     DATA every ::1 using ($4):((strcol(2) eq "box2d-2.4.1") ? column(c) + 1e-6 : 1/0) with points pt 13 ps 2 lc rgb "black" title "Box2D 2.4.1 (8/3)", \
	     DATA every ::1 using ($4):((strcol(2) eq "box2d-3") ? column(c) + 1e-6 : 1/0) with linespoints pt 15 ps 1.6 lw 2 lc rgb "#2ca02c" title "Box2D v3 (1,2,4,8 sub-steps)", \
	     DATA every ::1 using ($4):((strcol(2) eq "chipmunk-7") ? column(c) + 1e-6 : 1/0) with points pt 11 ps 2 lc rgb "red" title "Chipmunk 7 (10 it.)", \
	     DATA every ::1 using ($4):(column(f) == 1 ? column(c) + 1e-6 : 1/0) smooth unique with lines lc rgb "gray" dt 2 title "Pareto front", \
	     DATA every ::1 using ($4):((strcol(1) eq "soft-4") ? column(c) + 1e-6 : 1/0) with points pt 6 ps 3.5 lw 2 lc rgb "#d62728" title "default (auto): soft, 4 sub-steps"
}
unset multiplot
