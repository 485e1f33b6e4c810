#!/usr/bin/env bash
# Speed of the scan model in the CLI (docs/PERFORMANCE.md): CPU time per row of
# conescan-sim on three scenes, each against the paper scene in the same run, and the paper
# scene against the least work that produces its columns (conescan-cli-floor):
#   paper   the paper's scene (MODEL §8, bias model)              target: >= the floor's rate
#   scan    --model scan                                          target: <= 1.4 x paper per row
#   wgs84   --model scan --earth wgs84 --horizon-km 40
#           --head beta=90 --head beta=-90                        target: <= 2.9 x paper per row
# Usage: bench/scan_speed.sh [STEP_S]   (default 0.01 s: ~618,000 rows of the paper's orbit)
# BUILD_DIR (default build) is the CMake build directory; RUNS (default 7) the runs per program,
# of which the median CPU time is reported (bench/cpu_time.py: one core, to the microsecond).
# Times move with the machine's load; only ratios from one run are compared.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
step=${1:-0.01}
runs=${RUNS:-7}

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCAN_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-sim conescan-cli-floor >/dev/null

paper=("$build"/conescan-sim --step-s "$step")
scan=("${paper[@]}" --model scan)
wgs84=("${paper[@]}" --model scan --earth wgs84 --horizon-km 40 --head beta=90 --head beta=-90)
floor=("$build"/bench/conescan-cli-floor "$step" 1)

rows=$(("$(${paper[@]} | wc -l)" - 1))
for program in scan wgs84 floor; do  # the same rows, or the ratios mean nothing
  declare -n cmd=$program
  other=$(("$(${cmd[@]} | wc -l)" - 1))
  [ "$other" -eq "$rows" ] || { echo "scan_speed: $program wrote $other rows, paper $rows" >&2; exit 1; }
done

t_paper=$(bench/cpu_time.py "$runs" "${paper[@]}")
t_scan=$(bench/cpu_time.py "$runs" "${scan[@]}")
t_wgs84=$(bench/cpu_time.py "$runs" "${wgs84[@]}")
t_floor=$(bench/cpu_time.py "$runs" "${floor[@]}")

awk -v rows="$rows" -v tp="$t_paper" -v ts="$t_scan" -v tw="$t_wgs84" -v tf="$t_floor" \
    -v runs="$runs" 'BEGIN {
  printf "rows: %d per scene; median CPU time of %d runs, one core, to /dev/null\n", rows, runs
  printf "%-44s %12s %12s\n", "scene", "CPU time (s)", "ns/row"
  printf "%-44s %12.4f %12.0f\n", "paper (bias model)", tp, tp / rows * 1e9
  printf "%-44s %12.4f %12.0f\n", "--model scan", ts, ts / rows * 1e9
  printf "%-44s %12.4f %12.0f\n", "--model scan --earth wgs84, 40 km, 2 heads", tw, tw / rows * 1e9
  printf "%-44s %12.4f %12.0f\n", "conescan-cli-floor (paper scene)", tf, tf / rows * 1e9
  printf "scan / paper per row: %.2f (target <= 1.4)\n", ts / tp
  printf "wgs84 two heads / paper per row: %.2f (target <= 2.9)\n", tw / tp
  printf "paper / floor rate: %.2f (target >= 1.00)\n", tf / tp
}'
