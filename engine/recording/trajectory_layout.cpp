#include "engine/recording/trajectory_layout.hpp"

#include <algorithm>
#include <stdexcept>

namespace elbowsim {

namespace {

void add_joint_columns(std::vector<Column>& cols, const char* prefix, const char* unit, int n) {
  for (int j = 0; j < n; ++j) cols.push_back({prefix + std::to_string(j), unit});
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.size() > prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

TrajectoryLayout::TrajectoryLayout(Groups groups) : groups_(std::move(groups)) {
  const int n = groups_.dof;
  std::vector<Column>& cols = columns_;
  cols.push_back({"time", "s"});
  add_joint_columns(cols, "q", "rad", n);
  add_joint_columns(cols, "qd", "rad/s", n);
  add_joint_columns(cols, "qdd", "rad/s^2", n);
  if (groups_.motors) {
    current_ = size();
    add_joint_columns(cols, "i", "A", n);
    add_joint_columns(cols, "v", "V", n);
  }
  torque_ = size();
  add_joint_columns(cols, "tau", "N m", n);
  hand_ = size();
  for (const char* axis : {"hand_x", "hand_y", "hand_z"}) cols.push_back({axis, "m"});
  if (groups_.desired_hand) {
    desired_ = size();
    for (const char* name : {"hand_d_x", "hand_d_y", "hand_d_z", "hand_error"})
      cols.push_back({name, "m"});
  }
  if (groups_.contact) {
    elbow_ = size();
    for (const std::string& e : groups_.elbows) {
      cols.push_back({"fn_" + e, "N"});
      cols.push_back({"d_" + e, "m"});
      cols.push_back({"rest_" + e, "1"});
    }
    link_ = size();
    for (int j = 0; j < n; ++j) {
      cols.push_back({"fn_link" + std::to_string(j), "N"});
      cols.push_back({"d_link" + std::to_string(j), "m"});
      cols.push_back({"rest_link" + std::to_string(j), "1"});
    }
    if (groups_.friction) {
      friction_ = size();
      for (const std::string& e : groups_.elbows) cols.push_back({"E_friction_" + e, "J"});
      add_joint_columns(cols, "E_friction_link", "J", n);
    }
  }
  // Each energy column's index, recorded as it is laid out (-1: not recorded).
  energy_index_.fill(-1);
  for (const EnergyTermInfo& t : kEnergyTerms) {
    if (!*t.column || !has_energy_group(groups_, t.group)) continue;
    energy_index_[static_cast<std::size_t>(t.term)] = size();
    cols.push_back({t.column, "J"});
  }
  cols.push_back({"balance_residual", "J"});
}

bool TrajectoryLayout::has_energy_group(const Groups& groups, EnergyGroup group) {
  switch (group) {
    case EnergyGroup::always: return true;
    case EnergyGroup::contact: return groups.contact;
    case EnergyGroup::motors: return groups.motors;
    case EnergyGroup::joint_friction: return groups.joint_friction;
    case EnergyGroup::gear: return groups.gear;
    case EnergyGroup::hand_force: return false;  // its work is not recorded
    case EnergyGroup::pads: return groups.pads;
    case EnergyGroup::springs: return groups.springs;
  }
  return false;
}

int TrajectoryLayout::energy(Energy e) const { return energy_index_[static_cast<std::size_t>(e)]; }

int TrajectoryLayout::elbow(const std::string& name) const {
  for (std::size_t k = 0; k < groups_.elbows.size(); ++k)
    if (groups_.elbows[k] == name) return static_cast<int>(k);
  return -1;
}

TrajectoryLayout TrajectoryLayout::from_columns(const std::vector<Column>& columns) {
  // Infer the groups from the names, then require the columns to be exactly
  // that layout's.
  Groups g;
  auto has = [&](const std::string& name) {
    for (const Column& c : columns)
      if (c.name == name) return true;
    return false;
  };
  // Each group from any one of its columns, so that one renamed column is
  // reported as itself, not as a whole group missing or shifted.
  for (const char* prefix : {"q", "qd", "qdd", "tau"}) {
    int count = 0;
    while (has(prefix + std::to_string(count))) ++count;
    g.dof = std::max(g.dof, count);
  }
  g.motors = has("i0") || has("v0") || has("i1") || has("v1");
  g.desired_hand = has("hand_d_x") || has("hand_d_y") || has("hand_d_z") || has("hand_error");
  // An elbow has three columns: a name under two of fn_, d_, rest_ is one
  // (a single renamed column does not make a new elbow).
  for (const Column& c : columns)
    for (const char* prefix : {"fn_", "d_", "rest_"}) {
      const std::string p = prefix;
      if (!starts_with(c.name, p) || starts_with(c.name, p + "link")) continue;
      const std::string elbow = c.name.substr(p.size());
      int seen = 0;
      for (const char* q : {"fn_", "d_", "rest_"}) seen += has(q + elbow);
      if (seen >= 2 && std::find(g.elbows.begin(), g.elbows.end(), elbow) == g.elbows.end())
        g.elbows.push_back(elbow);
    }
  g.contact = has(energy_term(Energy::friction).column) || has("fn_link0") || !g.elbows.empty();
  g.friction = g.contact && (has("E_friction_link0") || has("E_friction_link1"));
  g.joint_friction = has(energy_term(Energy::joint_friction).column);
  g.gear = has(energy_term(Energy::gear_loss).column);
  g.pads = has(energy_term(Energy::pad_loss).column) || has(energy_term(Energy::pad_elastic).column);
  g.springs = has(energy_term(Energy::spring).column);
  TrajectoryLayout layout(std::move(g));
  const std::vector<Column>& expected = layout.columns();
  auto text = [](const Column& c) { return "'" + c.name + " [" + c.unit + "]'"; };
  for (std::size_t k = 0; k < std::max(expected.size(), columns.size()); ++k) {
    const std::string where = "trajectory column " + std::to_string(k + 1);
    if (k >= columns.size())
      throw std::invalid_argument(where + " is missing: expected " + text(expected[k]));
    if (k >= expected.size())
      throw std::invalid_argument(where + " " + text(columns[k]) + " is not a trajectory column");
    if (text(columns[k]) != text(expected[k]))
      throw std::invalid_argument(where + " is " + text(columns[k]) + ", expected " +
                                  text(expected[k]));
  }
  return layout;
}

}  // namespace elbowsim
