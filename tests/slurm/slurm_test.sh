#!/usr/bin/env bash
# Opt-in test (cmake -DRPU_SLURM_TESTS=ON, ctest -L slurm; docs/sweeps.md, "Running on Slurm"):
# rpu's work as Slurm job arrays on a one-node cluster of this machine, each compared with the
# same work run on one machine.
#   1. a sweep: `rpu sweep --emit-jobs`, jobs.txt submitted with the sbatch line of README.md
#      ("Parameter sweeps"), merge.sh; results.csv must equal a local `rpu sweep`'s byte for byte
#      (it has no timing column);
#   2. a frame in shards: one task per `rpu render --backend rtl --shard I/N`, then
#      --merge-shards; the image must equal a one-machine `rpu render --backend rtl` byte for byte.
# It installs slurm-wlm and munge from Debian when they are missing (root), and starts munged,
# slurmctld and slurmd of its own: their configuration, key, sockets, state and logs live in a
# temporary directory (nothing is written to /etc), on ports not in use, and they are stopped on
# every exit.
#
#   tests/slurm/slurm_test.sh RPU WORKDIR [RTL_RPU]
# RPU runs the sweep; RTL_RPU (default RPU) the shards, and must have the co-simulation
# (RPU_SIM=ON): without it part 2 is skipped, saying so. WORKDIR holds the outputs and a copy of
# the daemons' logs.
set -euo pipefail

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: $0 RPU WORKDIR [RTL_RPU]" >&2
  exit 64
fi
here=$(cd "$(dirname "$0")" && pwd)
rpu=$(realpath "$1")
rtl_rpu=$(realpath "${3:-$1}")
mkdir -p "$2"
work=$(cd "$2" && pwd)
sweep=$here/../sweeps/tiny.json
shards=4  # of a 48x48 frame: 576 pixels each

fail() {
  echo "FAILED: slurm_test: $*" >&2
  exit 1
}
# The paths below go into --wrap scripts inside single quotes.
case "$work$rpu$rtl_rpu" in *\'*) fail "a path holds a single quote: $work $rpu $rtl_rpu" ;; esac
[ -x "$rpu" ] || fail "$rpu is not an executable"
[ -x "$rtl_rpu" ] || fail "$rtl_rpu is not an executable"
[ "$(id -u)" = 0 ] || fail "must run as root (installs packages; slurmd runs jobs as their owner)"

# --- Slurm and MUNGE from Debian -----------------------------------------------------------
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null ||
   ! command -v sbatch >/dev/null || ! command -v munged >/dev/null; then
  echo "slurm_test: installing slurm-wlm and munge"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null
fi

# --- the daemons' directory ----------------------------------------------------------------
# In the temporary directory rather than WORKDIR, whose path may be long: a Unix socket's path
# has at most 107 bytes. munged wants the socket's directory searchable by all, and its key
# readable by root alone.
run=$(mktemp -d -t rpu-slurm.XXXXXX)
chmod 755 "$run"
mkdir -m 700 "$run/key"
mkdir "$run/state" "$run/spool" "$run/log"
export SLURM_CONF=$run/slurm.conf  # for sbatch, sinfo, squeue, scancel and the daemons

