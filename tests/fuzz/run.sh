#!/usr/bin/env bash
# Fuzzes the scenario loader for a bounded time: configures and builds build-fuzz/
# (clang, -DELBOWSIM_FUZZ=ON), then runs fuzz_scenario_loader for SECONDS seconds
# from the shipped scenarios (read in place: scenarios/*.yaml, scenarios/hard/*.yaml,
# scenarios/arms/*.yaml, whose URDFs the target finds beside them)
# and the new inputs of earlier runs (build-fuzz/corpus/).
# Exit 0 when no crash, sanitizer report, uncaught exception, hang (> 5 s for one
# input), leak or memory blow-up (> 2048 MB) was found; otherwise non-zero, with the
# input that did it in build-fuzz/artifacts/.
# Usage: tests/fuzz/run.sh SECONDS [more libFuzzer options]
set -euo pipefail
seconds=${1:?usage: tests/fuzz/run.sh SECONDS [libFuzzer options]}
shift
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build-fuzz
cxx=${ELBOWSIM_FUZZ_CXX:-clang++}

cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DELBOWSIM_FUZZ=ON \
  -DELBOWSIM_TESTS=OFF -DELBOWSIM_BENCH=OFF -DELBOWSIM_PRECOMPILE=ON >/dev/null
cmake --build "$build" -j2 --target fuzz_scenario_loader

# A scratch folder for the seeds: libFuzzer reads every file of a corpus folder,
# and scenarios/ holds a README too. Links, not copies.
seeds=$build/seeds
rm -rf "$seeds" && mkdir -p "$seeds" "$build/corpus" "$build/artifacts"
for f in "$root"/scenarios/*.yaml "$root"/scenarios/hard/*.yaml "$root"/scenarios/arms/*.yaml; do
  ln -s "$f" "$seeds/$(basename "$(dirname "$f")")_$(basename "$f")"
done

log=$build/fuzz.log
status=0
ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1 \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$build/tests/fuzz/fuzz_scenario_loader" -max_total_time="$seconds" -timeout=5 \
  -rss_limit_mb=2048 -max_len=16384 -dict="$root/tests/fuzz/yaml.dict" \
  -artifact_prefix="$build/artifacts/" -print_final_stats=1 "$@" \
  "$build/corpus" "$seeds" >"$log" 2>&1 || status=$?

fuzz_stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -1; }
execs=$(fuzz_stat number_of_executed_units)
if [ "$status" -ne 0 ]; then
  tail -n 60 "$log" >&2
  echo "fuzz_scenario_loader: FAILED (exit $status) after ${execs:-?} executions; the input is in $build/artifacts/, the log in $log" >&2
  exit "$status"
fi
echo "fuzz_scenario_loader: ${seconds} s, ${execs} executions (${execs:+$(fuzz_stat average_exec_per_sec)} per second), peak RSS $(fuzz_stat peak_rss_mb) MB, corpus $(ls "$build/corpus" | wc -l) inputs; no finding"
