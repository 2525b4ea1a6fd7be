#!/bin/bash
# The sensors' resolution as a study axis, and the elbow pad's stiffness among the
# drawn parameters: the experiment's five tasks at the nominal speed, elbow 40 cm out,
# the sized motors, all three arms, 30 draws per case, each case with plants of its
# own. The axis `sensors` (added here with --set; the shipped study keeps its 90
# cases): `fine`, the shipped 4096-count encoders with 1e-5 rad of noise; `coarse`,
# 512 counts with 1e-4 rad. Coarse sensors make the voltages chatter; at the shipped
# 0.5 ms step that leaves every energy balance 0.4-0.5 % open (all runs invalid), so
# the coarse level runs at 0.125 ms. Two studies, each study.json copied here:
#   rigid.json  the study's own uncertainty (link masses, motor K and R, the table's height);
#   pad.json    the fine sensors, and the same uncertainty plus a rubber pad on the elbow
#               of stiffness drawn 4e5 to 4e6 N/m (damping 300 N s/m), which the controller
#               does not know (it plans on the table's surface).
# Run from the repository's root after building:
#   bash docs/results/sensors/run.sh [OUT]      (OUT defaults to runs/sensors)
# then /usr/bin/python3 docs/tables.py rewrites docs/experiment.md's tables.
set -u
B=${ELBOWSIM:-build/app/elbowsim}
S=scenarios/elbow_experiment.yaml
OUT=${1:-runs/sensors}
C="--samples 30 --jobs 2"
CASE=speed=nominal,elbow=mid,motor=sized
AXIS='study.axes.sensors={fine: {}, coarse: {controller.sensors.encoder.counts_per_rev: 512, controller.sensors.noise: 1.0e-4, simulation.step: 1.25e-4, output.every: 80}}'
U='"robot.planar.links[*].mass": {uniform: 0.10}, "motors.joints[*].torque_constant": {uniform: 0.10}, "motors.joints[*].resistance": {uniform: 0.10}, "table.boxes[0].center[2]": {range: [-0.0999938, -0.0997938]}'
mkdir -p "$OUT"
run() {
  name=$1; shift
  "$B" montecarlo $S $C --set "$AXIS" --out "$OUT/$name" "$@" > "$OUT/$name.log" 2>&1
  echo "$name $?"
  cp "$OUT/$name/study.json" "docs/results/sensors/$name.json"
}
run rigid --case $CASE
run pad --case $CASE,sensors=fine --set 'contact.pad={stiffness: 1.0e6, damping: 300}' --set "uncertainty.parameters={$U, \"contact.pad.stiffness\": {range: [4.0e5, 4.0e6]}}"
echo ALLDONE
