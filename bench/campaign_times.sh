#!/usr/bin/env bash
# The times of docs/PERFORMANCE.md's "Campaigns": the Monte Carlo campaign of
# data/scenes/monte-carlo.toml (1000 runs of one day at 1 s, two heads on WGS84 with noise:
# 86.4 million rows, summarised) with 1 thread, 2 threads, and as 4 shards of one thread each
# run by GNU parallel and merged; with SLURM=1 also as a 4-shard Slurm job array with its merge
# (scripts/slurm/local-cluster.sh must be running, SLURM_CONF set). Each merged summary is
# checked against the single process's (scripts/compare-summaries.py).
# Usage: bench/campaign_times.sh [conescan-sim options...]   (e.g. --runs 100 for a shorter one)
# BUILD_DIR (default build). Prints wall time, CPU time (user + system) and the load average.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=$(realpath "${BUILD_DIR:-build}/conescan-sim")
scene=(--config "$(realpath data/scenes/monte-carlo.toml)" "$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

timed() {  # timed NAME CMD...: one line of wall and CPU time
  local name=$1
  shift
  /usr/bin/time -f "%e %U %S" -o "$work/time" "$@"
  read -r wall user system <"$work/time"
  printf "%-44s wall %8.1f s   CPU %8.1f s   load %s\n" "$name" "$wall" \
    "$(echo "$user + $system" | bc)" "$(cut -d' ' -f1-3 /proc/loadavg)"
}

echo "campaign: conescan-sim ${scene[*]}  ($(nproc) cores)"
timed "one process, --threads 1" bash -c "\"$sim\" ${scene[*]} --threads 1 >\"$work/one.csv\""
timed "one process, --threads 2" bash -c "\"$sim\" ${scene[*]} --threads 2 >\"$work/two.csv\""
cmp -s "$work/one.csv" "$work/two.csv" || { echo "threads 1 and 2 differ" >&2; exit 1; }
timed "4 shards by GNU parallel, then --merge" bash -c "
  parallel --halt now,fail=1 \"$sim\" ${scene[*]} --threads 1 --shard {}/4 \
    --summary-state \"$work/shard{}.state\" '>' /dev/null ::: 1 2 3 4 &&
  \"$sim\" --merge \"$work\"/shard{1,2,3,4}.state >\"$work/parallel.csv\""
echo "  merged against one process: $(scripts/compare-summaries.py "$work/one.csv" "$work/parallel.csv")"
if [ "${SLURM:-0}" = 1 ]; then
  out=$work/slurm
  start=$(date +%s.%N)
  CONESCAN_SIM=$sim scripts/slurm/campaign.sbatch 4 "$out" "${scene[@]}"
  while [ ! -s "$out/summary.csv" ]; do sleep 1; done
  sleep 0.2
  printf "%-44s wall %8.1f s   (submission to summary.csv)   load %s\n" \
    "4-shard Slurm job array + merge job" "$(echo "$(date +%s.%N) - $start" | bc)" \
    "$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "  merged against one process: $(scripts/compare-summaries.py "$work/one.csv" "$out/summary.csv")"
fi
