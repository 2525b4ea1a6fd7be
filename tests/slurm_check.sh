#!/bin/bash
# The Slurm path of elbowsim study, for real: a single-node Slurm (munged,
# slurmctld, slurmd from Debian's munge and slurm-wlm, with a minimal
# slurm.conf in a temporary folder, on ports of their own) runs a 4-task job
# array of a small study (elbowsim study --slurm writes submit.sh; sbatch
# --wait); merged, its table must equal a local --jobs 2 run of the same
# study byte for byte. Everything this script starts it stops, by PID.
# Skipped (exit 77), saying why, only where Slurm cannot run here: its or
# munge's programs not installed (apt-get install slurm-wlm munge; .ci/setup
# does), not run as root, or no cgroup filesystem at /sys/fs/cgroup (a chroot,
# some containers), which slurmd needs ("Unable to initialize cgroup plugin").
#
# usage: slurm_check.sh ELBOWSIM SOURCE_DIR [STUDY_FILE TASKS]
# With a study file (bench/bench_study.sh: the experiment's task-speed study),
# that study in TASKS array tasks instead of the pendulum's 8 cases in 4.
set -u
elbowsim=$(realpath "$1")
source_dir=$(realpath "$2")
given_study=${3:+$(realpath "$3")}
tasks=${4:-4}

for program in munged slurmctld slurmd sbatch sinfo; do
  if ! command -v "$program" > /dev/null; then
    echo "SKIP: $program is not installed (apt-get install slurm-wlm munge; .ci/setup installs them)"
    exit 77
  fi
done
if [ "$(id -u)" != 0 ]; then
  echo "SKIP: a private Slurm here needs root (slurmd starts jobs as their user)"
  exit 77
