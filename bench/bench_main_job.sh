#!/bin/bash
# The main job (README command 1) and its video, for one or more elbowsim
# binaries taken in turns (e.g. main's and a branch's, both built Release):
# - run: `elbowsim run scenarios/elbow_experiment.yaml --out DIR` (its
#   variants, three since the counterbalanced arm, their videos, the side-by-side, the reports), total CPU of the
#   process (and its children, when videos went to an ffmpeg process) as
#   /usr/bin/time gives it (user + sys),
#   and wall time;
# - render: `elbowsim render DIR/elbow_off` alone (145 frames, 1280x720,
#   FXAA, to mp4): frames per second end to end = frames / wall time;
# - start-up: CPU of `elbowsim --version` (perf stat -r 50; skipped without perf).
# One measurement each per binary per repetition; the load average is printed
# before each: the machine is shared, so compare binaries within one sitting.
#
# usage: bench/bench_main_job.sh [--repetitions N] ELBOWSIM [ELBOWSIM ...]
set -eu
repetitions=1
if [ "${1:-}" = "--repetitions" ]; then repetitions=$2; shift 2; fi
[ $# -ge 1 ] || { echo "usage: $0 [--repetitions N] ELBOWSIM [ELBOWSIM ...]" >&2; exit 2; }
source_dir=$(realpath "$(dirname "$0")/..")
scenario="$source_dir/scenarios/elbow_experiment.yaml"
work=$(mktemp -d "${TMPDIR:-/tmp}/elbowsim_bench_main_job.XXXXXX")
trap 'rm -rf "$work"' EXIT
printf '%-44s %9s %9s %9s %11s %11s\n' binary "run CPU" "run wall" "render" "render fps" "--version"
for r in $(seq "$repetitions"); do
  for binary in "$@"; do
    elbowsim=$(realpath "$binary")
    load=$(cut -d' ' -f1-3 /proc/loadavg)
    rm -rf "$work/x"
    /usr/bin/time -f "%U %S %e" -o "$work/time" "$elbowsim" run "$scenario" --out "$work/x" \
      > "$work/log" 2>&1
    read -r user sys wall < "$work/time"
    /usr/bin/time -f "%e" -o "$work/render_time" "$elbowsim" render "$work/x/elbow_off" \
      > "$work/render_log" 2>&1
    frames=$(sed -n 's/^video: .* \([0-9]*\) frames at .*/\1/p' "$work/render_log")
    render_wall=$(cat "$work/render_time")
    version="-"
    if command -v perf > /dev/null; then
      version=$(perf stat -r 50 -x, -e task-clock "$elbowsim" --version 2>&1 > /dev/null |
        awk -F, '/task-clock/ { printf "%.2f ms", $1 }')
    fi
    echo "load average $load"
    printf '%-44s %8.2fs %8.2fs %8.2fs %11.1f %11s\n' "$binary" "$(echo "$user + $sys" | bc)" \
      "$wall" "$render_wall" "$(echo "$frames / $render_wall" | bc -l)" "$version"
  done
done
