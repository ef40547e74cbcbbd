#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for trying scripts/slurm/batch.sbatch and for the
# cluster test: Debian's slurm-wlm and munge, started without systemd, everything (config,
# keys, state, logs, pid files) under one folder.
#
#   scripts/slurm/local-cluster.sh start DIR   # prints: export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm/local-cluster.sh stop DIR    # cancels every job, stops the daemons
#
# Needs root (slurmd starts jobs as their user). Pitfalls met on this kind of machine and
# handled here are in ../shared/notes/slurm-on-this-machine.md.
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action=$1
dir=$(realpath -m "$2")

# Runs a daemon with nothing of ours but stdin/stdout/stderr pointed at its log: a daemon
# that kept an inherited descriptor (munged keeps them all) could hold a caller's pipe open.
start_daemon() {
  local log=$1; shift
  (
    for fd in /proc/$BASHPID/fd/*; do
      fd=${fd##*/}
      [ "$fd" -gt 2 ] && eval "exec $fd>&-"
    done
    exec "$@" </dev/null >>"$log" 2>&1
  )
}

# The pid in a pid file, if that process is alive (a zombie counts as gone).
live_pid() {
  local file=$1 pid state
  [ -s "$file" ] || return 1
  pid=$(cat "$file")
  [ -r "/proc/$pid/stat" ] || return 1
  state=$(sed 's/.*) //' "/proc/$pid/stat" | cut -d' ' -f1)
  [ "$state" != Z ] && echo "$pid"
}

# Waits up to $2 seconds for the daemon of pid file $1 to end; then kills it.
stop_daemon() {
  local file=$1 wait=$2 pid
  pid=$(live_pid "$file") || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for _ in $(seq $((wait * 10))); do
    live_pid "$file" >/dev/null || return 0
    sleep 0.1
  done
  kill -KILL "$pid" 2>/dev/null || true
}

# A TCP port nobody listens on, from a range keyed to this process.
free_port() {
  local port=$((20000 + ($$ * 7 + $1) % 30000))
  while grep -qi ":$(printf '%04X' "$port") 00000000:0000 0A" /proc/net/tcp /proc/net/tcp6 2>/dev/null; do
    port=$((port + 1))
  done
  echo "$port"
}

start() {
  if [ "$(id -u)" -ne 0 ]; then echo "$0: needs root (slurmd starts jobs as their user)" >&2; exit 1; fi
  for program in munged mungekey slurmctld slurmd sbatch; do
    command -v "$program" >/dev/null || { echo "$0: $program not found; install slurm-wlm and munge (scripts/setup.sh)" >&2; exit 1; }
  done
  mkdir -p "$dir"/{munge/etc,munge/run,munge/log,munge/lib,state,spool,log,run}
  chmod 0755 "$dir/munge/run"                     # munged refuses a socket folder others cannot enter
  chmod 0700 "$dir/munge/etc" "$dir/munge/log" "$dir/munge/lib"
  rm -f "$dir/munge/etc/munge.key"
  mungekey --create --keyfile="$dir/munge/etc/munge.key"
  chmod 0400 "$dir/munge/etc/munge.key"
  local socket="$dir/munge/run/munge.socket"
  start_daemon "$dir/log/munged.out" munged --socket="$socket" --key-file="$dir/munge/etc/munge.key" \
    --pid-file="$dir/munge/run/munged.pid" --log-file="$dir/munge/log/munged.log" --seed-file="$dir/munge/lib/munged.seed"

  # The node as slurmd sees it: a RealMemory above the real one would mark it invalid.
  local cpus memory
  cpus=$(slurmd -C | sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' | head -1)
  memory=$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' | head -1)
  cat >"$dir/slurm.conf" <<CONF
ClusterName=lathesim-local
SlurmctldHost=localhost
SlurmctldPort=$(free_port 0)
SlurmdPort=$(free_port 1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerParameters=batch_sched_delay=0
ReturnToService=2
MinJobAge=3600
MailProg=/bin/true
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$dir/slurm.conf"
  start_daemon "$dir/log/slurmctld.out" slurmctld -f "$SLURM_CONF" -i
  start_daemon "$dir/log/slurmd.out" slurmd -f "$SLURM_CONF" -N localhost

  # Up when the node is idle; a drained or down node will not take jobs: stop at once.
  local state=""
  for _ in $(seq 150); do
    state=$(sinfo -h -N -o %T 2>/dev/null | head -1 || true)
    case "$state" in
      idle) echo "export SLURM_CONF=$SLURM_CONF"; return 0 ;;
      drain* | down* | fail*) break ;;
    esac
    sleep 0.1
  done
  echo "$0: the node did not come up (state '${state:-none}'); logs in $dir/log" >&2
  stop
  exit 1
}

stop() {
  export SLURM_CONF="$dir/slurm.conf"
  if live_pid "$dir/run/slurmctld.pid" >/dev/null; then
    # scontrol shutdown leaves running jobs' processes behind: cancel them first.
    scancel --quiet --user=root 2>/dev/null || true
    for _ in $(seq 100); do
      [ -z "$(squeue -h -t PD,R,CG,S -o %i 2>/dev/null)" ] && break
      sleep 0.1
    done
    scontrol shutdown >/dev/null 2>&1 || true
  fi
  stop_daemon "$dir/run/slurmd.pid" 10
  stop_daemon "$dir/run/slurmctld.pid" 10
  stop_daemon "$dir/munge/run/munged.pid" 5
}

case "$action" in
  start) start ;;
  stop) stop ;;
  *) usage ;;
esac
