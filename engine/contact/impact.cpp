#include "engine/contact/impact.hpp"

#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/contact/lcp.hpp"
#include "engine/run/state_layout.hpp"

namespace elbowsim {

namespace {

Eigen::MatrixXd normal_rows(const Model& model, Data& data, const std::vector<int>& elbows) {
  Eigen::MatrixXd Jc(elbows.size(), model.dof);
  for (std::size_t r = 0; r < elbows.size(); ++r) {
    const Elbow& e = model.elbows[elbows[r]];
    point_jacobian(model, data, e.link, e.point, data.contact.J3);
    Jc.row(r) = data.contact.normal[elbows[r]].transpose() * data.contact.J3;
  }
  return Jc;
}

}  // namespace

ImpactResult apply_impact(const Model& model, Data& data, const std::vector<int>& landing,
                          const std::vector<int>& resting) {
  const StateLayout s(model);
  ImpactResult r;
  r.elbows = landing;
  r.elbows.insert(r.elbows.end(), resting.begin(), resting.end());
  auto qd = data.x.segment(s.qd(), s.n);
  mass_matrix_crba(model, data);
  data.llt.compute(data.mass_matrix);
  const Eigen::MatrixXd Jc = normal_rows(model, data, r.elbows);
  const Eigen::MatrixXd MinvJt = data.llt.solve(Jc.transpose());
  const Eigen::MatrixXd A = Jc * MinvJt;
  r.speed_before = Jc * qd;
  Eigen::VectorXd b = r.speed_before;
  for (std::size_t k = 0; k < landing.size(); ++k) b[k] *= 1.0 + model.contact.restitution;
  Eigen::VectorXd w;
  std::vector<bool> active(r.elbows.size(), true);
  r.kinetic_before = 0.5 * qd.dot(data.mass_matrix * qd);
  r.solved = solve_lcp(A, b, model.contact.rank_tolerance, 1e-12, r.impulse, w, active).solved;
  qd += MinvJt * r.impulse;
  r.speed_after = Jc * qd;
  r.kinetic_after = 0.5 * qd.dot(data.mass_matrix * qd);
  r.energy_lost = -0.5 * r.impulse.cwiseProduct(r.speed_before + r.speed_after);
  return r;
}

}  // namespace elbowsim
