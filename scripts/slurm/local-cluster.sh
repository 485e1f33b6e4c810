#!/usr/bin/env bash
# A one-node Slurm on this machine, to try scripts/slurm/campaign.sbatch: munge, then
# slurmctld and slurmd with a configuration of this host's name and CPUs, everything under one
# directory (CONESCAN_SLURM_DIR, default /tmp/conescan-slurm: configuration, munge's own key,
# socket and daemon, state, spool, logs), on ports CONESCAN_SLURM_PORTS (default "6817 6818": the
# controller's and the node's), so that it touches nothing of a Slurm or munge the machine may
# already run, and two clusters in two directories on other ports can run side by side. Needs root
# and Debian's slurmctld, slurmd, munge, slurm-client (scripts/setup.sh installs them):
#   sudo scripts/slurm/local-cluster.sh start     # then: export SLURM_CONF=...; sinfo;
#                                                 #       scripts/slurm/campaign.sbatch
#   sudo scripts/slurm/local-cluster.sh stop      # cancels its jobs, stops its three daemons
# start waits (at most 30 s) for the node to be idle and fails, stopping what it started, when
# it is not; stop waits (at most 15 s) for each daemon to end. ctest campaign.slurm runs both.
set -euo pipefail
dir=${CONESCAN_SLURM_DIR:-/tmp/conescan-slurm}
read -r ctld_port node_port <<<"${CONESCAN_SLURM_PORTS:-6817 6818}"
conf=$dir/slurm.conf
munge_dir=$dir/munge
socket=$munge_dir/munge.socket
host=$(hostname -s)
cpus=$(nproc)
memory_mb=$(($(awk '/MemTotal/ { print $2 }' /proc/meminfo) / 1024 - 512))
export SLURM_CONF=$conf

write_conf() {
  cat >"$conf" <<CONF
ClusterName=conescan-local
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$node_port
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
JobCompType=jobcomp/none
MpiDefault=none
NodeName=$host CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

# munge of our own: a key made here, its socket and daemon in $munge_dir.
start_munge() {
  mkdir -p "$munge_dir"
  chmod 700 "$munge_dir"
  [ -s "$munge_dir/munge.key" ] || mungekey --create --keyfile="$munge_dir/munge.key" 2>/dev/null ||
    dd if=/dev/urandom of="$munge_dir/munge.key" bs=1 count=1024 status=none
  chmod 400 "$munge_dir/munge.key"
  /usr/sbin/munged --force --socket="$socket" --key-file="$munge_dir/munge.key" \
    --pid-file="$munge_dir/munged.pid" --log-file="$dir/log/munged.log" \
    --seed-file="$munge_dir/munged.seed"
}

start() {
  mkdir -p "$dir"/{state,spool,log}
  write_conf
  start_munge
  /usr/sbin/slurmctld -f "$conf"
  /usr/sbin/slurmd -f "$conf"
  for _ in $(seq 150); do  # the node registers within a few seconds
    sinfo -h -o %t 2>/dev/null | grep -qx idle && break
    sleep 0.2
  done
  if ! sinfo -h -o %t 2>/dev/null | grep -qx idle; then
    echo "local-cluster: the node did not come up idle within 30 s (logs in $dir/log):" >&2
    tail -n 20 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 || true
    stop >&2
    exit 1
  fi
  sinfo
  echo "export SLURM_CONF=$conf   # for sbatch, sinfo, squeue, sacct in this shell"
}

# Ends the daemon whose PID file is $1 (TERM, then KILL after 15 s), if it runs.
end_daemon() {
  local pid_file=$1 pid
  [ -s "$pid_file" ] || return 0
  pid=$(cat "$pid_file")
  kill "$pid" 2>/dev/null || return 0
  for _ in $(seq 75); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.2
  done
  kill -KILL "$pid" 2>/dev/null || true
}

stop() {
  if [ -s "$dir/slurmctld.pid" ] && kill -0 "$(cat "$dir/slurmctld.pid")" 2>/dev/null; then
    scancel --full --partition=local 2>/dev/null || true  # this cluster's jobs and their steps
    for _ in $(seq 50); do  # at most 10 s for them to go
      [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break
      sleep 0.2
    done
  fi
  end_daemon "$dir/slurmd.pid"
  end_daemon "$dir/slurmctld.pid"
  end_daemon "$munge_dir/munged.pid"
  echo "local-cluster: stopped (logs in $dir/log)"
}

case ${1:-start} in
  start) start ;;
  stop) stop ;;
  *) echo "usage: $0 start|stop" >&2; exit 2 ;;
esac
