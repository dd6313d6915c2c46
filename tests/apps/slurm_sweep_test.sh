#!/usr/bin/env bash
# A real single-node Slurm (Debian's slurm-wlm and munge, started here without systemd and stopped
# by their PIDs at the end) runs a 4-shard sweep through scripts/slurm/sweep-array.sh; the merged
# table must equal the unsharded sweep byte for byte, in every format.
# Usage: slurm_sweep_test.sh RASTRACE REPOSITORY    (exit 77: skipped, slurmd needs root)
set -euo pipefail
rastrace=$1 repo=$2
if [ "$(id -u)" -ne 0 ]; then echo "skipped: slurmd must run as root to start jobs"; exit 77; fi
for tool in munged slurmctld slurmd sbatch squeue; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool missing (scripts/setup.sh installs slurm-wlm and munge)"; exit 1; }
done

work=$(mktemp -d /tmp/rastrace-slurm.XXXXXX)
stop() {
  local pids=()
  for daemon in slurmd slurmctld munged; do
    [ -s "$work/$daemon.pid" ] && pids+=("$(cat "$work/$daemon.pid")")
  done
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  done
  rm -rf "$work"
}
trap stop EXIT

mkdir -p "$work"/{state,spool,munge,out}
chmod 700 "$work/munge"
head -c 1024 /dev/urandom > "$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
munged --key-file="$work/munge/munge.key" --socket="$work/munge/socket" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munge/seed" --force

host=$(hostname)
port=$((20000 + RANDOM % 20000))
cat > "$work/slurm.conf" <<CONF
ClusterName=rastrace-test
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 100); do sinfo -h -o %t 2>/dev/null | grep -q idle && break; sleep 0.2; done
sinfo -h -o %t | grep -q idle || { echo "FAIL: the Slurm node did not come up"; cat "$work"/slurm*.log; exit 1; }

trace=$work/grid.rtrace
"$rastrace" render builtin:grid --size 128x128 --order tipsy -o "$work/grid.png" --trace "$trace" >/dev/null
cache="size=1KiB..64KiB,assoc=1/2/full,policy=fifo/lru"
bash "$repo/scripts/slurm/sweep-array.sh" --shards 4 --out "$work/out" --format csv --rastrace "$rastrace" \
  "$trace" --cache "$cache" --threads 1

for _ in $(seq 600); do
  [ -s "$work/out/sweep.csv" ] && [ -z "$(squeue -h 2>/dev/null)" ] && break
  sleep 0.5
done
if [ ! -s "$work/out/sweep.csv" ]; then
  echo "FAIL: no merged table after 300 s"; squeue; cat "$work"/out/*.log "$work/slurmctld.log"; exit 1
fi

"$rastrace" sweep "$trace" --cache "$cache" --format csv > "$work/whole.csv"
cmp "$work/whole.csv" "$work/out/sweep.csv" || { echo "FAIL: merged csv differs"; diff "$work/whole.csv" "$work/out/sweep.csv" | head; exit 1; }
for format in md latex json; do
  "$rastrace" sweep "$trace" --cache "$cache" --format $format > "$work/whole.$format"
  "$rastrace" merge "$work"/out/part-*.json --format $format > "$work/merged.$format"
  cmp "$work/whole.$format" "$work/merged.$format" || { echo "FAIL: merged $format differs"; exit 1; }
done
echo "4 shards through Slurm: the merged table equals the unsharded sweep in csv, md, latex and json"
