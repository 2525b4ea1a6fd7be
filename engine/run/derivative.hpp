// The right-hand side of the equations of motion, split as
//   x' = lambda .* x + N(t, x)
// where lambda is -R/L for motor currents and zero elsewhere, so that the
// integrators can treat the (possibly very fast) electrical decay exactly.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// lambda per component of x (state_layout.hpp): -R/L on currents, else 0.
void stiff_rates(const Model& model, Eigen::Ref<Eigen::ArrayXd> lambda);

// N(t, x): kinematics, motors (eq. 16-27), forward dynamics (eq. 29/54) and
// the energy powers v.i, i^T R i, qd^T (D + Dm) qd. Leaves the stage outputs
// (qdd, voltage, current, actuation, ...) of this evaluation in data.
void nonstiff_rates(const Model& model, Data& data, double t, ConstVec x,
                    Eigen::Ref<Eigen::VectorXd> N);

}  // namespace elbowsim