stop_pid_file() {  # the daemon whose pid is in $1, if it runs; waits up to 10 s for its end
  local pid
  pid=$(cat "$1" 2>/dev/null) || return 0
  kill "$pid" 2>/dev/null || return 0
  for _ in $(seq 100); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  echo "slurm_test: $1 ($pid) did not stop" >&2
}
cleanup() {
  local rc=$?
  set +e
  if [ -S "$run/munge.socket" ] && [ -f "$run/slurmctld.pid" ]; then
    scancel --quiet --user=root 2>/dev/null  # only this test's controller is asked
    sleep 1
  fi
  stop_pid_file "$run/slurmd.pid"
  stop_pid_file "$run/slurmctld.pid"
  stop_pid_file "$run/munged.pid"
  mkdir -p "$work/daemon_logs"
  cp "$run"/log/* "$run/slurm.conf" "$work/daemon_logs/" 2>/dev/null
  if [ "$rc" != 0 ]; then
    for f in "$run"/log/*; do
      [ -f "$f" ] && { echo "--- last lines of $(basename "$f")"; tail -n 15 "$f"; }
    done >&2
  fi
  rm -rf "$run"
  if [ "$rc" = 0 ]; then echo "PASS: slurm_test"; else echo "FAILED: slurm_test (exit $rc; logs in $work/daemon_logs)"; fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM HUP

# --- MUNGE: a throwaway key of its own -----------------------------------------------------
mungekey --create --keyfile="$run/key/munge.key"
munged --socket="$run/munge.socket" --pid-file="$run/munged.pid" --log-file="$run/log/munged.log" \
  --seed-file="$run/munged.seed" --key-file="$run/key/munge.key"
munge -S "$run/munge.socket" -n | unmunge -S "$run/munge.socket" >/dev/null ||
  fail "munged does not answer on $run/munge.socket"

# --- a one-node cluster --------------------------------------------------------------------
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
port=16817
while ! port_free "$port" || ! port_free $((port + 1)); do
  port=$((port + 2))
  [ "$port" -lt 17817 ] || fail "no two free ports from 16817 on"
done
host=$(hostname -s)
# No cgroups (proctrack/linuxproc, task/none), no accounting; ReturnToService=2 so that the node
# is usable as soon as slurmd registers. RealMemory is a floor slurmd checks, not a limit.
cat >"$SLURM_CONF" <<EOF
ClusterName=rputest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$run/munge.socket
StateSaveLocation=$run/state
SlurmdSpoolDir=$run/spool
SlurmctldPidFile=$run/slurmctld.pid
SlurmdPidFile=$run/slurmd.pid
SlurmctldLogFile=$run/log/slurmctld.log
SlurmdLogFile=$run/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
MailProg=/bin/true
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=100 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld
slurmd
for _ in $(seq 60); do
  state=$(sinfo --noheader --node="$host" --format=%t 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 1
done
[ "$state" = idle ] || fail "node $host is not idle after 60 s (sinfo: '$state')"
echo "slurm_test: cluster up (node $host idle, $(nproc) CPUs, ports $port/$((port + 1)))"

# Each array task's output must exist and show rpu's success line.
check_tasks() {  # DIR JOBID FIRST LAST REGEX
  local k f
  for k in $(seq "$3" "$4"); do
    f=$1/slurm-$2_$k.out
    [ -f "$f" ] || fail "no output of array task $2_$k ($f)"
    grep -Eq "$5" "$f" || { cat "$f" >&2; fail "array task $2_$k did not succeed (/$5/ not in $f)"; }
    echo "slurm_test: task $2_$k: $(grep -E "$5" "$f" | head -n 1)"
  done
}

# --- 1. a sweep as a job array -------------------------------------------------------------
local_out=$work/sweep_local
jobs_out=$work/sweep_slurm
rm -rf "$local_out" "$jobs_out" "$work/submit_sweep"
"$rpu" sweep "$sweep" --out "$local_out" --no-yosys
"$rpu" sweep "$sweep" --out "$jobs_out" --no-yosys --emit-jobs
mkdir "$work/submit_sweep"
cd "$work/submit_sweep"
# README.md's line with this directory for /shared/sweep, and --wait (as written there: the
# count unquoted, the task's line expanded by the task's shell).
# shellcheck disable=SC2046,SC2016
submitted=$(sbatch --wait --array=1-$(wc -l < "$jobs_out/jobs.txt") --wrap \
  'sh -c "$(sed -n ${SLURM_ARRAY_TASK_ID}p '"'$jobs_out'"'/jobs.txt)"') ||
  fail "the sweep's job array failed: $submitted"
echo "slurm_test: $submitted"
jobid=${submitted##* }
ntasks=$(wc -l < "$jobs_out/jobs.txt")
check_tasks "$PWD" "$jobid" 1 "$ntasks" '^\[1/1\] [0-9a-f]+ .*: ok in '
"$jobs_out/merge.sh"
cmp "$local_out/results.csv" "$jobs_out/results.csv" ||
  { diff "$local_out/results.csv" "$jobs_out/results.csv" >&2 || true; fail "results.csv differs"; }
echo "PASS: sweep over a job array of $ntasks tasks: results.csv equals the local run's ($(($(wc -l < "$jobs_out/results.csv") - 1)) rows)"

# --- 2. a frame in shards as a job array ---------------------------------------------------
if "$rtl_rpu" config | grep -q "built without the co-simulation"; then
  echo "SKIPPED: frame shards: $rtl_rpu has no co-simulation (RPU_SIM=OFF); pass one as RTL_RPU"
  exit 0
fi
shard_out=$work/shards
rm -rf "$shard_out"
mkdir -p "$shard_out/submit"
cd "$shard_out/submit"
frame=(render builtin:curve12 --size 48x48 --backend rtl)
submitted=$(sbatch --wait --array=0-$((shards - 1)) --wrap \
  "'$rtl_rpu' ${frame[*]} --shard \$SLURM_ARRAY_TASK_ID/$shards -o '$shard_out'/share\$SLURM_ARRAY_TASK_ID.shard") ||
  fail "the shards' job array failed: $submitted"
echo "slurm_test: $submitted"
jobid=${submitted##* }
check_tasks "$PWD" "$jobid" 0 $((shards - 1)) 'checked against the model: equal'
files=()
for k in $(seq 0 $((shards - 1))); do files+=("$shard_out/share$k.shard"); done
"$rtl_rpu" "${frame[@]}" --merge-shards "${files[@]}" -o "$shard_out/merged.png"
"$rtl_rpu" "${frame[@]}" -o "$shard_out/one_machine.png"
cmp "$shard_out/one_machine.png" "$shard_out/merged.png" || fail "the merged shards differ from the one-machine image"
echo "PASS: a 48x48 frame in $shards shards over a job array equals the one-machine image"
