// Rows of M* for the resting slots (paper eq. 6-9, 15, 31): an elbow, a
// capsule end or interior point, a link sphere or box corner on a table box.
// With the table normal n held for the step, the constraint of slot k is its
// signed distance C_k(q) = n . (c_k(q) - s_k) - r_k (c_k the ball centre, s_k
// the surface point, r_k the radius), so ||dC/dr|| = 1 and j_ck = n^T J_k(q).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Fills data.contact.{Jc, Jf, gamma, C, Cd, slide} for the slots in
// data.contact.active, from forward_kinematics(q) and rates qd:
//   gamma_k = -n^T Jdot_k qd                             (eq. 15, 31)
//           - (2/T) Cd_k - (1/T^2) C_k                    (Baumgarte, stabilization: baumgarte)
//   Jf_k    = j_ck - mu t_k^T J_pk                        (friction, eq. 9)
// where J_pk is the Jacobian of the contact point (sphere centre - r n) and
// t_k its sliding direction, regularised as v / max(|v|, slip_velocity).
void constraint_rows(const Model& model, Data& data, ConstVec qd);

}  // namespace elbowsim
