#!/usr/bin/env bash
# Turns a conescan-sim CSV into a PNG of the roll and pitch errors (two panels, degrees).
#
#   scripts/plot.sh INPUT.csv OUTPUT.png [--x t_s|nu_deg|sweep] [--title "..."] [--heads]
#
#   --x t_s      time on the x axis (default)
#   --x nu_deg   true anomaly on the x axis
#   --x sweep    the swept value on the x axis, one point per row (a sweep CSV only): for
#                studies whose error is constant along the orbit, e.g. mounting-study.toml
#   --heads      per-head errors (hk_roll_err_deg, hk_pitch_err_deg) instead of the system
#                solution (roll_err_deg, pitch_err_deg)
#   --title      the figure's title (default: the input's file name)
#
# A sweep CSV (its first column is the swept option, before t_s; rows grouped by sweep value)
# gives one curve per sweep value; with --heads, one per head and sweep value. Rows whose status
# is not ok carry nan and leave a gap in their curve (counted in a note under the plot).
# awk splits the long-format CSV into gnuplot data blocks; scripts/plot-errors.gnuplot draws them.
# The picture is written as conescan's programs write (docs/RELIABILITY.md): never over the
# input, a read-only file or anything but a regular file (exit 2, or 1 for a file we may not
# write); into a temporary file beside it, renamed over it only once gnuplot wrote a whole PNG;
# a full disk or a file-size limit is a message and exit 1, with nothing left behind. Debian's
# gnuplot (scripts/setup.sh installs it), whatever else comes first in PATH.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

usage() {
  sed -n '4,16p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

[ $# -ge 2 ] || usage
input=$1
output=$2
shift 2
xaxis=t_s
title=""
heads=0
while [ $# -gt 0 ]; do
  case "$1" in
    --x) [ $# -ge 2 ] || usage; xaxis=$2; shift 2 ;;
    --x=*) xaxis=${1#--x=}; shift ;;
    --title) [ $# -ge 2 ] || usage; title=$2; shift 2 ;;
    --title=*) title=${1#--title=}; shift ;;
    --heads) heads=1; shift ;;
    -h | --help) usage ;;
    *) echo "plot.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
case "$xaxis" in
  t_s | nu_deg | sweep) ;;
  *) echo "plot.sh: --x '$xaxis' is not one of: t_s, nu_deg, sweep" >&2; exit 2 ;;
