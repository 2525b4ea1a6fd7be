#include "derivative.hpp"

#include "forward_dynamics.hpp"
#include "kinematics.hpp"
#include "motor.hpp"
#include "state_vector.hpp"

namespace elbowsim {

void stiff_rates(const Model& model, Eigen::Ref<Eigen::ArrayXd> lambda) {
  const StateLayout s(model);
  lambda.setZero();
  if (s.current >= 0)
    lambda.segment(s.current, s.n) = -model.resistance.array() / model.inductance.array();
}

namespace {

// Powers that feed the energy integrals: electrical input, Joule loss, viscous loss.
void energy_rates(const Model& model, const Data& data, ConstVec qd, Eigen::Ref<Eigen::VectorXd> out) {
  if (model.has_motor()) {
    out[0] = data.voltage.dot(data.current);
    out[1] = data.current.dot(model.resistance.cwiseProduct(data.current));
  } else {
    out[0] = data.actuation.dot(qd);
    out[1] = 0.0;
  }
  out[2] = model.effects.damping ? qd.dot(model.viscous.cwiseProduct(qd)) : 0.0;
}

}  // namespace

void nonstiff_rates(const Model& model, Data& data, double t, ConstVec x,
                    Eigen::Ref<Eigen::VectorXd> N) {
  const StateLayout s(model);
  const auto q = x.segment(s.q(), s.n);
  const auto qd = x.segment(s.qd(), s.n);
  forward_kinematics(model, data, q);
  if (s.current >= 0)
    motor_stage(model, data, t, qd, x.segment(s.current, s.n));
  else
    motor_stage(model, data, t, qd, data.current);
  forward_dynamics(model, data, qd, data.actuation, data.qdd);

  N.segment(s.q(), s.n) = qd;
  N.segment(s.qd(), s.n) = data.qdd;
  // Electrical eq. (16): L di/dt = v - R i - Km qd; the -R/L i part is in lambda.
  if (s.current >= 0)
    N.segment(s.current, s.n) =
        (data.voltage - model.km.cwiseProduct(qd)).cwiseQuotient(model.inductance);
  energy_rates(model, data, qd, N.segment(s.energy, 3));
}

}  // namespace elbowsim
