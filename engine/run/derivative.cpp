#include "engine/run/derivative.hpp"

#include <cmath>

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/pad.hpp"
#include "engine/dynamics/applied_torques.hpp"
#include "engine/dynamics/joint_friction.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/motor.hpp"
#include "engine/control/controller.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

void stiff_rates(const Model& model, Eigen::Ref<Eigen::ArrayXd> lambda) {
  const StateLayout s(model);
  lambda.setZero();
  if (s.current >= 0)
    lambda.segment(s.current, s.n) = -model.resistance.array() / model.inductance.array();
}

namespace {

// Powers that feed the energy integrals (each into its slot): electrical
// input, Joule loss, viscous loss (and with contact, friction loss and the
// table's normal work). Without motors the input is the work of the input
// torques: data.actuation less the hand force's share, whose power
// `hand_power` has its own integral.
void energy_rates(const Model& model, Data& data, const StateLayout& s, ConstVec qd,
                  double hand_power, Eigen::Ref<Eigen::VectorXd> N) {
  const auto rate = [&](Energy e) -> double& { return N[s.slot(e)]; };
  if (model.has_motor()) {
    rate(Energy::electrical_in) = data.voltage.dot(data.current);
    rate(Energy::joule) = data.current.dot(model.resistance.cwiseProduct(data.current));
    // E_in split by the sign of each motor's power.
    double drawn = 0, regenerated = 0;
    for (int j = 0; j < model.dof; ++j) {
      const double p = data.voltage[j] * data.current[j];
      (p > 0 ? drawn : regenerated) += std::abs(p);
    }
    rate(Energy::drawn) = drawn;
    rate(Energy::regenerated) = regenerated;
  } else {
    rate(Energy::electrical_in) = data.actuation.dot(qd) - hand_power;
    rate(Energy::joule) = 0.0;
  }
  rate(Energy::viscous) = model.effects.damping ? qd.dot(model.viscous.cwiseProduct(qd)) : 0.0;
  if (!model.effects.contact) return;
  // Table power on the arm: f^T Jf qd = the normal rows' fn^T Jc qd (normal
  // work, zero while C holds) - the friction loss (sliding rows: mu fn |v_t|
  // >= 0; tangent rows of sticking slots: -f_t v_t, zero while they stick).
  const ContactData& c = data.contact;
  const int pad_slot = s.slot(Energy::pad_loss);
  if (pad_slot >= 0) N[pad_slot] = c.active.empty() ? 0.0 : pad_loss_rate(model, c);
  if (c.active.empty()) {
    rate(Energy::friction) = rate(Energy::normal_work) = 0.0;
    return;
  }
  const Eigen::Index pn = c.normal_rows();
  const double normal = c.fn.head(pn).dot(c.Cd.head(pn));
  data.contact.Jf_qd.noalias() = c.Jf * qd;
  rate(Energy::friction) = normal - c.fn.dot(c.Jf_qd);
  // A pad's push does work on the arm, -d/dt(k d^2 / 2) - c d'^2: the pad's
  // own terms (E_pad_elastic, E_pad) hold it, so the table's normal work
  // leaves those rows out (the table under the pad does none).
  rate(Energy::normal_work) = pad_slot >= 0 ? normal - pad_power(model, c) : normal;
}

// E_friction's rate split by contact body (each elbow, then each link): each
// row's share, fn_r Cd_r - fn_r (Jf qd)_r (the first term on normal rows only),
// which energy_rates sums. Needs energy_rates' Jf qd at this evaluation.
void body_friction_rates(const Model& model, const Data& data, Eigen::Ref<Eigen::VectorXd> out) {
  out.setZero();
  const ContactData& c = data.contact;
  if (c.active.empty()) return;
  const int elbows = static_cast<int>(model.elbows.size());
  const int pn = c.normal_rows();
  const int p = pn + static_cast<int>(c.tangent_rows.size());
  for (int r = 0; r < p; ++r) {
    const int slot = r < pn ? c.active[std::size_t(r)] : c.tangent_rows[std::size_t(r - pn)].slot;
    const Primitive& prim = c.primitive_of(slot);
    out[prim.elbow >= 0 ? prim.elbow : elbows + prim.link] +=
        (r < pn ? c.fn[r] * c.Cd[r] : 0.0) - c.fn[r] * c.Jf_qd[r];
  }
}

// (M + Jm) qdd = tau - B_J + Jf^T fn with Jc qdd = gamma for the resting
// elbows (eq. 30-33), stuck joints locked (joint friction); plain forward
// dynamics when none rests.
void arm_accelerations(const Model& model, Data& data, ConstVec qd) {
  if (!model.effects.contact || data.contact.active.empty()) {
    if (model.effects.joint_friction)
      joint_friction_dynamics(model, data, qd);
    else
      forward_dynamics(model, data, qd, data.actuation, data.qdd);
    return;
  }
  // M (CRBA's when the dynamics are aba) or, with the aba solver, the
  // articulated inertias; and B_J.
  constrained_mechanics(model, data, qd);
  constraint_rows(model, data, qd);
  solve_constrained(model, data, data.tau_applied);
  if (model.effects.joint_friction) holding_torques(model, data);
}

}  // namespace

void nonstiff_rates(const Model& model, Data& data, double t, ConstVec x,
                    Eigen::Ref<Eigen::VectorXd> N) {
  const StateLayout s(model);
  ++data.work.evaluations;
  const auto q = x.segment(s.q(), s.n);
  const auto qd = x.segment(s.qd(), s.n);
  forward_kinematics(model, data, q);
  command(model, data, t, q, qd);
  if (s.current >= 0)
    motor_stage(model, data, qd, x.segment(s.current, s.n));
  else
    motor_stage(model, data, qd, data.current);
  const double hand_power = applied_torques(model, data, qd);
  arm_accelerations(model, data, qd);

  N.segment(s.q(), s.n) = qd;
  N.segment(s.qd(), s.n) = data.qdd;
  // Electrical eq. (16): L di/dt = v - R i - Km qd; the -R/L i part is in lambda.
  if (s.current >= 0)
    N.segment(s.current, s.n) =
        (data.voltage - model.km.cwiseProduct(qd)).cwiseQuotient(model.inductance);
  energy_rates(model, data, s, qd, hand_power, N);
  if (s.slot(Energy::external) >= 0) N[s.slot(Energy::external)] = hand_power;
  // Friction loss of the sliding joints (a stuck joint does not move: qd_j = 0).
  if (s.slot(Energy::joint_friction) >= 0)
    N[s.slot(Energy::joint_friction)] = -data.joint_friction_torque.dot(qd);
  if (s.slot(Energy::gear_loss) >= 0) N[s.slot(Energy::gear_loss)] = data.gear_loss_power;
  if (s.body_friction >= 0) body_friction_rates(model, data, N.segment(s.body_friction, s.size - s.body_friction));
}

}  // namespace elbowsim
