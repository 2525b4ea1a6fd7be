// Composite-rigid-body algorithm for the joint-space inertia matrix.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// data.mass_matrix [n x n] = M(q) + Jm. Needs forward_kinematics(q). Also
// leaves data.spatial_inertia (per link) and data.motion_subspace filled.
void mass_matrix_crba(const Model& model, Data& data);

}  // namespace elbowsim
