// Rows of M* for the resting slots (paper eq. 6-9, 15, 31): an elbow, a
// capsule end or interior point, a link sphere or box corner on a table box.
// The feature a slot rests on is held for the step (its frame,
// detection.hpp): a face's plane, an edge's line or a corner's point. The
// constraint of slot k is the distance of its ball centre c_k(q) from that
// feature less the radius, C_k = |c_k - feature| - r_k (on a face: the signed
// n . (c_k - s_k) - r_k), so ||dC/dc|| = 1 and j_ck = n_k^T J_k(q) with n_k
// the unit vector from the feature to the centre (constant on a face; it
// turns with a ball rolling over an edge).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Fills data.contact.{Jc, Jf, gamma, C, Cd, slide, row_normal, row_friction} for
// the normal rows of the slots in data.contact.active, then the tangent rows
// of data.contact.tangent_rows, from forward_kinematics(q) and rates qd:
//   gamma_k = -n^T Jdot_k qd - (|v_perp|^2 - (n.v_perp)^2) / rho   (eq. 15, 31;
//             the second term: an edge's or a corner's curvature, rho = C + r,
//             v_perp the centre's velocity across the edge)
//           - (2/T) Cd_k - (1/T^2) C_k                    (Baumgarte, stabilization: baumgarte)
//   Jf_k    = j_ck - mu s_k^T J_pk                        (sliding friction, eq. 9)
// where J_pk is the Jacobian of the contact point (ball centre - r n) and s_k
// its slip direction scaled by the law (friction.hpp). A tangent row t of a
// sticking slot: Jc = Jf = t^T J_pk, gamma = -t^T Jdot_pk qd - (1/T) t^T v_pk,
// C = 0, Cd = t^T v_pk (its slip speed).
void constraint_rows(const Model& model, Data& data, ConstVec qd);

}  // namespace elbowsim
