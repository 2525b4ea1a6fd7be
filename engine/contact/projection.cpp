#include "engine/contact/projection.hpp"

#include <Eigen/QR>

#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/state_layout.hpp"

namespace elbowsim {

namespace {

// Minimum-norm, mass-weighted correction dx with Jc dx = -residual.
Eigen::VectorXd weighted_correction(const Model& model, Data& data, const Eigen::VectorXd& residual) {
  mass_matrix_crba(model, data);
  data.llt.compute(data.mass_matrix);
  const Eigen::MatrixXd MinvJt = data.llt.solve(data.contact.Jc.transpose());
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(data.contact.Jc * MinvJt);
  cod.setThreshold(model.contact.rank_tolerance);
  return -MinvJt * cod.solve(residual);
}

}  // namespace

double project_onto_constraints(const Model& model, Data& data) {
  const StateLayout s(model);
  auto q = data.x.segment(s.q(), s.n);
  auto qd = data.x.segment(s.qd(), s.n);
  double worst = 0;
  for (int iteration = 0; iteration < 5; ++iteration) {
    forward_kinematics(model, data, q);
    constraint_rows(model, data, qd);
    worst = data.contact.C.cwiseAbs().maxCoeff();
    if (worst < 1e-13) break;
    q += weighted_correction(model, data, data.contact.C);
  }
  forward_kinematics(model, data, q);
  constraint_rows(model, data, qd);
  worst = data.contact.C.cwiseAbs().maxCoeff();
  qd += weighted_correction(model, data, data.contact.Cd);
  return worst;
}

}  // namespace elbowsim
