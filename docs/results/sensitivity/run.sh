#!/bin/bash
# What flips the experiment's verdicts: elbowsim sensitivity on the nominal
# case (loops in 4 s, elbow 40 cm out), 30 draws per point, each run's
# sensitivity.json copied here. Run from the repository's root after building:
#   bash docs/results/sensitivity/run.sh [OUT]      (OUT defaults to runs/sensitivity)
# then /usr/bin/python3 docs/tables.py rewrites docs/experiment.md's tables.
set -u
B=${ELBOWSIM:-build/app/elbowsim}
S=scenarios/elbow_experiment.yaml
OUT=${1:-runs/sensitivity}
C="--case task=loops,speed=nominal,elbow=mid --samples 30 --jobs 2"
run() {
  name=$1; shift
  "$B" sensitivity $S $C --out "$OUT/$name" "$@" > "$OUT/$name.log" 2>&1
  echo "$name $?"
  cp "$OUT/$name/sensitivity.json" "docs/results/sensitivity/$name.json"
}
mkdir -p "$OUT"
# The study's own uncertainty: link masses, motor K and R, each +-10 %.
run shipped
# The same, and the table's height +-0.1 mm from what the controller believes.
run table --set 'uncertainty.parameters={"robot.planar.links[*].mass": {uniform: 0.10}, "motors.joints[*].torque_constant": {uniform: 0.10}, "motors.joints[*].resistance": {uniform: 0.10}, "table.boxes[0].center[2]": {range: [-0.0999938, -0.0997938]}}'
echo ALLDONE
