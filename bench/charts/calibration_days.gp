# How each 1 sigma shrinks with days of data (docs/calibration-days.png) from
# docs/data/calibration-days.csv, the output of scripts/calibration-days.sh (conescan-fit
# --predict). Each parameter's 1 sigma relative to its value with one day, so that degrees and
# km share an axis; the dashed line is 1/sqrt(days), what independent data alone would give.
set terminal pngcairo size 900,600 enhanced font "DejaVu Sans,11"
set output output
set datafile separator ","
set logscale xy
set xlabel "days of 1 Hz telemetry (two heads, 0.01 deg crossing noise)"
set ylabel "1 sigma / 1 sigma with one day"
set title "conescan-fit --predict: the paper's orbit (e = 0.1), two heads, 6 free parameters"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top box noenhanced
set xrange [0.1:10]
# The fourth data row is the one-day row (days = 1).
stats data skip 1 every ::3::3 using 2 name "s1" nooutput
stats data skip 1 every ::3::3 using 3 name "s2" nooutput
stats data skip 1 every ::3::3 using 4 name "s3" nooutput
stats data skip 1 every ::3::3 using 5 name "s4" nooutput
stats data skip 1 every ::3::3 using 6 name "s5" nooutput
stats data skip 1 every ::3::3 using 7 name "s6" nooutput
plot data skip 1 using 1:($2/s1_max) with linespoints lw 2 title "h1.sigma (1 day: ".sprintf("%.2g", s1_max)." deg)", \
     data skip 1 using 1:($3/s2_max) with linespoints lw 2 title "h1.phase (".sprintf("%.2g", s2_max)." deg)", \
     data skip 1 using 1:($4/s3_max) with linespoints lw 2 title "h1.dgamma (".sprintf("%.2g", s3_max)." deg)", \
     data skip 1 using 1:($5/s4_max) with linespoints lw 2 title "h2.sigma (".sprintf("%.2g", s4_max)." deg)", \
     data skip 1 using 1:($6/s5_max) with linespoints lw 2 title "h2.phase (".sprintf("%.2g", s5_max)." deg)", \
     data skip 1 using 1:($7/s6_max) with linespoints lw 2 title "horizon-km (".sprintf("%.2g", s6_max)." km)", \
     1/sqrt(x) with lines dt 2 lc rgb "#888888" title "1/sqrt(days)"
