# The speed-accuracy chart (docs/speed-accuracy.png) from docs/data/speed-accuracy.csv, the
# output of conescan-speed-accuracy. Run by scripts/make-charts.sh, which passes:
#   data, output           the CSV and the PNG
#   floor_float, floor_double, floor_long_double   the floor kernel's ns per sample
set terminal pngcairo size 1100,760 enhanced font "DejaVu Sans,11"
set output output
set datafile separator ","
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "time per head sample (ns, median; log)"
set ylabel "max |error| of the sensed eta against cpp\\_bin\\_float\\_50 (deg; log)"
set title "Speed against accuracy: each method x precision over the scene grid (docs/PERFORMANCE.md)\nclosed forms (dark) and the iterative solvers they replaced (light)"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
# Precision by the point's shape and method by its colour: no label is drawn near a point (the
# letters of one precision's cluster fell over each other's points).
set key outside right top title "method (colour)\nprecision (shape)" box noenhanced
set xrange [50:100000]
set yrange [1e-17:10]  # up to the quartic form in float, 2 deg off

# The levels that matter: the paper's effect (1e-2 deg) and the double requirement (1e-12 deg).
set arrow from graph 0, first 1e-2 to graph 1, first 1e-2 nohead dt 2 lc rgb "#888888"
set label "size of the misalignment effect: about 1e-2 deg" at graph 0.02, first 1.6e-2 tc rgb "#666666" noenhanced
set arrow from graph 0, first 1e-12 to graph 1, first 1e-12 nohead dt 2 lc rgb "#888888"
set label "double target: 1e-12 deg" at graph 0.70, first 1.6e-12 tc rgb "#666666" noenhanced
# The floor kernel of each precision (the least trigonometric work of a closed form).
do for [f in sprintf("%g %g %g", floor_float, floor_double, floor_long_double)] {
  set arrow from first f+0, graph 0 to first f+0, graph 1 nohead dt 3 lc rgb "#bbbbbb"
}
set label "floor: float, double, long double" at first floor_float*1.05, graph 0.04 tc rgb "#999999"

methods = "paper-quadratic stable-closed-form scan-sphere scan-sphere-iterative scan-ellipsoid scan-ellipsoid-iterative scan-ellipsoid-quartic"
colours = "#d62728 #1f77b4 #2ca02c #98df8a #9467bd #c5b0d5 #8c564b"
shape(p) = p eq "float" ? 7 : p eq "double" ? 5 : 9
select(m, col) = strcol(1) eq m ? column(col) : NaN

plot for [i=1:words(methods)] data using (select(word(methods,i), 3)):7:(shape(strcol(2))) \
       with points pt variable ps 1.6 lc rgb word(colours,i) notitle, \
     for [i=1:words(methods)] NaN with points pt 7 ps 1.6 lc rgb word(colours,i) \
       title word(methods,i), \
     NaN with points pt 7 ps 1.6 lc rgb "#555555" title "float", \
     NaN with points pt 5 ps 1.6 lc rgb "#555555" title "double", \
     NaN with points pt 9 ps 1.6 lc rgb "#555555" title "long double"
