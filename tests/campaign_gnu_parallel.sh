#!/usr/bin/env bash
# ctest campaign.gnu_parallel: the Monte Carlo campaign of data/scenes/monte-carlo.toml,
# shortened to 12 runs of an hour at 10 s, run as 4 shards by GNU parallel (Debian's parallel,
# scripts/setup.sh) and merged by conescan-sim --merge, equals the single process's summary:
# every count equal, every statistic within 1e-12 relative (scripts/compare-summaries.py).
# Usage: tests/campaign_gnu_parallel.sh CONESCAN_SIM SOURCE_DIR
set -euo pipefail
sim=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=(--config "$root/data/scenes/monte-carlo.toml" --runs 12 --duration-s 3600 --step-s 10)

"$sim" "${scene[@]}" --threads 1 >"$work/single.csv"
parallel --halt now,fail=1 "$sim" "${scene[@]}" --threads 1 --shard {}/4 \
  --summary-state "$work/shard{}.state" '>' "$work/shard{}.csv" ::: 1 2 3 4
"$sim" --merge "$work"/shard{1,2,3,4}.state >"$work/merged.csv"
/usr/bin/python3 "$root/scripts/compare-summaries.py" "$work/single.csv" "$work/merged.csv" 1e-12
# Each shard's own summary covers its 3 runs.
for k in 1 2 3 4; do
  [ "$(cut -d, -f1 "$work/shard$k.csv" | sed -n 2p)" = 3 ] || { echo "shard $k: not 3 runs" >&2; exit 1; }
done
