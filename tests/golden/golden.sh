#!/usr/bin/env bash
# Golden hashes: every shipped scenario, run headless, must give the outputs
# whose SHA-256 is checked in (tests/golden/hashes.txt), so that a change in
# any number shows as a failing test that its author updates on purpose:
#
#   bash tests/golden/golden.sh BUILD/app/elbowsim . WORKDIR            # check
#   bash tests/golden/golden.sh BUILD/app/elbowsim . WORKDIR --update   # rewrite hashes.txt
#
# Hashed per run folder (and per variant folder): trajectory.csv, events.csv,
# scenario.yaml and summary.json without its wall_seconds line, its
# "provenance" block (the program's version, commit, build type, compiler)
# and its "units" block (report/summary_units.cpp): the fields that are not results. comparison.* are left out: they are made
# from the summaries and carry wall times.
#
# Bit-identical floating point holds on one platform: the same glibc libm
# (which picks FMA code paths by CPU) and the same build. hashes.txt records
# a fingerprint of the platform (libm's sin/exp/log/pow on fixed inputs, the
# glibc version, the machine); on another fingerprint the check is skipped
# (exit 77) with the reason, not failed: the numbers may differ in the last
# bits there, and an encoder count that flips makes that visible.
set -euo pipefail
binary=$(realpath "$1")
source_dir=$(realpath "$2")
work=$3
update=${4:-}
golden="$source_dir/tests/golden/hashes.txt"

fingerprint() {
  {
    uname -m
    ldd --version 2>&1 | head -1
    awk 'BEGIN { for (i = 1; i <= 400; i++) printf "%.17g %.17g %.17g %.17g\n",
                 sin(i * 0.37), exp(i * 0.013), log(i * 1.7), (i * 0.31) ^ 1.37 }'
  } | sha256sum | cut -c1-16
}

without_provenance() {  # summary.json less its top-level "provenance" and "units" blocks
  awk '/^  "(provenance|units)": \{$/ { skip = 1; next } skip { if (/^  \},?$/) skip = 0; next } { print }' "$1"
}

hash_folder() {  # one line per folder holding a run: relative path and hash
  local root=$1
  find "$root" -name summary.json -printf '%h\n' | sort | while read -r dir; do
    {
      for f in trajectory.csv events.csv scenario.yaml; do
        [ -f "$dir/$f" ] && { echo "== $f"; cat "$dir/$f"; }
      done
      echo "== summary.json"
      without_provenance "$dir/summary.json" | grep -v '"wall_seconds"'
    } | sha256sum | cut -c1-64
  done | sha256sum | cut -c1-64
}

rm -rf "$work"
mkdir -p "$work"
cd "$source_dir"
scenarios=$(ls scenarios/*.yaml scenarios/hard/*.yaml scenarios/arms/*.yaml)
platform=$(fingerprint)
lines=("# Golden hashes of every shipped scenario's outputs (tests/golden/golden.sh)."
       "# Rewrite on purpose with: bash tests/golden/golden.sh build/app/elbowsim . /tmp/golden --update"
       "platform $platform")
for scenario in $scenarios; do
  out="$work/$(echo "$scenario" | tr '/' '_')"
  if ! "$binary" run "$scenario" --out "$out" --no-render --no-report > "$out.log" 2>&1; then
    # A hard scene may stop on purpose (exit 3, painleve.yaml): its outputs
    # are still results. Anything else is a failure of the check.
    status=0; grep -q '"valid"' "$out/summary.json" 2>/dev/null || status=1
    if [ "$status" -ne 0 ]; then echo "golden: $scenario did not run:"; cat "$out.log"; exit 1; fi
  fi
  lines+=("$scenario $(hash_folder "$out")")
done

if [ "$update" = "--update" ]; then
  printf '%s\n' "${lines[@]}" > "$golden"
  echo "golden: wrote $golden (${#lines[@]} lines)"
  exit 0
fi

[ -f "$golden" ] || { echo "golden: $golden is missing: run with --update"; exit 1; }
recorded_platform=$(awk '$1 == "platform" { print $2 }' "$golden")
if [ "$recorded_platform" != "$platform" ]; then
  echo "golden: skipped: this platform's floating-point fingerprint is $platform, the hashes were"
  echo "recorded on $recorded_platform (another libm or CPU path); rerun with --update here to compare"
  echo "commits on this machine"
  exit 77
fi
failed=0
for line in "${lines[@]:3}"; do
  scenario=${line%% *}
  hash=${line##* }
  recorded=$(awk -v s="$scenario" '$1 == s { print $2 }' "$golden")
  if [ -z "$recorded" ]; then
    echo "golden: $scenario has no recorded hash (new scenario?): run with --update"; failed=1
  elif [ "$recorded" != "$hash" ]; then
    echo "golden: $scenario: outputs changed (hash $hash, recorded $recorded)"; failed=1
  else
    echo "golden: $scenario: same"
  fi
done
for scenario in $(awk '$1 ~ /^scenarios\// { print $1 }' "$golden"); do
  [ -f "$scenario" ] || { echo "golden: $scenario is recorded but no longer shipped: run with --update"; failed=1; }
done
if [ "$failed" -ne 0 ]; then
  echo "golden: if the change is intended, rewrite the hashes: bash tests/golden/golden.sh build/app/elbowsim . /tmp/golden --update"
  exit 1
fi
