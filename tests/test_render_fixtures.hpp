// Shared by the renderer tests: a small arm with one elbow over a table, and a
// hand-made recording of it with a touchdown at t = 0.5 s.
//
//   z
//   |        o  link 1 (q1 = pi/2 at t = 0.2 .. 0.4 s)
//   |        |
//   o--------O------- x     link 0 along +x (q0 = 0), elbow sphere O at its tip
//   ==========================  table, top at z = -0.03 (touching the sphere)
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "support/recordings.hpp"
#include "engine/data.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/recording/recording.hpp"
#include "support/models.hpp"

namespace render_fixture {

inline elbowsim::Model arm(int dof = 2) {
  using namespace elbowsim;
  std::vector<testing::PlanarLinkSpec> links{{0.4, 1.3, 0.2, 0.017}, {0.35, 0.9, 0.175, 0.009}};
  if (dof == 3) links.push_back({0.2, 0.5, 0.1, 0.002});
  Model m = testing::planar_arm(links);
  m.links[0].radius = 0.02;
  m.links[1].radius = 0.015;
  m.elbows = {Elbow{"elbow", 0, Eigen::Vector3d(0.4, 0, 0), 0.03}};
  TableBox table;
  table.center = Eigen::Vector3d(0.4, 0, -0.08);
  table.size = Eigen::Vector3d(1.0, 0.6, 0.1);
  m.table = {table};
  m.effects.contact = true;
  finalize(m);
  return m;
}

// Rows every 0.1 s from 0 to 1 s: q0 = 0; q1 = 0, pi/4, pi/2 (to 0.4 s), then 0;
// the elbow rests from 0.5 s on, fn = 6, 7, 8, 12, 12, 12 N; E_in = t [J]; the
// other columns 0. With `desired_hand` the layout has the desired hand columns (0).
inline elbowsim::Recording recording(bool desired_hand = false) {
  using namespace elbowsim;
  const Model model = arm();
  Recording rec = testing::zero_recording({2, false, desired_hand, true, {"elbow"}}, 11);
  const TrajectoryLayout& L = rec.layout;
  const double pi = std::numbers::pi;
  const double q1[11] = {0, pi / 4, pi / 2, pi / 2, pi / 2, 0, 0, 0, 0, 0, 0};
  const double fn[11] = {0, 0, 0, 0, 0, 6, 7, 8, 12, 12, 12};
  Data data(model);
  for (int k = 0; k <= 10; ++k) {
    const double t = 0.1 * k;
    const Eigen::Vector2d q(0, q1[k]);
    forward_kinematics(model, data, q);
    const Eigen::Vector3d hand = point_position(data, model.hand_link, model.hand_point);
    testing::set(rec, k, L.time(), t);
    testing::set(rec, k, L.q(1), q[1]);
    for (int a = 0; a < 3; ++a) testing::set(rec, k, L.hand(a), hand[a]);
    testing::set(rec, k, L.elbow_force(0), fn[k]);
    testing::set(rec, k, L.elbow_resting(0), k >= 5 ? 1.0 : 0.0);
    testing::set(rec, k, L.energy(Energy::electrical_in), t);
  }
  return rec;
}

// A valid scenario file without a render: section (append one to test it).
inline std::string scenario_yaml() {
  return "name: fixture\n"
         "robot:\n"
         "  planar:\n"
         "    links:\n"
         "      - {length: 0.4, mass: 1.3}\n"
         "      - {length: 0.35, mass: 0.9}\n"
         "effects: {motor: none}\n"
         "simulation: {duration: 0.2}\n";
}
inline int scenario_lines() { return 8; }

}  // namespace render_fixture
