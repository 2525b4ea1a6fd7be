#!/usr/bin/env bash
# Runs every benchmark program in build/bench/ and writes its results as JSON
# into bench/results/<machine>/<program>.json, plus machine.json (what ran
# where). Builds nothing: build the bench targets first (bench/README.md).
#
#   bench/run.sh [--quick] [--out DIR]
#
#   --quick   a smoke run (min time 0.02 s per repetition, one render per
#             configuration), written to build/bench-quick/<machine>/ unless
#             --out says otherwise: not numbers to commit.
#   --out DIR write the JSON files into DIR instead.
#
# Environment: ELBOWSIM_BUILD (default: <repo>/build).
#
# <machine> = <arch>-<n>core-<cpu slug>: `uname -m`, the number of online
# logical CPUs (getconf _NPROCESSORS_ONLN), and the first "model name" of
# /proc/cpuinfo lowercased, with "(R)", "(TM)" and "(C)" removed and every run
# of characters other than a-z and 0-9 turned into one "-" (trimmed, at most
# 48 characters). No host name: the same hardware gives the same folder.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${ELBOWSIM_BUILD:-$root/build}
python=/usr/bin/python3
quick=0
out=""
while (($#)); do
  case $1 in
    --quick) quick=1 ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "run.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

# --- the machine's name ---------------------------------------------------------
cpu_model=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n1)
if [[ -z $cpu_model ]] && command -v lscpu >/dev/null; then
  cpu_model=$(LC_ALL=C lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -n1)
fi
cpu_model=${cpu_model:-unknown cpu}
cores=$(getconf _NPROCESSORS_ONLN)
arch=$(uname -m)
slug=$(printf '%s' "$cpu_model" | tr 'A-Z' 'a-z' | sed -e 's/(r)//g; s/(tm)//g; s/(c)//g' \
  -e 's/[^a-z0-9]\{1,\}/-/g; s/^-//; s/-$//' | cut -c1-48 | sed 's/-$//')
machine="$arch-${cores}core-$slug"

if [[ -z $out ]]; then
  if ((quick)); then out=$build/bench-quick/$machine; else out=$root/bench/results/$machine; fi
fi
mkdir -p "$out"
logs=$build/bench-logs
mkdir -p "$logs"

