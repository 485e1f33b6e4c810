#!/usr/bin/env bash
# A one-node Slurm on this machine, to try scripts/slurm/campaign.sbatch: munge, then
# slurmctld and slurmd with a configuration of this host's name and CPUs, everything under
# /tmp/conescan-slurm (logs, state, spool). Needs root and Debian's slurmctld, slurmd, munge:
#   scripts/setup.sh slurmctld slurmd munge slurm-client
#   sudo scripts/slurm/local-cluster.sh start     # then: sinfo; scripts/slurm/campaign.sbatch
#   sudo scripts/slurm/local-cluster.sh stop
set -euo pipefail
dir=/tmp/conescan-slurm
conf=$dir/slurm.conf
host=$(hostname -s)
cpus=$(nproc)
memory_mb=$(($(awk '/MemTotal/ { print $2 }' /proc/meminfo) / 1024 - 512))

start() {
  mkdir -p "$dir"/{state,spool,log}
  cat >"$conf" <<CONF
ClusterName=conescan-local
SlurmctldHost=$host
AuthType=auth/munge
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
  # munge: a key (Debian's package makes one), its daemon.
  [ -s /etc/munge/munge.key ] || mungekey --create
  mkdir -p /run/munge && chown munge:munge /run/munge 2>/dev/null || true
  pgrep -x munged >/dev/null || runuser -u munge -- /usr/sbin/munged 2>/dev/null || /usr/sbin/munged --force
  SLURM_CONF=$conf /usr/sbin/slurmctld -f "$conf"
  SLURM_CONF=$conf /usr/sbin/slurmd -f "$conf"
  for _ in $(seq 50); do  # the node registers within a few seconds
    SLURM_CONF=$conf sinfo -h -o %t 2>/dev/null | grep -qx idle && break
    sleep 0.2
  done
  SLURM_CONF=$conf sinfo
  echo "export SLURM_CONF=$conf   # for sbatch, sinfo, squeue, sacct in this shell"
}

stop() {
  for daemon in slurmd slurmctld; do
    [ -f "$dir/$daemon.pid" ] && kill "$(cat "$dir/$daemon.pid")" 2>/dev/null || true
  done
  echo "slurm stopped (munged left running; logs in $dir/log)"
}

case ${1:-start} in
  start) start ;;
  stop) stop ;;
  *) echo "usage: $0 start|stop" >&2; exit 2 ;;
esac
