#!/usr/bin/env bash
# Instruction counts (valgrind's callgrind) of one constrained derivative
# evaluation with motors, p = 2, at s = 7 and s = 60, per solver: counts do not
# move with the machine's load, so a regression shows even on a noisy machine.
# Writes bench/results/<machine>/callgrind.json (or --out DIR) with the
# instructions per evaluation inside nonstiff_rates (--toggle-collect); the
# counts the file held before, with their commit, are kept as "previous".
#
#   bench/callgrind.sh [--out DIR]        needs build/bench/count_derivative
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${ELBOWSIM_BUILD:-$root/build}
out=""
while (($#)); do
  case $1 in
    --out) out=${2:?--out needs a folder}; shift ;;
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "callgrind.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
command -v valgrind >/dev/null || { echo "callgrind.sh: valgrind not found" >&2; exit 1; }
program=$build/bench/count_derivative
[[ -x $program ]] || { echo "callgrind.sh: build $program first" >&2; exit 1; }
# The machine folder, as run.sh names it.
cpu_model=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n1)
slug=$(printf '%s' "${cpu_model:-unknown cpu}" | tr 'A-Z' 'a-z' | sed -e 's/(r)//g; s/(tm)//g; s/(c)//g' \
  -e 's/[^a-z0-9]\{1,\}/-/g; s/^-//; s/-$//' | cut -c1-48 | sed 's/-$//')
machine="$(uname -m)-$(getconf _NPROCESSORS_ONLN)core-$slug"
out=${out:-$root/bench/results/$machine}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
reps=200
rows=()
for s in 7 60; do
  for solver in auto schur aba; do
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" \
      --toggle-collect='elbowsim::nonstiff_rates*' "$program" "$s" 2 "$solver" "$reps" \
      >/dev/null 2>"$tmp/log"
    total=$(sed -n 's/^summary: //p; s/^totals: //p' "$tmp/cg.out" | head -n1 | awk '{print $1}')
    per=$((total / reps))
    echo "s = $s, p = 2, $solver: $per instructions per evaluation"
    rows+=("{\"s\": $s, \"p\": 2, \"solver\": \"$solver\", \"instructions\": $per}")
  done
done
commit=$(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)
# The counts the file held, unless they are of this same commit (a rerun).
previous=""
if [[ -f $out/callgrind.json ]]; then
  previous=$(COMMIT=$commit /usr/bin/python3 - "$out/callgrind.json" <<'EOF'
import json, os, sys
doc = json.load(open(sys.argv[1]))
if doc.get("git_commit") == os.environ["COMMIT"]:
    doc = doc.get("previous")
if doc:
    rows = ",\n".join("      " + json.dumps(r) for r in doc["counts"])
    print('  "previous": {\n    "git_commit": "%s",\n    "counts": [\n%s\n    ]\n  },'
          % (doc["git_commit"], rows))
EOF
  )
fi
{
  echo "{"
  echo "  \"what\": \"instructions per derivative evaluation (nonstiff_rates, full motors, p resting elbows), callgrind --toggle-collect\","
  echo "  \"valgrind\": \"$(valgrind --version)\","
  echo "  \"git_commit\": \"$commit\","
  echo "  \"evaluations\": $reps,"
  [[ -n $previous ]] && echo "$previous"
  echo "  \"counts\": ["
  for i in "${!rows[@]}"; do
    sep=","; ((i == ${#rows[@]} - 1)) && sep=""
    echo "    ${rows[$i]}$sep"
  done
  echo "  ]"
  echo "}"
} >"$out/callgrind.json.tmp"
mv "$out/callgrind.json.tmp" "$out/callgrind.json"
echo "callgrind.sh: wrote ${out#$root/}/callgrind.json"
