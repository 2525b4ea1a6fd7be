// Models built in code for tests and benchmarks: the textbook planar arm and
// random spatial chains. Scenario files cover the rest (scenarios/).
#pragma once

#include <cstdint>

#include "engine/model.hpp"

namespace elbowsim::testing {

struct PlanarLinkSpec {
  double length, mass, com, inertia;  // [m], [kg], [m along link], [kg m^2 about the com]
};

//   z
//   |      o---- link 1 ----o (hand)
//   |     /q2
//   |    link 0
//   |   /q1
//   +--o------------------------- x      joint axes along -y
// Planar arm in the x-z plane; no motors, gravity on, damping off.
Model planar_arm(const std::vector<PlanarLinkSpec>& links);

// A small servo every joint of `model` gets: R 2 ohm, L 0.5 mH, K 0.03 N m/A,
// gear 50, rotor 5e-7 kg m^2, gear friction 1e-6 N m s/rad, 24 V.
Motor small_servo();

// Random chain of n revolute joints: random unit axes, origin offsets and
// rotations, masses in [0.5, 2] kg, coms, and physically valid inertias.
// With motors (full) of random gear ratios, damping and gravity on.
Model random_chain(int n, std::uint32_t seed);

}  // namespace elbowsim::testing
