// The paper's forward-dynamics method (eq. 50, 53-54, Walker & Orin 1982, method 1):
// M is built column by column from s calls of inverse dynamics.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// data.mass_matrix [n x n] = M(q) + Jm, column i = INV(q, 0, e_i, 0).
// Needs forward_kinematics(q).
void mass_matrix_walker_orin(const Model& model, Data& data);

// data.bias [n] = B_J = INV(q, qd, 0, g) = h + G + (D + Dm) qd (eq. 53).
// Needs forward_kinematics(q).
void bias_torques(const Model& model, Data& data, ConstVec qd);

}  // namespace elbowsim
