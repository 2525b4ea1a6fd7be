#include "engine/contact/projection.hpp"

#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/detection.hpp"
#include "engine/contact/min_norm_solve.hpp"
#include "engine/contact/stick_slip.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

// Minimum-norm, mass-weighted correction ws.dx with Jc dx = -residual.
const Eigen::VectorXd& weighted_correction(const Model& model, Data& data, ConstVec residual) {
  ContactData& c = data.contact;
  SolverWorkspace& ws = c.solver(c.rows());
  mass_matrix_crba(model, data);
  data.llt.compute(data.mass_matrix);
  ws.MinvJt = c.Jc.transpose();
  data.llt.solveInPlace(ws.MinvJt);
  ws.block.noalias() = c.Jc * ws.MinvJt;
  ws.cod.compute(ws.block);
  ws.cod.setThreshold(model.contact.rank_tolerance);
  min_norm_solve(ws, residual, ws.x);
  ws.dx.noalias() = -ws.MinvJt * ws.x;
  return ws.dx;
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

void stabilise(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.active.clear();
  for (int k = 0; k < int(c.resting.size()); ++k)
    if (c.resting[k]) c.active.push_back(k);
  tangent_rows_from_modes(model, data);
  if (c.active.empty()) return;
  freeze_frames(data);  // onto the features the slots touch now (the detection is current)
  const StateLayout s(model);
  const auto qd = data.x.segment(s.qd(), s.n);
  EnergyTerms before, after;
  forward_kinematics(model, data, data.x.segment(s.q(), s.n));
  stored_energy(model, data, qd, data.current, before);  // only the mechanical part is used
  project_onto_constraints(model, data);
  stored_energy(model, data, qd, data.current, after);
  c.projection_energy += after.mechanical() - before.mechanical();
  detect_contacts(model, data);
}

}  // namespace elbowsim
