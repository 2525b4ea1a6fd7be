// One reader per top-level section of a scenario file. Each validates what it
// reads and fails at the offending node (see yaml_reader.hpp). The order the
// loader calls them in matters: robot first (it sets dof), effects before
// motors and inputs (which depend on the motor model).
#pragma once

#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"
#include "app/scenario/yaml_reader.hpp"
#include "engine/model.hpp"

namespace elbowsim::loader {

// robot: base, planar | joints, damping, hand. Sets dof, base, joints, links,
// damping and the hand of `model`.
void read_robot(const Value& robot, Model& model);

// robot.planar / robot.joints: appends joints and links to `model`.
void read_planar_chain(const Value& planar, Model& model);
void read_general_chain(const Value& joints, Model& model);

// motors (optional): one Motor per joint. Needs model.dof and model.effects.
std::vector<Motor> read_motors(const Value& motors, const Model& model);

Effects read_effects(const Value& effects);                                // optional
Options read_simulation(const Value& simulation);                          // required
Model::InitialState read_initial(const Value& initial, int dof);           // optional
OpenLoopInputs read_inputs(const Value& inputs, const Model& model);       // optional
OutputSettings read_output(const Value& output, const std::string& name);  // optional

}  // namespace elbowsim::loader
