# Narrow-phase chart: ns per polygon pair against normal and depth error, for Tumble's SAT (through
# tbCollideShapes, and through tbCollidePolygons, the call Box2D v3's row makes), its GJK/EPA, and
# Box2D v3's b2CollidePolygons, on the same pairs. Colour: method; circle: boxes, triangle: hulls;
# filled: mean error, open: largest.
# Input: DATA (narrowphase.csv); output: OUT.
set terminal pngcairo size 1200,520 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set logscale y
set xlabel "ns per pair"
set grid
set key below horizontal maxcols 4 font ",9"
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
set multiplot layout 1,2 title "Narrow phase: cost vs error against a double-precision SAT reference (4,096 shallow overlaps per family)"
colour(m) = (m eq "box2d-3" ? 0x2ca02c : (m eq "gjk" ? 0x9467bd : (m eq "sat_local" ? 0xff7f0e : 0x1f77b4)))
mean(f) = (f eq "boxes" ? 7 : 9)
most(f) = (f eq "boxes" ? 6 : 8)
do for [panel = 0:1] {
	c = panel == 0 ? 5 : 7
	set title (panel == 0 ? "normal error (rad)" : "depth error (m)")
	set ylabel (panel == 0 ? "angle to the reference normal (rad)" : "|depth - reference| (m)")
	plot DATA every ::1 using 4:(column(c) + 1e-9):(mean(strcol(2))):(colour(strcol(1))) with points pt variable ps 1.6 lc rgb variable notitle, \
	     DATA every ::1 using 4:(column(c + 1) + 1e-9):(most(strcol(2))):(colour(strcol(1))) with points pt variable ps 1.6 lc rgb variable notitle, \
	     1/0 with points pt 7 lc rgb "#1f77b4" title "Tumble SAT, tbCollideShapes (the world's path)", \
	     1/0 with points pt 7 lc rgb "#ff7f0e" title "Tumble SAT, tbCollidePolygons (v3's form)", \
	     1/0 with points pt 7 lc rgb "#9467bd" title "Tumble GJK/EPA", \
	     1/0 with points pt 7 lc rgb "#2ca02c" title "Box2D v3 b2CollidePolygons", \
	     1/0 with points pt 7 lc rgb "black" title "boxes, mean", \
	     1/0 with points pt 6 lc rgb "black" title "boxes, largest", \
	     1/0 with points pt 9 lc rgb "black" title "hulls, mean", \
	     1/0 with points pt 8 lc rgb "black" title "hulls, largest"
}
unset multiplot
