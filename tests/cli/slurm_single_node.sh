#!/usr/bin/env bash
# A single-node Slurm on this machine for tests, from Debian's slurm-wlm and munge, configured
# here and nowhere else: its own munge key and munged, slurmctld and slurmd with a slurm.conf in
# a temporary folder, listening on 127.0.0.1 only (CommunicationParameters=NoInAddrAny; the
# caller runs inside scripts/netns_run.sh, where lo is the only interface). Sourced by a test:
#   source slurm_single_node.sh; slurm_start DIR; ...; slurm_stop   (slurm_stop is also trapped)
# Exports SLURM_CONF so sbatch, squeue and scontrol find this cluster. Needs root (munged and
# slurmd run as root here).

slurm_pids=()

slurm_stop() {
  local pid
  # each daemon by its own id, newest first
  for ((i = ${#slurm_pids[@]} - 1; i >= 0; i--)); do
    pid=${slurm_pids[i]}
    kill -TERM "$pid" 2>/dev/null || true
  done
  for pid in "${slurm_pids[@]}"; do
    for _ in $(seq 1 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -KILL "$pid" 2>/dev/null || true
  done
  slurm_pids=()
}

# prints each daemon's log, for a failure's explanation
slurm_logs() {
  local f
  for f in "$slurm_dir"/*.log; do
    echo "--- $f"
    tail -n 30 "$f"
  done
}

slurm_start() {
  slurm_dir=$1
  local missing=()
  local program
  for program in munged slurmctld slurmd sbatch scontrol sinfo; do
    command -v "$program" > /dev/null || [[ -x /usr/sbin/$program ]] || missing+=("$program")
  done
  if [[ ${#missing[@]} -gt 0 ]]; then
    echo "slurm_single_node: missing ${missing[*]} (scripts/install_deps.sh installs slurm-wlm and munge)" >&2
    return 1
  fi
  export PATH=$PATH:/usr/sbin
  mkdir -p "$slurm_dir/state" "$slurm_dir/spool" "$slurm_dir/munge"
  chmod 0700 "$slurm_dir/munge"
  # a key of this test's own, never the machine's /etc/munge/munge.key
  dd if=/dev/urandom of="$slurm_dir/munge/munge.key" bs=1024 count=1 status=none
  chmod 0400 "$slurm_dir/munge/munge.key"
  local socket=$slurm_dir/munge/munge.socket
  munged --foreground --force --key-file="$slurm_dir/munge/munge.key" --socket="$socket" \
    --pid-file="$slurm_dir/munge/munged.pid" --log-file="$slurm_dir/munged.log" \
    --seed-file="$slurm_dir/munge/munged.seed" > "$slurm_dir/munged.out" 2>&1 &
  slurm_pids+=($!)
  local cpus
  cpus=$(nproc)
  # the ports: above the usual 6817/6818, so a real cluster's daemons on this host are not met
  cat > "$slurm_dir/slurm.conf" <<CONF
ClusterName=cerebellum-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
CommunicationParameters=NoInAddrAny
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$slurm_dir/state
SlurmdSpoolDir=$slurm_dir/spool
SlurmctldPidFile=$slurm_dir/slurmctld.pid
SlurmdPidFile=$slurm_dir/slurmd.pid
SlurmctldLogFile=$slurm_dir/slurmctld.log
SlurmdLogFile=$slurm_dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdTimeout=60
NodeName=cerebellum-node NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=cerebellum-node Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$slurm_dir/slurm.conf
  for _ in $(seq 1 50); do
    [[ -S "$socket" ]] && break
    sleep 0.1
  done
  [[ -S "$socket" ]] || { echo "slurm_single_node: munged did not start" >&2; slurm_logs >&2; return 1; }
  # in the foreground (-D) so each is stopped by its own id; their logs are the files above
  slurmctld -D -i -f "$SLURM_CONF" > "$slurm_dir/slurmctld.out" 2>&1 &
  slurm_pids+=($!)
  slurmd -D -N cerebellum-node -f "$SLURM_CONF" > "$slurm_dir/slurmd.out" 2>&1 &
  slurm_pids+=($!)
  local state=""
  for _ in $(seq 1 300); do
    state=$(sinfo -h -n cerebellum-node -o %t 2> /dev/null || true)
    [[ "$state" == idle ]] && return 0
    sleep 0.1
  done
  echo "slurm_single_node: the node is '$state', not idle, after 30 s" >&2
  slurm_logs >&2
  return 1
}