fi
# slurmd's cgroup plugin reads the cgroup filesystem (v1 or v2) at /sys/fs/cgroup.
if ! awk '($3 == "cgroup" || $3 == "cgroup2") && $2 ~ "^/sys/fs/cgroup(/|$)" { found = 1 }
          END { exit !found }' /proc/mounts 2> /dev/null; then
  echo "SKIP: no cgroup filesystem is mounted at /sys/fs/cgroup (a chroot or a container" \
    "without it), and slurmd cannot start without one"
  exit 77
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/elbowsim_slurm.XXXXXX")
chmod 700 "$work"
pids=()
stop_all() {
  for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2> /dev/null
    wait "$pid" 2> /dev/null
  done
}
fail() {
  echo "FAIL: $*"
  for log in "$work"/*.log; do echo "--- $log"; tail -n 20 "$log"; done
  stop_all
  exit 1
}
trap 'stop_all; rm -rf "$work"' EXIT
trap 'exit 1' INT TERM
started=$(date +%s.%N)

# munge: a key of its own and a socket in the temporary folder.
head -c 1024 /dev/urandom > "$work/munge.key"
chmod 400 "$work/munge.key"
munged --foreground --force --socket="$work/munge.socket" --key-file="$work/munge.key" \
  --log-file="$work/munged.log" --pid-file="$work/munged.pid" --seed-file="$work/munged.seed" \
  > "$work/munged.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$work/munge.socket" ] && break; sleep 0.1; done
[ -S "$work/munge.socket" ] || fail "munged did not start"

# Slurm: one node (this machine, 2 CPUs), one partition, ports from this PID.
node=$(hostname -s)
port=$((20000 + ($$ % 5000) * 2))
mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" << CONF
ClusterName=elbowsim
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SlurmdTimeout=30
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=study Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out.log" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$node" > "$work/slurmd.out.log" 2>&1 &
pids+=($!)
slurmd_pid=$!
for _ in $(seq 100); do
  state=$(sinfo -h -N -o %t 2> /dev/null)
  [ "$state" = idle ] && break
  kill -0 "$slurmd_pid" 2> /dev/null || break  # slurmd gave up
  sleep 0.1
done
if [ "$state" != idle ] && grep -qs "Unable to initialize cgroup plugin" "$work"/slurmd*.log; then
  reason=$(grep -hs "cgroup" "$work"/slurmd*.log | sed 's/^\[[^]]*\] //; s/^slurmd: //' |
    awk '!seen[$0]++ { printf "%s%s", sep, $0; sep = "; " }')
  echo "SKIP: slurmd cannot start here ($reason)"
  exit 77  # (the EXIT trap stops what was started)
fi
[ "$state" = idle ] || fail "the node did not come up (sinfo: '$state')"
up=$(date +%s.%N)

# The study: the pendulum at 8 cases, 4 array tasks of 2 cases each.
cat > "$work/study.yaml" << STUDY
scenario: $source_dir/scenarios/two_link_pendulum.yaml
set: [simulation.duration=0.5, output.every=10]
grid:
  initial.q: [[0.5, 0.3], [0.2, 0.1], [-0.4, 0.9], [1.0, -0.5]]
  simulation.step: [1.0e-3, 5.0e-4]
STUDY
study="${given_study:-$work/study.yaml}"
"$elbowsim" study "$study" --out "$work/slurm_study" --slurm --tasks "$tasks" > "$work/study.out.log" 2>&1 ||
  fail "elbowsim study --slurm"
grep -q -- "--array=1-$tasks\$" "$work/slurm_study/submit.sh" || fail "submit.sh has no $tasks-task array"
submitted=$(date +%s.%N)
job=$(sbatch --parsable "$work/slurm_study/submit.sh" 2> "$work/sbatch.log") || fail "sbatch"
# Wait for the array (polled: sbatch --wait polls only every few seconds), 300 s at most.
for _ in $(seq 3000); do
  [ -z "$(squeue -h -j "$job" 2>> "$work/sbatch.log")" ] && break
  sleep 0.1
done
[ -z "$(squeue -h -j "$job")" ] || fail "the array did not end within 300 s"
ran=$(date +%s.%N)
logs=$(ls "$work/slurm_study/slurm/"*.out 2> /dev/null | wc -l)
[ "$logs" = "$tasks" ] || fail "expected $tasks array task logs, found $logs"
for shard in $(seq "$tasks"); do
  grep -q "cases run ([0-9]* failed), 0 already finished, of .* (shard $shard/$tasks)" \
    "$work/slurm_study/slurm/"*.out || fail "no task ran shard $shard/$tasks"
done
if [ -z "$given_study" ] && grep -L "study study: 2 cases run (0 failed)" "$work/slurm_study/slurm/"*.out | grep -q .; then
  fail "a task ran other than 2 of the 8 cases"
fi
"$elbowsim" merge "$work/slurm_study" > "$work/merge.log" 2>&1 || fail "merge of the Slurm run"

# The same study here, --jobs 2: the same table, byte for byte.
# (exit 3: a case failed, recorded as such: the task-speed study's 1 s elbow_on run)
"$elbowsim" study "$study" --out "$work/local" --jobs 2 > "$work/local.log" 2>&1 || [ $? = 3 ] || fail "local study"
"$elbowsim" merge "$work/local" > "$work/merge_local.log" 2>&1 || fail "merge of the local run"
cmp "$work/slurm_study/table.csv" "$work/local/table.csv" || fail "the Slurm and local tables differ"
rows=$(($(wc -l < "$work/local/table.csv") - 1))
[ -n "$given_study" ] || [ "$rows" = 8 ] || fail "expected 8 rows, got $rows"
cases=$(grep -c '"folder"' "$work/local/cases.json")

stop_all
pids=()
done_at=$(date +%s.%N)
awk -v s="$started" -v u="$up" -v b="$submitted" -v r="$ran" -v d="$done_at" -v n="$rows" -v t="$tasks" -v c="$cases" 'BEGIN {
  printf "slurm: up in %.1f s, %d-task array of %d cases in %.2f s (%.2f cases/s), all in %.1f s; tables identical (%d rows)\n",
    u - s, t, c, r - b, c / (r - b), d - s, n }'
echo "1 passed, 0 failed"
