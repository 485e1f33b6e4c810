# Roll and pitch errors of a conescan-sim run, two panels (roll above, pitch below), degrees.
# Called by scripts/plot.sh, which prepares the data; not meant to be run alone. Variables
# (gnuplot -e):
#   datafile   whitespace-separated blocks, one per sweep value, separated by two blank lines;
#              columns: x, then (roll, pitch) of the system solution, or of each head
#   outfile    the PNG to write
#   plot_title the figure's title
#   xaxis      t_s | nu_deg | sweep
#   sweepname  the swept option ("" when the run is not a sweep)
#   labels     the sweep values, space-separated, one per block
#   nblocks    number of blocks
#   nheads     0 for the system solution, else the number of heads (columns 2h, 2h+1)
#   gaps       number of rows with a NaN among the plotted errors (a status other than ok)

set encoding utf8
set terminal pngcairo size 1100,800 font "DejaVu Sans,11" noenhanced rounded
set output outfile

# Beyond this many sweep values a legend would bury the plot: colour the curves by value on a
# colour bar instead.
max_legend_entries = 8
use_palette = (sweepname ne "" && xaxis ne "sweep" && nblocks > max_legend_entries)

# Below this an error is rounding, not signal (a double-precision angle near 1 rad carries
# ~1e-16 rad): such a panel takes the other panel's scale instead of magnifying the noise.
zero_to_rounding_deg = 1e-12

ncurves = (nheads > 0 ? nheads : 1)
column_of(panel, head) = (nheads > 0 ? 2 * head + panel : 2 + panel)  # panel 0 roll, 1 pitch

# Largest |value| of each panel over every block and head.
max_abs = 0
array panel_max[2]
do for [panel = 0:1] {
  panel_max[panel + 1] = 0
  do for [h = 1:ncurves] {
    stats datafile using (column(column_of(panel, h))) nooutput
    if (STATS_records > 0) {
      m = (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max))
      if (m > panel_max[panel + 1]) { panel_max[panel + 1] = m }
    }
  }
  if (panel_max[panel + 1] > max_abs) { max_abs = panel_max[panel + 1] }
}

# The x axis.
unit_of(name) = (strstrt(name, "-deg") || strstrt(name, "alpha") || strstrt(name, "beta") || \
                 strstrt(name, "gamma") || strstrt(name, "sigma") || strstrt(name, "phase")) \
                ? " (deg)" : (strstrt(name, "-km") ? " (km)" : (strstrt(name, "-s") ? " (s)" : ""))
if (xaxis eq "nu_deg") {
  x_label = "true anomaly ν (deg)"
  set xrange [0:360]
  set xtics 45
} else {
  if (xaxis eq "sweep") {
    x_label = sweepname . unit_of(sweepname)
    set autoscale xfix
    set offsets graph 0.03, graph 0.03, 0, 0
  } else {
    x_label = "time since t = 0 (s)"
    set autoscale xfix
  }
}

# Okabe-Ito colours (distinguishable in colour-blind vision and in grey), the pale yellow left
# out: it vanishes on white.
array okabe_ito[7] = ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000"]
do for [k = 1:7] { set linetype k lc rgb okabe_ito[k] }
set linetype cycle 7

set grid lc rgb "#d0d0d0"
set mxtics
set format y "%g"
# A legend beside the plot when there are several curves; inside for the single curve of a
# one-run system solution.
side_legend = (use_palette || ncurves > 1 || sweepname ne "")
if (side_legend) {
  set key outside right top vertical Left reverse samplen 2 spacing 1.1 box lc rgb "#b0b0b0"
} else {
  set key inside right top vertical Left reverse samplen 2 box lc rgb "#b0b0b0" opaque
}

if (use_palette) {
  unset key
  if (nheads > 1) { set key }
  set palette defined (0 "#1b3a8c", 1 "#2a9d8f", 2 "#e9c46a", 3 "#d1495b")
  set cblabel sweepname . unit_of(sweepname) offset 1.5, 0
  set colorbox user origin 0.86, 0.2 size 0.02, 0.6
}

# Curve titles and styles.
sweep_value(b) = word(labels, b + 1)
head_name(h) = sprintf("head %d", h)
sweep_name(b) = sprintf("%s = %s", sweepname, sweep_value(b))
system_name = "system (all heads)"
curve_title(b, h) = (xaxis eq "sweep") ? (nheads > 0 ? head_name(h) : system_name) : \
  (sweepname eq "" ? (nheads > 0 ? head_name(h) : system_name) : \
   (use_palette ? (b == 0 && nheads > 1 ? head_name(h) : "") : \
    (nheads > 1 ? sweep_name(b) . ", " . head_name(h) : sweep_name(b))))
# Colour: by sweep value when there is a sweep (heads then differ by dash), else by head.
colour_index(b, h) = (sweepname ne "" && xaxis ne "sweep") ? b + 1 : h

# Say why a curve has gaps: the CSV writes nan where a head could not measure (MODEL §9).
if (gaps > 0) {
  set label 2 sprintf("gaps: %d rows with a status other than ok (nan in the CSV; see the status columns)", \
                      gaps) at screen 0.01, screen 0.015 left font ",9" front
}

set multiplot layout 2, 1 title plot_title font ",13" margins 0.1, (side_legend ? 0.78 : 0.96), 0.09, 0.91 spacing 0, 0.08

do for [panel = 0:1] {
  quantity = (panel == 0 ? "roll" : "pitch")
  set ylabel quantity . " error, sensed − true (deg)"
  set xlabel (panel == 1 ? x_label : "")
  # Both panels hold the same curves: one legend, beside the upper panel, is enough.
  if (panel == 1) { unset key; unset colorbox }
  unset label 1
  if (panel_max[panel + 1] < zero_to_rounding_deg) {
    span = (max_abs >= zero_to_rounding_deg ? max_abs : 1e-3)
    set yrange [-1.1 * span:1.1 * span]
    set label 1 sprintf("%s error is zero to rounding (|error| < %g deg)", quantity, \
                        zero_to_rounding_deg) at graph 0.02, graph 0.9 left front
  } else {
    set autoscale y
  }
  if (xaxis eq "sweep") {
    plot for [h = 1:ncurves] datafile using 1:(column(column_of(panel, h))) \
         with points pt (h == 1 ? 7 : 5) ps 0.8 lc h title curve_title(0, h)
  } else {
    if (use_palette) {
      plot for [b = 0:nblocks - 1] for [h = 1:ncurves] datafile index b \
           using 1:(column(column_of(panel, h))):(real(sweep_value(b))) \
           with lines lw 1.8 dt h lc palette title curve_title(b, h)
    } else {
      plot for [b = 0:nblocks - 1] for [h = 1:ncurves] datafile index b \
           using 1:(column(column_of(panel, h))) \
           with lines lw 2 dt h lc colour_index(b, h) title curve_title(b, h)
    }
  }
}
unset multiplot
