#!/usr/bin/env bash
# Renders a scene on a real Slurm scheduler and checks that the result is the one-process
# render, bit for bit: a single-node cluster on this machine (munged, slurmctld and slurmd,
# started here and stopped at the end), a job array rendering sample ranges
# (deploy/slurm/render-array.sbatch) and a job depending on it that merges them
# (deploy/slurm/merge.sbatch).
#
#   sudo scripts/slurm-check.sh [--parts N] [--spp S] [--res R] [--objektiv PATH] [--keep]
#
# Needs root (the daemons run as root) and the cgroup filesystem (slurmd wants it); without
# either it exits 77: skipped (as in a chroot without /sys). Installs Debian's slurm-wlm and
# munge if missing (scripts/setup.sh --cluster) and builds objektiv if needed (scripts/build.sh;
# or --objektiv names the binary). Everything else lives in a fresh directory under /tmp
# (config, keys, sockets, logs, spool, images), removed at the end unless --keep; daemons left
# by an earlier run that was killed are stopped first. The daemons listen on ports 16817 and
# 16818 of localhost. Prints PASS and exits 0 when the merged image equals the one-process
# render. The test suite runs it (cluster_slurm).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
parts=4 spp=64 res=128 keep=0 objektiv=$root/build/objektiv
while [[ $# -gt 0 ]]; do
  case $1 in
    --parts) parts=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --res) res=$2; shift 2 ;;
    --objektiv) objektiv=$(realpath "$2"); shift 2 ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "slurm-check: unknown option $1" >&2; exit 2 ;;
  esac
done
(( parts >= 1 && spp >= parts )) || { echo "slurm-check: need 1 <= --parts <= --spp" >&2; exit 2; }
[[ $(id -u) == 0 ]] || { echo "slurm-check: skipped: run as root (the Slurm daemons and munge run as root here)" >&2; exit 77; }
# slurmd (22.05) needs the cgroup filesystem even with proctrack/linuxproc and task/none; a
# chroot without /sys (as scripts run in a bare root) has none.
[[ -e /sys/fs/cgroup/cgroup.controllers || -d /sys/fs/cgroup/cpuset ]] ||
  { echo "slurm-check: skipped: no cgroup filesystem at /sys/fs/cgroup (a chroot without /sys?): slurmd cannot run" >&2; exit 77; }
scripts/setup.sh --cluster
[[ -x $objektiv ]] || scripts/build.sh

pkill -f '/tmp/objektiv-slurm\.[A-Za-z0-9]+/' 2> /dev/null && sleep 1  # an earlier run's daemons, killed with it
work=$(mktemp -d /tmp/objektiv-slurm.XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  local status=$?
  [[ -n ${SLURM_CONF:-} ]] && scontrol shutdown > /dev/null 2>&1 || true
  for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done
  sleep 1
  for p in "${pids[@]}"; do kill -9 "$p" 2> /dev/null || true; done
  if (( keep )); then echo "slurm-check: kept $work"; else rm -rf "$work"; fi
  exit $status
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; for f in "$work"/log/*; do echo "--- $f"; tail -20 "$f"; done; exit 1; }

# --- munge: its own key, socket and files ----------------------------------------------
mkdir -p "$work/munge" "$work/log" "$work/spool/ctld" "$work/spool/d" "$work/out"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/socket" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/seed" --log-file="$work/log/munged.log"
pids+=("$(cat "$work/munge/munged.pid")")

# --- Slurm: one node, this machine ------------------------------------------------------
cpus=$(nproc)
memory=$(( $(awk '/MemTotal/ { print $2 }' /proc/meminfo) / 1024 / 2 ))
export SLURM_CONF=$work/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=objektiv
SlurmctldHost=localhost
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/spool/ctld
SlurmdSpoolDir=$work/spool/d
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
NodeName=localhost NodeHostname=$(hostname) CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=render Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -f "$SLURM_CONF" > "$work/log/slurmctld.out" 2>&1 &
ctld=$!
pids+=($ctld)
slurmd -D -f "$SLURM_CONF" -N localhost > "$work/log/slurmd.out" 2>&1 &
slurmd=$!
pids+=($slurmd)
for _ in $(seq 60); do
  kill -0 $ctld 2> /dev/null && kill -0 $slurmd 2> /dev/null || fail "a Slurm daemon ended"
  timeout 5 sinfo -h -o %T 2> /dev/null | grep -qE '^idle' && break
  sleep 1
done
timeout 5 sinfo -h -o %T | grep -qE '^idle' || fail "the node did not come up: $(timeout 5 sinfo 2>&1)"
echo "slurm-check: cluster up: $(sinfo -h -o '%P %D nodes %c CPUs %T')"

# --- the render: a job array of sample ranges, then a merge that waits for it -------------
scene=$root/scenes/cornell-box/cornell-box.xml
args="-D res=$res --spp $spp"
array=$(sbatch --parsable --array=0-$((parts - 1)) --chdir="$work/out" --output="$work/log/part-%a.log" \
  --export=ALL,OBJEKTIV="$objektiv",SCENE="$scene",ARGS="$args",SPP="$spp",PARTS="$parts" \
  "$root/deploy/slurm/render-array.sbatch")
merge=$(sbatch --parsable --dependency=afterok:"$array" --chdir="$work/out" --output="$work/log/merge.log" \
  --export=ALL,OBJEKTIV="$objektiv",PARTS="$parts" "$root/deploy/slurm/merge.sbatch")
echo "slurm-check: job array $array ($parts parts of $spp samples per pixel), merge job $merge after it"
for _ in $(seq 600); do
  kill -0 $ctld 2> /dev/null && kill -0 $slurmd 2> /dev/null || fail "a Slurm daemon ended"
  [[ -z $(timeout 5 squeue -h -j "$array,$merge" 2> /dev/null) ]] && break
  sleep 1
done
[[ -z $(timeout 5 squeue -h -j "$array,$merge" 2> /dev/null) ]] && [[ -s $work/out/merged.exr ]] ||
  fail "the jobs did not finish: $(timeout 5 squeue 2>&1)"
cat "$work/log/merge.log"

# --- the same render in one process --------------------------------------------------------
# shellcheck disable=SC2086
"$objektiv" render "$scene" $args -q -o "$work/out/whole.exr"
"$objektiv" imgtool diff --exact "$work/out/merged.exr" "$work/out/whole.exr" ||
  fail "the merged image is not the one-process render"
echo PASS
