// controller.model: what the controller believes about the plant, where it
// differs from it. Each entry is "dotted.key: value", like a variant's, but
// only keys the plan, feed-forward and inverse kinematics read may be given:
// the robot, motors, gravity, payload, elbows and table. The loader applies
// them to a copy of the scenario and reads that copy's model (scenario_loader.cpp).
#include <set>

#include "app/scenario/sections.hpp"

namespace elbowsim::loader {

namespace {

// The sections a controller's model may change (what the plan reads).
constexpr std::string_view kBelievable[] = {"robot", "motors", "gravity", "hand_load", "elbows",
                                            "table"};

bool believable(const std::string& path) {
  for (std::string_view section : kBelievable)
    if (path == section || path.starts_with(std::string(section) + ".") ||
        path.starts_with(std::string(section) + "["))
      return true;
  return false;
}

}  // namespace

std::vector<VariantSpec::Entry> read_controller_model(const Value& model) {
  std::vector<VariantSpec::Entry> out;
  if (!model.present()) return out;
  if (!model.is_map())
    model.fail("expected a map of key.path: value (what the controller believes, e.g. "
               "robot.planar.links[0].mass: 1.1)");
  std::set<std::string> paths;
  for (const auto& [key, value] : model.entries()) {
    const std::string path = key.text();
    if (!believable(path))
      key.fail("the controller's model may change robot, motors, gravity, hand_load, elbows "
               "or table keys only (got \"" + path + "\")");
    if (!paths.insert(path).second) key.fail("duplicate key in controller.model");
    out.push_back({path + "=" + value.flow_yaml(), key.origin()});
  }
  return out;
}

}  // namespace elbowsim::loader
