#!/bin/bash
# Study throughput: the experiment's task-speed study (scenarios/studies/
# task_speed.yaml: 6 cases x 2 variants, no video, no per-run report) run with
# --jobs 1 and --jobs 2, interleaved A/B (the order alternating per
# repetition), wall clock per whole study; medians, cases per second and the
# speed-up; the merged tables of every run must be identical. Then the same
# study as a 2-task Slurm job array on a private single-node Slurm
# (tests/slurm_check.sh; skipped without slurm-wlm). Prints the load average
# at the start and the end: the machine is shared.
#
# usage: bench/bench_study.sh ELBOWSIM [REPETITIONS=3]
set -eu
elbowsim=$(realpath "$1")
repetitions=${2:-3}
source_dir=$(realpath "$(dirname "$0")/..")
study="$source_dir/scenarios/studies/task_speed.yaml"
work=$(mktemp -d "${TMPDIR:-/tmp}/elbowsim_bench_study.XXXXXX")
trap 'rm -rf "$work"' EXIT
cases=$("$elbowsim" study "$study" --out "$work/list" --list | tail -n +2 | wc -l)
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
declare -A times
for r in $(seq "$repetitions"); do
  order="1 2"; [ $((r % 2)) = 0 ] && order="2 1"
  for jobs in $order; do
    rm -rf "$work/run"
    start=$(date +%s.%N)
    # Exit 3: a case failed (the 1 s task is too fast for elbow_on: invalid), recorded as such.
    "$elbowsim" study "$study" --out "$work/run" --jobs "$jobs" > "$work/log" 2>&1 || [ $? = 3 ]
    end=$(date +%s.%N)
    times[$jobs]+="$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }') "
    "$elbowsim" merge "$work/run" > /dev/null || [ $? = 3 ]
    if [ -f "$work/table.csv" ]; then cmp -s "$work/table.csv" "$work/run/table.csv" || { echo "tables differ"; exit 1; }; fi
    cp "$work/run/table.csv" "$work/table.csv"
  done
done
median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
m1=$(echo "${times[1]}" | median)
m2=$(echo "${times[2]}" | median)
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "study task_speed: $cases cases (x 2 variants), $repetitions repetitions, merged tables identical"
echo "| --jobs | wall [s] (each) | median [s] | cases per second |"
echo "|---|---|---|---|"
for j in 1 2; do
  m=$([ $j = 1 ] && echo "$m1" || echo "$m2")
  awk -v j="$j" -v t="${times[$j]}" -v m="$m" -v c="$cases" 'BEGIN { printf "| %d | %s| %.2f | %.2f |\n", j, t, m, c / m }'
done
awk -v a="$m1" -v b="$m2" 'BEGIN { printf "speed-up of two jobs: %.2fx\n", a / b }'
bash "$source_dir/tests/slurm_check.sh" "$elbowsim" "$source_dir" "$study" 2 | grep -v passed || true
