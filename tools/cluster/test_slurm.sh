#!/usr/bin/env bash
# `make test-slurm`: runs tools/cluster/slurm_array.sh on a real, single-node Slurm started here,
# and checks that its outputs equal one single-process `curvbench run` of the same experiments.
#
#   bash tools/cluster/test_slurm.sh BUILD EXPERIMENTS_DIR
#
# Needs root (the daemons run as root) and Debian's slurm-wlm and munge (installed here through
# tools/deps.sh slurm). Starts munged, slurmctld and slurmd with everything under BUILD/slurm/
# (key, slurm.conf, state, spool, logs; nothing in /etc), on ports SLURM_TEST_PORT (default 6817)
# and the next one. Submits the array of SLURM_TEST_SHARDS (default 4) shards and the report
# job, waits at most SLURM_TEST_TIMEOUT seconds (default 900), then compares (same_outputs.sh).
# The daemons it started and any job left are stopped on exit, whatever happens.
set -euo pipefail
if [[ $# -ne 2 ]]; then
  sed -n '2,12p' "$0" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
build=$(realpath "$1")
experiments=$(realpath "$2")
exe=$build/curvbench
port=${SLURM_TEST_PORT:-6817}
shards=${SLURM_TEST_SHARDS:-4}
timeout=${SLURM_TEST_TIMEOUT:-900}
say() { echo "test-slurm: $*"; }
die() {
  echo "test-slurm: FAILED: $*" >&2
  exit 1
}

if [[ $(id -u) -ne 0 ]]; then
  cat >&2 <<EOF
test-slurm: needs root: it starts munged, slurmctld and slurmd (SlurmUser=root) on this machine,
with Debian's slurm-wlm and munge (as root: bash tools/deps.sh slurm installs them), on the free
local ports $port and $((port + 1)) (SLURM_TEST_PORT). Run it as root, e.g. in a container:
  sudo make test-slurm
EOF
  exit 1
fi
[[ -d $experiments ]] || die "no experiment folder $2"
[[ -x $exe ]] || die "no $exe (make build first)"
bash "$src/tools/deps.sh" slurm

# Daemons of an earlier run that was killed before its exit trap ran: found by their pid files,
# and stopped only if their command line names this folder.
dir=$build/slurm
for f in "$dir/munge/munged.pid" "$dir/slurmctld.pid" "$dir/slurmd.pid"; do
  pid=$(cat "$f" 2> /dev/null || true)
  if [[ $pid =~ ^[0-9]+$ ]] && tr '\0' ' ' < "/proc/$pid/cmdline" 2> /dev/null | grep -qF "$dir/"; then
    say "stopping $(basename "$f" .pid) (pid $pid) left by an earlier run"
    kill -TERM "$pid"
    for _ in $(seq 50); do
      kill -0 "$pid" 2> /dev/null || break
      sleep 0.2
    done
    kill -KILL "$pid" 2> /dev/null || true
  fi
done
for p in "$port" "$((port + 1))"; do
  if (exec 3<> "/dev/tcp/127.0.0.1/$p") 2> /dev/null; then
    die "port $p is in use (another Slurm?); set SLURM_TEST_PORT to a free pair of ports"
  fi
done

start=$(date +%s)
rm -rf "$dir"
mkdir -p "$dir"/{munge,state,spool,log,jobs}
chmod 711 "$dir/munge" # munged: the socket's folder open to all, the key's not writable
export SLURM_CONF=$dir/slurm.conf
pids=()

stop() {
  local code=$?
  set +e
  trap - EXIT INT TERM
  if [[ ${#pids[@]} -gt 0 ]]; then
    # Jobs first (slurmstepd outlives slurmd otherwise), then the daemons, newest first.
    if [[ -n $(squeue -h -o %i 2> /dev/null) ]]; then
      say "cancelling the jobs left"
      mapfile -t jobs < <(squeue -h -o %A 2> /dev/null)
      scancel --full --quiet "${jobs[@]}" 2> /dev/null
      for _ in $(seq 30); do
        [[ -z $(squeue -h -o %i 2> /dev/null) ]] && break
        sleep 1
      done
    fi
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
      kill -TERM "${pids[i]}" 2> /dev/null
    done
    for pid in "${pids[@]}"; do
      for _ in $(seq 50); do
        kill -0 "$pid" 2> /dev/null || break
        sleep 0.2
      done
      if kill -0 "$pid" 2> /dev/null; then
        say "process $pid did not stop on SIGTERM: SIGKILL"
        kill -KILL "$pid" 2> /dev/null
      fi
      wait "$pid" 2> /dev/null
    done
    say "stopped munged, slurmctld and slurmd"
  fi
  exit "$code"
}
trap stop EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

logs() {
  for f in "$dir"/log/*; do
    echo "---- last lines of $f" >&2
    tail -n 20 "$f" >&2
  done
}

# MUNGE, the authentication every Slurm message carries: a fresh key and a private socket.
mungekey --create --keyfile="$dir/munge/munge.key"
chmod 400 "$dir/munge/munge.key"
munged --foreground --force --socket="$dir/munge/munge.socket" \
  --key-file="$dir/munge/munge.key" --pid-file="$dir/munge/munged.pid" \
  --seed-file="$dir/munge/munged.seed" > "$dir/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do
  [[ -S $dir/munge/munge.socket ]] && break
  sleep 0.1
done
[[ -S $dir/munge/munge.socket ]] || { logs; die "munged did not start"; }

# slurm.conf: this host as the only node, with the CPUs and memory slurmd detects. The machine
# may be a container, so no cgroup plugin: processes are tracked by their parent (linuxproc)
# and nothing is bound or limited (task/none).
host=$(hostname -s)
node=$(slurmd -C | head -n 1)
[[ $node == NodeName=* ]] || die "slurmd -C printed no node line: $node"
cat > "$SLURM_CONF" <<EOF
# Written by tools/cluster/test_slurm.sh: a single-node cluster for make test-slurm.
ClusterName=curvbench-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MailProg=/bin/true
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
KillWait=5
# Finished jobs stay visible to scontrol for an hour: their states are checked at the end.
MinJobAge=3600
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
say "single node: $node"

slurmctld -D -f "$SLURM_CONF" > "$dir/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" > "$dir/log/slurmd.out" 2>&1 &
pids+=($!)
state=
for _ in $(seq 60); do
  state=$(sinfo -h -N -o %T 2> /dev/null || true)
  [[ $state == idle ]] && break
  for pid in "${pids[@]}"; do
    kill -0 "$pid" 2> /dev/null || { logs; die "a daemon exited (pid $pid); logs above"; }
  done
  sleep 1
done
[[ $state == idle ]] || { logs; die "the node is not idle after 60 s (state: '${state:-none}')"; }
say "slurmctld and slurmd up, node $host idle ($(($(date +%s) - start)) s)"

# The reference: one single-process run of the same experiments.
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1790000000}
run=(--all --experiments-dir "$experiments" --no-readings)
t0=$(date +%s)
"$exe" run "${run[@]}" --output "$dir/single" > "$dir/log/single.out" 2>&1 ||
  { tail -n 20 "$dir/log/single.out" >&2; die "the single-process run failed"; }
say "single-process run: $(($(date +%s) - t0)) s"

# The shipped script, as a user would call it.
t0=$(date +%s)
submitted=$(cd "$dir/jobs" && CURVBENCH=$exe THREADS=1 bash "$here/slurm_array.sh" \
  --logs "$dir/jobs" "$shards" "$dir/store" "$dir/sharded" "${run[@]}")
echo "$submitted"
[[ $submitted =~ shards\ ([0-9]+)\ .*report\ ([0-9]+) ]] || die "no job ids in: $submitted"
array_job=${BASH_REMATCH[1]} report_job=${BASH_REMATCH[2]}
while [[ -n $(squeue -h -o %i 2> /dev/null) ]]; do
  if (($(date +%s) - t0 > timeout)); then
    squeue >&2
    die "the jobs did not finish within $timeout s (SLURM_TEST_TIMEOUT)"
  fi
  sleep 2
done
say "Slurm jobs done: $(($(date +%s) - t0)) s"

# Every array task and the report job completed with exit code 0.
states=$(scontrol -o show job "$array_job"; scontrol -o show job "$report_job")
fail=0
for k in $(seq "$shards"); do
  line=$(grep -E "ArrayJobId=$array_job ArrayTaskId=$k " <<< "$states" || true)
  if [[ $line != *"JobState=COMPLETED"*"ExitCode=0:0"* ]]; then
    echo "shard $k: $(grep -oE 'JobState=[^ ]+|ExitCode=[^ ]+' <<< "$line" | tr '\n' ' ')" >&2
    fail=1
  elif ! grep -q "shard $k/$shards done" "$dir/jobs/slurm-shard-$k.log"; then
    echo "shard $k: no 'shard $k/$shards done' in its log" >&2
    fail=1
  fi
done
line=$(grep -E "^JobId=$report_job " <<< "$states" || true)
if [[ $line != *"JobState=COMPLETED"*"ExitCode=0:0"* ]]; then
  echo "report: $(grep -oE 'JobState=[^ ]+|ExitCode=[^ ]+|Reason=[^ ]+' <<< "$line" | tr '\n' ' ')" >&2
  fail=1
fi
if [[ $fail -ne 0 ]]; then
  tail -n 5 "$dir"/jobs/*.log >&2
  die "a Slurm job failed (logs in $dir/jobs)"
fi
[[ -f $dir/sharded/REPORT.md ]] || die "no REPORT.md in $dir/sharded"
bash "$here/same_outputs.sh" "$dir/single" "$dir/sharded" ||
  die "the Slurm run's outputs differ from the single-process run's"
say "OK: $shards shards + report under Slurm equal one run of $2 ($(($(date +%s) - start)) s)"
