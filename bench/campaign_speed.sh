#!/usr/bin/env bash
# Campaigns on every core, as ratios measured in one run (wall clock, the median of
# RUNS runs, the programs compared taking turns: bench/wall_time.py):
#   1. --runs 100 of the two-head WGS84 scan scene with noise (data/scenes/monte-carlo.toml) and
#      --summary: --threads 2 against --threads 1 (target >= 1.8 on a 2-core machine);
#   2. the paper's scene streaming CSV to /dev/null with --threads 2 against the single-threaded
#      floor program bench/cli_floor.cpp (target >= 1.6 times its rows per second);
#   3. the campaign of 1. as 4 shards (--shard K/4 --summary-state), merged with --merge: every
#      count equal and every statistic within 1e-12 relative of the single process's
#      (scripts/compare-summaries.py).
# Usage: bench/campaign_speed.sh   env: BUILD_DIR (build), RUNS (3), DURATION_S (86400: a
# day at 1 s; shorter for a quick look), STEP_S (0.001: 6.2 million rows of the paper's
# scene). On a machine others are using, the ratios move with their load: re-run it idle.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
runs=${RUNS:-3}
duration=${DURATION_S:-86400}
step=${STEP_S:-0.001}

cmake --build "$build" -j"$(nproc)" --target conescan-sim conescan-cli-floor >/dev/null
sim=$build/conescan-sim
campaign=("$sim" --config data/scenes/monte-carlo.toml --runs 100 --duration-s "$duration")
paper=("$sim" --step-s "$step" --max-rows 100000000)
floor=("$build/bench/conescan-cli-floor" "$step" 1)
wall() { bench/wall_time.py "$runs" "$@"; }

rows_campaign=$(awk -v d="$duration" 'BEGIN { print 100 * (int(d) + 1) }')
rows_paper=$(("$("${paper[@]}" --threads 1 | wc -l)" - 1))
[ "$(("$("${floor[@]}" | wc -l)" - 1))" -eq "$rows_paper" ] || { echo "floor: other rows" >&2; exit 1; }

{ read -r t1; read -r t2; } < <(wall "${campaign[@]}" --threads 1 --- "${campaign[@]}" --threads 2)
{ read -r tp1; read -r tp2; read -r tf; } < <(wall "${paper[@]}" --threads 1 --- \
  "${paper[@]}" --threads 2 --- "${floor[@]}")

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"${campaign[@]}" >"$work/single.csv"
for k in 1 2 3 4; do
  "${campaign[@]}" --threads 1 --shard "$k/4" --summary-state "$work/shard$k.state" >/dev/null &
done
wait
"$sim" --merge "$work"/shard{1,2,3,4}.state >"$work/merged.csv"
merged=$(scripts/compare-summaries.py "$work/single.csv" "$work/merged.csv" 1e-12) ||
  { echo "4 shards merged: NOT the single summary" >&2; exit 1; }

awk -v r="$rows_campaign" -v t1="$t1" -v t2="$t2" -v rp="$rows_paper" -v tp1="$tp1" -v tp2="$tp2" \
    -v tf="$tf" -v runs="$runs" -v cores="$(nproc)" -v load="$(cut -d' ' -f1 /proc/loadavg)" 'BEGIN {
  printf "%d cores, load average %s at the end; median wall time of %d runs\n", cores, load, runs
  printf "%-58s %10s %14s\n", "program", "wall (s)", "rows/s"
  printf "%-58s %10.3f %14.0f\n", "monte-carlo.toml --runs 100 --summary, --threads 1", t1, r / t1
  printf "%-58s %10.3f %14.0f\n", "monte-carlo.toml --runs 100 --summary, --threads 2", t2, r / t2
  printf "%-58s %10.3f %14.0f\n", "paper scene CSV, --threads 1", tp1, rp / tp1
  printf "%-58s %10.3f %14.0f\n", "paper scene CSV, --threads 2", tp2, rp / tp2
  printf "%-58s %10.3f %14.0f\n", "conescan-cli-floor (one thread)", tf, rp / tf
  printf "campaign, 2 threads / 1 thread: %.2f (target >= 1.8)\n", t1 / t2
  printf "paper scene CSV, 2 threads / floor: %.2f (target >= 1.6)\n", tf / tp2
}'
echo "4 shards merged against the single process: $merged (counts equal; target 1e-12)"
