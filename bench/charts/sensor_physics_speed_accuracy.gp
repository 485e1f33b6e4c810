# The sensor physics speed-accuracy chart (docs/sensor-physics-speed-accuracy.png) from
# docs/data/sensor-physics-speed-accuracy.csv, the output of conescan-sensor-physics-speed
# --chart-csv. Run by scripts/sensor-physics-chart.sh, which passes:
#   data, output   the CSV and the PNG
#   geometric_ns   the geometric scan row's time (ns): the target is 10 times it
#   reference_floor  the reference's own error (deg) at its grid step
set terminal pngcairo size 1100,720 enhanced font "DejaVu Sans,11"
set output output
set datafile separator ","
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "time per head-row (ns, median of 7 runs; log)"
set ylabel "worst |crossing - reference| over the reference rows (deg; log)"
set title "MODEL §12's crossings: speed against accuracy (docs/SENSOR\\_PHYSICS.md, \"The fast method\", \"The table\")\n1.5 deg square field, 1 ms lag at 1 rev/s, normalised 1/2, along the paper's e = 0.1 orbit"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top box noenhanced
set xrange [10:1e6]
set yrange [1e-9:10]

# The target: at most 10 times the geometric row, within 1e-6 deg of the reference.
set object 1 rect from graph 0, graph 0 to first 10*geometric_ns, first 1e-6 fc rgb "#e8f5e9" fs solid 1.0 noborder behind
set label "target: <= 10 x geometric, <= 1e-6 deg" at first 12, first 3e-7 tc rgb "#2e7d32" noenhanced
set arrow from graph 0, first 1e-6 to graph 1, first 1e-6 nohead dt 2 lc rgb "#2e7d32"
set arrow from first 10*geometric_ns, graph 0 to first 10*geometric_ns, graph 1 nohead dt 2 lc rgb "#2e7d32"
set arrow from graph 0, first reference_floor to graph 1, first reference_floor nohead dt 3 lc rgb "#999999"
set label "the reference's own error" at graph 0.62, first reference_floor*1.6 tc rgb "#888888" noenhanced

methods = "geometric exact exact-light exact-lightest fast fast-light fast-lightest table"
colours = "#000000 #d62728 #ff9896 #f7b6d2 #1f77b4 #6baed6 #9ecae1 #2ca02c"
# Each label above its point, or below where two points sit close (the lighter settings).
lifts = "1.1 1.1 -1.1 1.1 1.1 -1.1 1.1 1.1"
select(m, col) = strcol(1) eq m ? column(col) : NaN
# An error below the reference's own is drawn at it (not resolved).
shown(e) = e < reference_floor ? reference_floor : e

plot for [i=1:words(methods)] data using (select(word(methods,i), 2)):(shown(column(6))) \
       with points pt 7 ps 1.8 lc rgb word(colours,i) title word(methods,i), \
     for [i=1:words(methods)] data using (select(word(methods,i), 2)):(shown(column(6))):(sprintf("%.0fx", column(5))) \
       with labels offset char 0, char word(lifts,i)+0 tc rgb word(colours,i) notitle
