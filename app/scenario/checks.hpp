// Small validated readers shared by the section readers: signs, poses, enums,
// per-joint lists. Each fails at the offending node with its key path.
#pragma once

#include <Eigen/Geometry>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/scenario/yaml_reader.hpp"

namespace elbowsim::loader {

double number(const Value& v);        // any finite number
double positive(const Value& v);      // > 0
double non_negative(const Value& v);  // >= 0
Eigen::Vector3d vec3(const Value& v);
std::string text(const Value& v);
bool boolean(const Value& v);

// `read(v)` if v is given and not null, else `fallback`:
//   link.radius = value_or(v.get("radius"), 0.02, positive);
template <class T, class Read>
T value_or(const Value& v, T fallback, Read read) {
  return v.present() ? T(read(v)) : fallback;
}

// R = Rz(yaw) Ry(pitch) Rx(roll), rpy = (roll, pitch, yaw) [rad] (fixed XYZ).
Eigen::Matrix3d rpy_rotation(const Eigen::Vector3d& rpy);
// {xyz: [m], rpy: [rad]}, both optional (zero).
Eigen::Isometry3d pose(const Value& v);

// A list of exactly `dof` numbers, one per joint.
Eigen::VectorXd per_joint(const Value& v, int dof);

// The enumerator named by v's text; fails listing the names.
template <class Enum>
Enum choose(const Value& v, const std::vector<std::pair<Enum, std::string_view>>& options) {
  std::string given = v.text();
  std::vector<std::string_view> names;
  for (const auto& [e, name] : options) {
    if (given == name) return e;
    names.push_back(name);
  }
  std::string guess = closest(given, names);
  v.fail("must be one of " + join(names) + " (got \"" + given + "\"" +
         (guess.empty() ? ")" : "; did you mean \"" + guess + "\"?)"));
}

// Same, named by the engine's to_string().
template <class Enum>
Enum choose(const Value& v, std::initializer_list<Enum> options) {
  std::vector<std::pair<Enum, std::string_view>> named;
  for (Enum e : options) named.emplace_back(e, to_string(e));
  return choose(v, named);
}

}  // namespace elbowsim::loader
