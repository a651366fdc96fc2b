# Continuous-collision chart: (left) ns per time-of-impact query against the error at impact, each
# engine's result against the closed form at its own target separation; (right) the fraction of
# bodies that pass through a 0.1 m wall against speed, per method and peer.
# Input: TOI (toi.csv), TUNNEL (tunnel.csv); output: OUT.
set terminal pngcairo size 1300,520 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set grid
set multiplot layout 1,2 title "Continuous collision"
set title "time of impact: cost vs error (closed-form reference; filled: mean, open: largest)"
set xlabel "ns per query"
set ylabel "error at impact (m)"
set logscale y
set key below horizontal maxcols 3 font ",9"
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
colour(m) = (m eq "box2d-3" ? 0x2ca02c : (m eq "quadratic" ? 0xd62728 : 0x1f77b4))
mean(f) = (f eq "circles" ? 7 : 5)
most(f) = (f eq "circles" ? 6 : 4)
plot TOI every ::1 using 4:($5 + 1e-9):(mean(strcol(2))):(colour(strcol(1))) with points pt variable ps 1.6 lc rgb variable notitle, \
     TOI every ::1 using 4:($6 + 1e-9):(most(strcol(2))):(colour(strcol(1))) with points pt variable ps 1.6 lc rgb variable notitle, \
     1/0 with points pt 7 lc rgb "#d62728" title "Tumble quadratic (circles; the default)", \
     1/0 with points pt 7 lc rgb "#1f77b4" title "Tumble conservative advancement", \
     1/0 with points pt 7 lc rgb "#2ca02c" title "Box2D v3 b2TimeOfImpact", \
     1/0 with points pt 7 lc rgb "black" title "circles, mean (open: largest)", \
     1/0 with points pt 5 lc rgb "black" title "boxes, mean (open: largest)"
unset logscale y
set offsets 0,0,0,0
set title "tunnelling through a 0.1 m wall (20 bodies per point)"
set xlabel "speed (m/s)"
set ylabel "fraction through"
set logscale x
set yrange [-0.05:1.05]
set key inside top left font ",8"
# A small lift per method keeps the lines that all stay at 0 (nothing through) apart.
methods = "off quadratic conservative box2d-2.4.1 box2d-3 chipmunk-7"
colours = "#7f7f7f #d62728 #1f77b4 #000000 #2ca02c #ff7f0e"
dash(s) = (s eq "boxes" ? 2 : 1)
plot for [i=1:6] for [s in "circles boxes"] \
	TUNNEL every ::1 using ((strcol(1) eq word(methods, i) && strcol(2) eq s) ? $3 : 1/0):($4 + 0.008 * i) \
	with linespoints dt dash(s) lc rgb word(colours, i) pt 7 ps 0.6 title sprintf("%s, %s", word(methods, i), s)
unset multiplot
