#!/usr/bin/env bash
# What --intrusions (MODEL §13: the Sun and Moon from their track once per row, the rule for
# each head) adds to a two-head WGS84 scan row (docs/SUN_MOON.md; the target: at most +30 %).
# Median CPU time of RUNS runs on one core (bench/cpu_time.py) of the same scene with and without
# --intrusions: with --summary (the rows' computation and the statistics, no text) and as CSV to
# /dev/null (the four added columns are formatted too). The scene: the paper's orbit over a day
# at 0.1 s (864 001 rows), two pitch-axis heads, the inflated WGS84 ellipsoid, the scan model.
# Usage: bench/intrusions_speed.sh [STEP_S]. BUILD_DIR (default build), RUNS (default 7).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
step=${1:-0.1}
runs=${RUNS:-7}

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-sim >/dev/null
scene=("$build"/conescan-sim --earth wgs84 --model scan --head beta=90 --head beta=-90
  --epoch 2026-05-01T00:00:00 --duration-s 86400 --step-s "$step" --threads 1)
rows=$(("$("${scene[@]}" --summary | awk -F, 'NR == 2 { print $2 }')"))
median_seconds() { bench/cpu_time.py "$runs" "$@"; }
t_summary=$(median_seconds "${scene[@]}" --summary)
t_summary_on=$(median_seconds "${scene[@]}" --summary --intrusions)
t_csv=$(median_seconds "${scene[@]}")
t_csv_on=$(median_seconds "${scene[@]}" --intrusions)
awk -v rows="$rows" -v a="$t_summary" -v b="$t_summary_on" -v c="$t_csv" -v d="$t_csv_on" \
    -v runs="$runs" 'BEGIN {
  printf "rows: %d (two heads, wgs84, scan); median CPU time of %d runs, one core\n", rows, runs
  printf "%-22s %12s %12s %10s\n", "output", "ns/row", "+intrusions", "ratio"
  printf "%-22s %12.0f %12.0f %10.3f\n", "--summary", a / rows * 1e9, b / rows * 1e9, b / a
  printf "%-22s %12.0f %12.0f %10.3f\n", "CSV to /dev/null", c / rows * 1e9, d / rows * 1e9, d / c
  printf "target: --intrusions adds at most 30 %% to a row (--summary: %+.1f %%)\n", (b / a - 1) * 100
}'
