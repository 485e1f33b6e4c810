#!/usr/bin/env bash
# ctest campaign.slurm: the campaign of ctest campaign.gnu_parallel (data/scenes/monte-carlo.toml
# shortened to 12 runs of an hour at 10 s) through Slurm, as CI can run it (root, one machine): a
# one-node cluster started for the test (scripts/slurm/local-cluster.sh in a directory of its own,
# with its own munge, on two free ports), the campaign submitted by scripts/slurm/campaign.sbatch
# (sbatch: a job array of 4 shards, then the merge as a job that depends on all of them), and the
# merged summary equal to the single process's: every count equal, every statistic within 1e-12
# relative (scripts/compare-summaries.py). Bounded: the cluster comes up within 30 s or the test
# fails, the jobs end within 120 s or it fails (a shard that failed, leaving the merge's
# dependency never satisfied, fails it at once); the cluster is stopped whatever happens (a trap
# on exit, and INT and TERM end the script through it). Skipped (77) when not root or without
# Slurm's packages (scripts/setup.sh installs them).
# Usage: tests/campaign_slurm.sh CONESCAN_SIM SOURCE_DIR
set -euo pipefail
sim=$(realpath "$1")
root=$(realpath "$2")
if [ "$(id -u)" -ne 0 ]; then
  echo "campaign.slurm: skipped: Slurm's daemons need root" >&2
  exit 77
fi
for program in /usr/sbin/slurmctld /usr/sbin/slurmd /usr/sbin/munged /usr/bin/sbatch; do
  if [ ! -x "$program" ]; then
    echo "campaign.slurm: skipped: no $program (scripts/setup.sh installs Slurm and munge)" >&2
    exit 77
  fi
done
work=$(mktemp -d)
export CONESCAN_SLURM_DIR=$work/slurm
CONESCAN_SLURM_PORTS=$(/usr/bin/python3 -c '
import socket
sockets = [socket.socket() for _ in range(2)]
for s in sockets: s.bind(("", 0))
print(*(s.getsockname()[1] for s in sockets))')
export CONESCAN_SLURM_PORTS
export SLURM_CONF=$CONESCAN_SLURM_DIR/slurm.conf
cluster=$root/scripts/slurm/local-cluster.sh
finish() {
  local status=$?
  "$cluster" stop >/dev/null 2>&1 || true
  if [ "$status" -ne 0 ]; then
    for log in "$CONESCAN_SLURM_DIR"/log/*.log "$work"/out/*.log; do
      [ -f "$log" ] && { echo "--- $log" >&2; tail -n 15 "$log" >&2; }
    done
  fi
  rm -rf "$work"
  exit "$status"
}
trap finish EXIT
trap 'exit 1' INT TERM

scene=(--config "$root/data/scenes/monte-carlo.toml" --runs 12 --duration-s 3600 --step-s 10)
"$sim" "${scene[@]}" --threads 1 >"$work/single.csv"
"$cluster" start >/dev/null
cd "$work"
submitted=$(CONESCAN_SIM=$sim "$root/scripts/slurm/campaign.sbatch" 4 "$work/out" "${scene[@]}")
echo "$submitted" >&2
deadline=$((SECONDS + 120))
while [ -n "$(squeue -h -o %i)" ]; do
  if squeue -h -o %r | grep -q DependencyNeverSatisfied; then
    echo "campaign.slurm: a shard failed: the merge's dependency can never be satisfied" >&2
    exit 1
  fi
  if [ "$SECONDS" -ge "$deadline" ]; then
    echo "campaign.slurm: the jobs did not end within 120 s:" >&2
    squeue >&2
    exit 1
  fi
  sleep 1
done
for k in 1 2 3 4; do
  [ -s "$work/out/shard-$k.state" ] || { echo "campaign.slurm: shard $k wrote no state" >&2; exit 1; }
done
/usr/bin/python3 "$root/scripts/compare-summaries.py" "$work/single.csv" "$work/out/summary.csv" 1e-12
