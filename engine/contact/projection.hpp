// Drift control by projection (stabilization: projection): after a step, q
// is moved back onto C(q) = 0 by mass-weighted least squares,
//   dq = -M^-1 Jc^T (Jc M^-1 Jc^T)^+ C(q)     (Gauss-Newton, a few iterations)
// and qd onto Jc qd = 0 the same way.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Projects data.x for the elbows in data.contact.active (normals and
// surface points in data.contact). Returns max |C| after the position pass.
// Leaves forward_kinematics at the projected q. Allocates nothing.
double project_onto_constraints(const Model& model, Data& data);

// The stabilisation stage of a step (stabilization: projection): projects
// onto the resting elbows' constraints, adds the stored-energy change it made
// to data.contact.projection_energy and detects contacts again.
void stabilise(const Model& model, Data& data);

}  // namespace elbowsim
