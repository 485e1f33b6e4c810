# The stability map (docs/stability-map.png) from docs/data/stability-map.csv, the output of
# conescan-stability-map: over the plane of the true nadir angle eta and the Earth's angular
# radius rho, for one cone. Run by scripts/make-charts.sh, which passes data, output, gamma_deg,
# sigma_deg, phi_a_deg and step_deg (the cell size).
set terminal pngcairo size 2000,960 enhanced font "DejaVu Sans,10"
set output output
set datafile separator ","
set xrange [0:180]
set yrange [0:90]
set xtics 30
set ytics 15
set xlabel "true nadir angle eta of the spin axis (deg)"
set ylabel "Earth angular radius rho (deg)"
set tics out

status_palette = 'set palette maxcolors 7; set palette defined (0 "#b7e4b0", 1 "#f2f2f2", 2 "#9e9e9e", 3 "#ff9f1c", 4 "#d62728", 5 "black", 6 "#7b3294"); set cbrange [-0.5:6.5]; set cbtics ("ok" 0, "miss" 1, "engulfed" 2, "grazing" 3, "fold" 4, "invalid" 5, "wrong root" 6)'
error_palette = 'set palette maxcolors 0; set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c"); set cbtics auto'

set multiplot layout 2,4 title noenhanced sprintf("Where the methods fail: gamma = %g deg, sigma = %g deg at phi_A = %g deg; cells of %g deg (docs/ACCURACY.md)", gamma_deg, sigma_deg, phi_a_deg, step_deg)

# 1: error amplification of the chord inversion (the fold is where it goes to infinity).
eval error_palette
set cbrange [0:4]
set cbtics ("1" 0, "10" 1, "100" 2, "1e3" 3, "1e4" 4)
set title "|d eta / d Phi| (log; status fold above 100)"
plot data using 1:2:($4 > 4 ? 4 : $4) with image notitle

# 2-4: the status each method returns in double.
eval status_palette
set title "stable closed form: status (double)"
plot data using 1:2:5 with image notitle
set title "paper's quadratic forms: status (double)"
plot data using 1:2:9 with image notitle
set title "scan model, sphere: status (double)"
plot data using 1:2:13 with image notitle

# 5-8: observed error against cpp_bin_float_50 where both are ok (log10 deg).
eval error_palette
set cbrange [-17:-11]
set cbtics 1 format "1e%g"
set title "stable closed form: double error (log10 deg)"
plot data using 1:2:7 with image notitle
set title "paper's quadratic forms: double error (log10 deg)"
plot data using 1:2:11 with image notitle
set cbrange [-8:-2]
set title "stable closed form: float error (log10 deg)"
plot data using 1:2:8 with image notitle
set title "paper's quadratic forms: float error (log10 deg)"
plot data using 1:2:12 with image notitle
unset multiplot
