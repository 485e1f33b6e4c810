# The sensor physics speed-accuracy chart (docs/sensor-physics-speed-accuracy.png) from
# docs/data/sensor-physics-speed-accuracy.csv: conescan-sensor-physics-speed --chart-csv of each
# case, its name in the first column. Run by scripts/sensor-physics-chart.sh, which passes:
#   data, output   the CSV and the PNG
#   geometric_ns   WGS84's geometric scan row's time (ns): the target is 10 times it
#   reference_floor  the reference's own error (deg) at its grid step
set terminal pngcairo size 1200,760 enhanced font "DejaVu Sans,11"
set output output
set datafile separator ","
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "time per head-row (ns, median of the benchmark's runs; log)"
set ylabel "worst |crossing - reference| over the reference rows (deg; log)"
set title "MODEL §12's crossings: speed against accuracy (docs/SENSOR_PHYSICS.md, \"Cost\", \"The table\")\n1 ms of lag at 1 rev/s, normalised 1/2, along the paper's e = 0.1 orbit; labels: times the case's geometric row;\ntable: its rows alone; table-day: over a day at 1 s with its build (evaluations of the chain)" noenhanced
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top box noenhanced
set xrange [10:1e8]
set yrange [1e-9:10]

# The target: at most 10 times the geometric row (WGS84's), within 1e-6 deg of the reference.
set object 1 rect from graph 0, graph 0 to first 10*geometric_ns, first 1e-6 fc rgb "#e8f5e9" fs solid 1.0 noborder behind
set label "target: <= 10 x geometric, <= 1e-6 deg" at first 12, first 3e-7 tc rgb "#2e7d32" noenhanced
set arrow from graph 0, first 1e-6 to graph 1, first 1e-6 nohead dt 2 lc rgb "#2e7d32"
set arrow from first 10*geometric_ns, graph 0 to first 10*geometric_ns, graph 1 nohead dt 2 lc rgb "#2e7d32"
set arrow from graph 0, first reference_floor to graph 1, first reference_floor nohead dt 3 lc rgb "#999999"
set label "the reference's own error" at graph 0.62, first reference_floor*1.6 tc rgb "#888888" noenhanced

# A colour a case, a shape a method.
cases = "sphere-square wgs84-square wgs84-circle wgs84-pencil"
colours = "#1f77b4 #d62728 #9467bd #2ca02c"
methods = "geometric chain table table-day"
shapes = "2 7 5 9"
select(c, m, col) = (strcol(1) eq c && strcol(2) eq m) ? column(col) : NaN
# An error below the reference's own is drawn at it (not resolved).
shown(e) = e < reference_floor ? reference_floor : e

plot for [i=1:words(cases)] for [j=1:words(methods)] data \
       using (select(word(cases,i), word(methods,j), 3)):(shown(column(7))) \
       with points pt (word(shapes,j)+0) ps 1.8 lc rgb word(colours,i) \
       title word(cases,i)." ".word(methods,j), \
     for [i=1:words(cases)] for [j=1:words(methods)] data \
       using (select(word(cases,i), word(methods,j), 3)):(shown(column(7))):(sprintf("%.0fx", column(6))) \
       with labels offset char 0, char (i % 2 == 0 ? -1.1 : 1.1) tc rgb word(colours,i) notitle