# --- what runs, and how ------------------------------------------------------------
gbench_programs=(bench_dynamics bench_constrained bench_collision bench_effects bench_step bench_derivative)
all_programs=("${gbench_programs[@]}" bench_render bench_montecarlo)
missing=()
for p in "${all_programs[@]}"; do [[ -x $build/bench/$p ]] || missing+=("$p"); done
if ((${#missing[@]})); then
  echo "run.sh: not built: ${missing[*]} (in $build/bench). Build them first:" >&2
  echo "  cmake --build ${build#$root/} -j2 --target ${all_programs[*]}" >&2
  exit 1
fi
for p in "${all_programs[@]}"; do
  if [[ $root/bench/$p.cpp -nt $build/bench/$p ]]; then
    echo "run.sh: warning: bench/$p.cpp is newer than $build/bench/$p (rebuild?)" >&2
  fi
done

repetitions=5
if ((quick)); then min_time=0.02 warmup=0.01 render_runs=1; else min_time=0.5 warmup=0.2 render_runs=5; fi
gbench_args=(
  --benchmark_repetitions=$repetitions
  --benchmark_report_aggregates_only=true
  --benchmark_min_time=$min_time
  --benchmark_min_warmup_time=$warmup
  --benchmark_enable_random_interleaving=true
)

# --- machine.json ---------------------------------------------------------------------
read -r load1 load5 load15 _ </proc/loadavg
started=$(date -u +%Y-%m-%dT%H:%M:%SZ)
t0=$(date +%s)
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null | head -n1)
compiler_version=$("${compiler:-c++}" --version 2>/dev/null | head -n1 || true)
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null | head -n1)
pkg() { dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo unknown; }
commit=$(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)
dirty=false
[[ -n $(git -C "$root" status --porcelain --untracked-files=no -- . ':!bench/results' 2>/dev/null) ]] && dirty=true
os=$(. /etc/os-release 2>/dev/null && echo "${PRETTY_NAME:-}")

write_machine_json() {  # $1: finished (true/false)
  MACHINE=$machine CPU_MODEL=$cpu_model CORES=$cores ARCH=$arch KERNEL=$(uname -r) OS=$os \
  COMPILER="$compiler_version" BUILD_TYPE=$build_type \
  EIGEN=$(pkg libeigen3-dev) BULLET=$(pkg libbullet-dev) GBENCH=$(pkg libbenchmark-dev) \
  OSMESA=$(pkg libosmesa6) LIBAV=$(pkg libavcodec-dev) \
  STARTED=$started COMMIT=$commit DIRTY=$dirty LOAD_START="$load1 $load5 $load15" \
  FINISHED=$1 QUICK=$quick REPS=$repetitions MIN_TIME=$min_time WARMUP=$warmup \
  RENDER_RUNS=$render_runs GBENCH_ARGS="${gbench_args[*]}" T0=$t0 OUT=$out \
  "$python" - <<'EOF'
import json, os, time
e = os.environ
doc = {
    "machine": e["MACHINE"],
    "machine_rule": "<uname -m>-<online logical CPUs>core-<slug of /proc/cpuinfo 'model name'>",
    "cpu_model": e["CPU_MODEL"],
    "cores": int(e["CORES"]),
    "arch": e["ARCH"],
    "kernel": e["KERNEL"],
    "os": e["OS"],
    "compiler": e["COMPILER"],
    "build_type": e["BUILD_TYPE"],
    "packages": {"libeigen3-dev": e["EIGEN"], "libbullet-dev": e["BULLET"],
                 "libbenchmark-dev": e["GBENCH"], "libosmesa6": e["OSMESA"],
                 "libavcodec-dev": e["LIBAV"]},
    "date": e["STARTED"],
    "git_commit": e["COMMIT"],
    "git_dirty": e["DIRTY"] == "true",
    "load_avg_start": [float(x) for x in e["LOAD_START"].split()],
    "protocol": {
        "quick": e["QUICK"] == "1",
        "repetitions": int(e["REPS"]),
        "min_time_s": float(e["MIN_TIME"]),
        "min_warmup_time_s": float(e["WARMUP"]),
        "random_interleaving": True,
        "google_benchmark_args": e["GBENCH_ARGS"].split(),
        "render_runs": int(e["RENDER_RUNS"]),
        "render_warmup_renders": 1,
    },
}
if e["FINISHED"] == "true":
    doc["load_avg_end"] = [float(x) for x in open("/proc/loadavg").read().split()[:3]]
    doc["wall_seconds"] = round(time.time() - int(e["T0"]))
path = os.path.join(e["OUT"], "machine.json")
with open(path + ".tmp", "w") as f:
    json.dump(doc, f, indent=2)
    f.write("\n")
os.replace(path + ".tmp", path)
EOF
}
write_machine_json false

echo "run.sh: machine $machine, load $load1 $load5 $load15, results in ${out#$root/}"
((quick)) && echo "run.sh: --quick: min time $min_time s, not numbers to commit"

# --- the runs ----------------------------------------------------------------------
for p in "${gbench_programs[@]}"; do
  echo "== $p $(date -u +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)"
  "$build/bench/$p" "${gbench_args[@]}" \
    --benchmark_out="$out/$p.json.tmp" --benchmark_out_format=json | tee "$logs/$p.txt"
  mv "$out/$p.json.tmp" "$out/$p.json"
done
echo "== bench_render $(date -u +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/bench_render" "$render_runs" --json "$out/bench_render.json.tmp" | tee "$logs/bench_render.txt"
mv "$out/bench_render.json.tmp" "$out/bench_render.json"
echo "== bench_montecarlo $(date -u +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)"
if ((quick)); then mc_args=(1 --samples 4); else mc_args=(3 --samples 8); fi
"$build/bench/bench_montecarlo" "${mc_args[@]}" --json "$out/bench_montecarlo.json.tmp" | tee "$logs/bench_montecarlo.txt"
mv "$out/bench_montecarlo.json.tmp" "$out/bench_montecarlo.json"

write_machine_json true
echo "run.sh: done in $(( $(date +%s) - t0 )) s"
if ((quick)); then
  echo "run.sh: check the tables with: /usr/bin/python3 bench/tables.py --results ${out#$root/} --print"
else
  echo "run.sh: docs/performance.md tables: /usr/bin/python3 bench/tables.py --results ${out#$root/}"
fi
