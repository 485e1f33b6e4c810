# The stability map (docs/stability-map.png) from the output of conescan-stability-map: over the
# plane of the true nadir angle eta and the Earth's angular radius rho, for one cone. Run by
# scripts/make-charts.sh, which passes data, output, gamma_deg, sigma_deg, phi_a_deg and
# step_deg (the cell size). Columns: 1 eta, 2 rho, 3 half chord, 4 log10 amplification, then per
# method (stable closed form 5-8, paper's forms 9-12, scan model closed form 13-16, its bracketed
# solver 17-20): status code in double, the reference's, log10 double error, log10 float error.
set terminal pngcairo size 2400,1400 enhanced font "DejaVu Sans,10"
set output output
set datafile separator ","
set xrange [0:180]
set yrange [0:90]
set xtics 30
set ytics 15
set xlabel "true nadir angle eta of the spin axis (deg)"
set ylabel "Earth angular radius rho (deg)"
set tics out

# Status codes: status_index (include/conescan/status.hpp), then 9 for the paper's wrong root.
status_palette = 'set palette maxcolors 10; set palette defined (0 "#b7e4b0", 1 "#f2f2f2", 2 "#9e9e9e", 3 "#ff9f1c", 4 "#17becf", 5 "#d62728", 6 "#e377c2", 7 "black", 8 "#ffffff", 9 "#7b3294"); set cbrange [-0.5:9.5]; set cbtics font ",8"; set cbtics ("ok" 0, "miss" 1, "engulfed" 2, "grazing" 3, "multiple" 4, "fold" 5, "ambiguous" 6, "invalid" 7, "none" 8, "wrong root" 9)'
error_palette = 'set palette maxcolors 0; set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c"); set cbtics auto'

# Fixed margins and room between the columns: each panel's colour-box labels ("wrong root",
# "ambiguous") end before the next panel's axis label, and the last column's within the page
# (with the automatic layout they ran over both).
set multiplot layout 3,4 margins 0.035,0.925,0.045,0.93 spacing 0.09,0.075 title noenhanced sprintf("Where the methods fail: gamma = %g deg, sigma = %g deg at phi_A = %g deg; eta0 = eta, attitude envelope 10 deg; cells of %g deg (docs/ACCURACY.md)", gamma_deg, sigma_deg, phi_a_deg, step_deg)

# 1: error amplification of the chord inversion (the fold is where it goes to infinity).
eval error_palette
set cbrange [0:4]
set cbtics ("1" 0, "10" 1, "100" 2, "1e3" 3, "1e4" 4)
set title "|d eta / d Phi| (log; status fold above 30)"
plot data using 1:2:($4 > 4 ? 4 : $4) with image notitle

# 2-4: the status each method returns in double.
eval status_palette
set title "stable closed form (bias model): status (double)"
plot data using 1:2:5 with image notitle
set title "paper's quadratic forms: status (double)"
plot data using 1:2:9 with image notitle
set title "scan model, sphere, closed form: status (double)"
plot data using 1:2:13 with image notitle

# 5-12: observed error against cpp_bin_float_50 where both are ok (log10 deg).
eval error_palette
set cbrange [-17:-11]
set cbtics 1 format "1e%g"
set title "stable closed form: double error (log10 deg)"
plot data using 1:2:7 with image notitle
set title "paper's quadratic forms: double error (log10 deg)"
plot data using 1:2:11 with image notitle
set title "scan model, closed form: double error (log10 deg)"
plot data using 1:2:15 with image notitle
set title "scan model, bracketed Newton: double error (log10 deg)"
plot data using 1:2:19 with image notitle
set cbrange [-8:-2]
set title "stable closed form: float error (log10 deg)"
plot data using 1:2:8 with image notitle
set title "paper's quadratic forms: float error (log10 deg)"
plot data using 1:2:12 with image notitle
set title "scan model, closed form: float error (log10 deg)"
plot data using 1:2:16 with image notitle
set title "scan model, bracketed Newton: float error (log10 deg)"
plot data using 1:2:20 with image notitle
unset multiplot
