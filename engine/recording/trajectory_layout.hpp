// The columns of a recorded trajectory: every column's name, unit and index,
// in one place. The recorder (run/recorder.hpp) builds the layout from the
// model and writes each value through it; readers (metrics, report, renderer)
// rebuild it from a CSV header with from_columns(), which refuses a header
// that is not exactly a layout, so a renamed column fails there, loudly, and
// not as a missing plot later.
//
// Columns, in order ([n] = one per joint j, [e] = three per elbow):
//   time [s]; q<j> [rad], qd<j> [rad/s], qdd<j> [rad/s^2];
//   i<j> [A], v<j> [V] (motors); tau<j> [N m];
//   hand_x, hand_y, hand_z [m];
//   hand_d_x, hand_d_y, hand_d_z, hand_error [m] (a desired hand path);
//   fn_<e> [N], d_<e> [m], rest_<e> [1] (contact);
//   fn_link<j> [N], d_link<j> [m], rest_link<j> [1] (contact: the table's force on
//     link j's own solid, its signed distance to the nearest box, inf for a link
//     without a solid, and whether any of its contact points rests);
//   E_friction_<e> [J] per elbow, then E_friction_link<j> [J] per link (contact with
//     friction: the energy friction took from the arm at that body so far, E_friction
//     split by body);
//   the energy terms with a column, in the order of engine/recording/energy_terms.hpp [J]:
//     E_in, E_joule, E_viscous, KE_links, KE_rotors, PE, E_magnetic;
//     E_friction, E_normal, E_impact, E_projection (contact);
//     E_drawn, E_regenerated (motors); E_joint_friction; E_gear;
//   balance_residual [J].
#pragma once

#include <array>
#include <string>
#include <vector>

#include "engine/recording/energy_terms.hpp"

namespace elbowsim {

struct Column {
  std::string name;  // e.g. "q0"
  std::string unit;  // e.g. "rad"
};


class TrajectoryLayout {
 public:
  // What the run recorded.
  struct Groups {
    int dof = 0;
    bool motors = false;              // i<j>, v<j>
    bool desired_hand = false;        // hand_d_*, hand_error
    bool contact = false;             // elbow columns and contact energies
    std::vector<std::string> elbows;  // names, in model order (contact)
    bool friction = false;            // E_friction_<body> columns: friction loss per body (contact)
    bool joint_friction = false;      // E_joint_friction
    bool gear = false;                // E_gear (gear efficiency below 1)
    bool pads = false;                // E_pad, E_pad_elastic (an elbow has a compliant pad)
    bool springs = false;             // E_spring (joint springs)
  };

  // Whether a run of these groups has the energy terms of `group`.
  static bool has_energy_group(const Groups& groups, EnergyGroup group);

  TrajectoryLayout() = default;
  explicit TrajectoryLayout(Groups groups);

  // The layout whose columns are exactly `columns` (names and units).
  // Throws std::invalid_argument naming the first column that differs from
  // what a layout would have there.
  static TrajectoryLayout from_columns(const std::vector<Column>& columns);

  const Groups& groups() const { return groups_; }
  const std::vector<Column>& columns() const { return columns_; }
  int size() const { return static_cast<int>(columns_.size()); }
  int dof() const { return groups_.dof; }
  int elbows() const { return static_cast<int>(groups_.elbows.size()); }
  bool has_motors() const { return groups_.motors; }
  bool has_desired_hand() const { return groups_.desired_hand; }
  bool has_contact() const { return groups_.contact; }

  // Column indices; -1 where the run did not record the quantity.
  int time() const { return 0; }
  int q(int j) const { return q_ + j; }
  int qd(int j) const { return q_ + groups_.dof + j; }
  int qdd(int j) const { return q_ + 2 * groups_.dof + j; }
  int current(int j) const { return current_ < 0 ? -1 : current_ + j; }
  int voltage(int j) const { return current_ < 0 ? -1 : current_ + groups_.dof + j; }
  int torque(int j) const { return torque_ + j; }
  int hand(int axis) const { return hand_ + axis; }                 // axis 0, 1, 2 = x, y, z
  int hand_desired(int axis) const { return desired_ < 0 ? -1 : desired_ + axis; }
  int hand_error() const { return desired_ < 0 ? -1 : desired_ + 3; }
  int elbow_force(int k) const { return elbow_ < 0 ? -1 : elbow_ + 3 * k; }
  int elbow_distance(int k) const { return elbow_ < 0 ? -1 : elbow_ + 3 * k + 1; }
  int elbow_resting(int k) const { return elbow_ < 0 ? -1 : elbow_ + 3 * k + 2; }
  int link_force(int j) const { return link_ < 0 ? -1 : link_ + 3 * j; }
  int link_distance(int j) const { return link_ < 0 ? -1 : link_ + 3 * j + 1; }
  int link_resting(int j) const { return link_ < 0 ? -1 : link_ + 3 * j + 2; }
  bool has_body_friction() const { return friction_ >= 0; }
  int elbow_friction(int k) const { return friction_ < 0 ? -1 : friction_ + k; }
  int link_friction(int j) const { return friction_ < 0 ? -1 : friction_ + elbows() + j; }
  int energy(Energy e) const;  // -1 for a term without a column or not recorded
  int balance_residual() const { return size() - 1; }
  // Index of the elbow called `name`, or -1.
  int elbow(const std::string& name) const;

 private:
  Groups groups_;
  std::vector<Column> columns_;
  int q_ = 1, current_ = -1, torque_ = -1, hand_ = -1, desired_ = -1, elbow_ = -1, link_ = -1,
      friction_ = -1;
  std::array<int, kEnergyTermCount> energy_index_{};  // energy(): -1 if absent
};

}  // namespace elbowsim
