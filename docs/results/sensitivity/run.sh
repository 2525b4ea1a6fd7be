#!/bin/bash
# What flips the experiment's verdicts: elbowsim sensitivity on the nominal
# case (loops in 4 s, elbow 40 cm out, the sized motors), 30 draws per point, each run's
# sensitivity.json copied here. Run from the repository's root after building:
#   bash docs/results/sensitivity/run.sh [OUT]      (OUT defaults to runs/sensitivity)
# then /usr/bin/python3 docs/tables.py rewrites docs/experiment.md's tables.
set -u
B=${ELBOWSIM:-build/app/elbowsim}
S=scenarios/elbow_experiment.yaml
OUT=${1:-runs/sensitivity}
C="--case task=loops,speed=nominal,elbow=mid,motor=sized --samples 30 --jobs 2"
run() {
  name=$1; shift
  "$B" sensitivity $S $C --out "$OUT/$name" "$@" > "$OUT/$name.log" 2>&1
  echo "$name $?"
  cp "$OUT/$name/sensitivity.json" "docs/results/sensitivity/$name.json"
}
mkdir -p "$OUT"
T='"robot.planar.links[*].mass": {uniform: 0.10}, "motors.joints[*].torque_constant": {uniform: 0.10}, "motors.joints[*].resistance": {uniform: 0.10}'
# The study's own uncertainty: link masses, motor K and R, each +-10 %, and the
# table's height +-0.1 mm from where the controller believes it. The first two
# variants: the resting arm against the held-up one.
run shipped
# The same with the table's height known exactly.
run tableknown --set "uncertainty.parameters={$T}"
# A compliant elbow pad of uncertain stiffness, 4e5 to 4e6 N/m (damping 300 N s/m),
# the table's height known exactly: where along it the accuracy verdict turns.
run pad --set 'contact.pad={stiffness: 1.0e6, damping: 300}' --set "uncertainty.parameters={$T, \"contact.pad.stiffness\": {range: [4.0e5, 4.0e6]}}"
echo ALLDONE