esac
[ -r "$input" ] || { echo "plot.sh: cannot read '$input'" >&2; exit 2; }
[ -n "$title" ] || title=$(basename "$input")
# The file the picture replaces: the output, or the file a link to it names.
target=$output
[ -L "$output" ] && target=$(readlink -f "$output")
if [ -e "$target" ]; then
  if [ "$(stat -L -c %d:%i "$input")" = "$(stat -L -c %d:%i "$target")" ]; then
    echo "plot.sh: '$output' is the input: give the picture a file of its own" >&2
    exit 2
  fi
  [ -f "$target" ] || { echo "plot.sh: cannot write '$output': not a regular file" >&2; exit 2; }
  # A write permission bit and access(W_OK), as the programs ask: a read-only file stays
  # read-only, for root too.
  if (((8#$(stat -c %a "$target") & 8#222) == 0)) || [ ! -w "$target" ]; then
    echo "plot.sh: cannot write '$output': Permission denied" >&2
    exit 1
  fi
elif [ -L "$output" ]; then
  echo "plot.sh: cannot write '$output': a symbolic link to nothing" >&2
  exit 2
fi

"$here/setup.sh" gnuplot-nox

work=$(mktemp -d)
temporary=""
trap 'rm -rf "$work"; [ -z "$temporary" ] || rm -f "$temporary"' EXIT
temporary=$(mktemp "$(dirname "$target")/.$(basename "$target").tmp-XXXXXX" 2>/dev/null) || {
  echo "plot.sh: cannot write '$output': its directory is not writable" >&2
  exit 1
}

# The data blocks, one per curve group (sweep value), separated by two blank lines so that
# gnuplot addresses them with `index`. Columns: x, then (roll, pitch) for the system solution
# or for each head. meta.sh receives what the gnuplot script needs to know about them.
awk -F, -v xaxis="$xaxis" -v heads="$heads" -v data="$work/data.dat" -v meta="$work/meta.sh" '
  function fail(msg) { print "plot.sh: " msg > "/dev/stderr"; failed = 1; exit 2 }
  function shell_quote(s) { gsub(/\047/, "\047\\\047\047", s); return "\047" s "\047" }
  function num(s) { return (s == "nan" || s == "-nan" || s == "") ? "NaN" : s }
  NR == 1 {
    sub(/\r$/, "")
    for (i = 1; i <= NF; i++) col[$i] = i
    if (!("t_s" in col)) fail("no t_s column: not a conescan-sim CSV")
    sweep = (col["t_s"] == 2) ? $1 : ""
    if (xaxis == "sweep" && sweep == "") fail("--x sweep needs a sweep CSV (swept option first)")
    if (xaxis != "sweep") xcol = col[xaxis]
    nheads = 0
    while (("h" (nheads + 1) "_roll_err_deg") in col) nheads++
    if (heads) {
      if (nheads == 0) fail("--heads: no hk_roll_err_deg columns")
      for (h = 1; h <= nheads; h++) {
        ycol[2 * h - 1] = col["h" h "_roll_err_deg"]
        ycol[2 * h] = col["h" h "_pitch_err_deg"]
      }
      ny = 2 * nheads
    } else {
      if (!("roll_err_deg" in col)) fail("no roll_err_deg column")
      ycol[1] = col["roll_err_deg"]; ycol[2] = col["pitch_err_deg"]; ny = 2
    }
    next
  }
  {
    sub(/\r$/, "")
    if (sweep != "" && (nblocks == 0 || $1 != current)) {
      if (nblocks > 0) printf "\n\n" > data
      current = $1
      started = 0
      labels = labels (nblocks ? " " : "") sprintf("%.6g", $1 + 0)
      nblocks++
    } else if (sweep == "" && nblocks == 0) {
      nblocks = 1
    }
    line = (xaxis == "sweep") ? $1 : $xcol
    # The true anomaly wraps from 360 to 0 deg after each orbit: break the curve there (one
    # blank line) rather than draw a line back across the plot.
    if (xaxis == "nu_deg" && started && $xcol + 0 < previous_x) printf "\n" > data
    previous_x = $xcol + 0
    started = 1
    gap = 0
    for (j = 1; j <= ny; j++) {
      y = num($ycol[j])
      if (y == "NaN") gap = 1
      line = line " " y
    }
    gaps += gap
    print line > data
    rows++
  }
  END {
    if (failed) exit 2
    if (rows == 0) { print "plot.sh: no data rows" > "/dev/stderr"; exit 2 }
    print "nblocks=" nblocks > meta
    print "nheads=" (heads ? nheads : 0) > meta
    print "sweep=" shell_quote(sweep) > meta
    print "labels=" shell_quote(labels) > meta
    print "gaps=" (gaps + 0) > meta
  }' "$input"
nblocks=0 nheads=0 gaps=0 sweep="" labels=""  # set by meta.sh
# shellcheck source=/dev/null
. "$work/meta.sh"

gnuplot_string() { printf "'%s'" "${1//\'/\'\'}"; }
status=0
/usr/bin/gnuplot -e "datafile=$(gnuplot_string "$work/data.dat"); \
  outfile=$(gnuplot_string "$temporary"); \
  plot_title=$(gnuplot_string "$title"); \
  xaxis=$(gnuplot_string "$xaxis"); \
  sweepname=$(gnuplot_string "$sweep"); \
  labels=$(gnuplot_string "$labels"); \
  nblocks=$nblocks; nheads=$nheads; gaps=$gaps" \
  "$here/plot-errors.gnuplot" || status=$?
# A whole PNG ends with its IEND chunk: gnuplot may exit 0 after a short write on a full disk.
png_end=$(tail -c 12 "$temporary" | od -An -tx1 | tr -d ' \n')
if [ "$status" -ne 0 ] || [ "$png_end" != 0000000049454e44ae426082 ]; then
  case $status in
    0) reason="the PNG is incomplete (No space left on device?)" ;;
    153) reason="File too large" ;;
    *) reason="gnuplot failed (status $status)" ;;
  esac
  echo "plot.sh: cannot write '$output': $reason" >&2
  exit 1
fi
if [ -e "$target" ]; then
  chmod --reference="$target" "$temporary"
else
  chmod "$(printf %o $((8#666 & ~8#$(umask))))" "$temporary"
fi
mv -f "$temporary" "$target" || { echo "plot.sh: cannot write '$output'" >&2; exit 1; }
temporary=""
echo "plot.sh: wrote $output" >&2
