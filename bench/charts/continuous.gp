# Continuous-collision chart: (left) ns per TOI query vs error against closed forms; (right) the
# fraction of bodies that pass through a 0.1 m wall vs speed, per method and peer.
# Input: TOI (toi.csv), TUNNEL (tunnel.csv); output: OUT.
set terminal pngcairo size 1300,500 font ",10"
set output OUT
set termoption noenhanced
set datafile separator ","
set grid
set multiplot layout 1,2 title "Continuous collision"
set title "time of impact: cost vs error (closed-form reference)"
set xlabel "ns per query"
set ylabel "error at impact (m)"
set logscale y
set offsets graph 0.15, graph 0.3, graph 0.1, graph 0.1
plot TOI every ::1 using 4:($5 + 1e-9):(sprintf("%s/%s mean", strcol(1), strcol(2))) with labels point pt 7 offset 1,0.5 left notitle, \
     TOI every ::1 using 4:($6 + 1e-9):(sprintf("%s/%s max", strcol(1), strcol(2))) with labels point pt 6 offset 1,-0.5 left notitle, \
     TOI every ::1 using 4:(((strcol(2) eq "circles" && strcol(1) eq "quadratic") || (strcol(2) ne "circles" && strcol(1) eq "conservative")) ? $5 + 1e-9 : 1/0) \
         with points pt 6 ps 3.5 lw 2 lc rgb "#d62728" title "default (auto): quadratic for circles, CA otherwise"
unset logscale y
set offsets 0,0,0,0
set title "tunnelling through a 0.1 m wall (20 bodies per point)"
set xlabel "speed (m/s)"
set ylabel "fraction through"
set logscale x
set yrange [-0.05:1.05]
set key top left font ",8"
dash(s) = (s eq "boxes" ? 2 : 1)
plot for [m in "off quadratic conservative box2d-2.4.1 box2d-3 chipmunk-7"] for [s in "circles boxes"] \
	TUNNEL every ::1 using ((strcol(1) eq m && strcol(2) eq s) ? $3 : 1/0):4 with linespoints dt dash(s) \
	title sprintf("%s, %s", m, s)
unset multiplot
