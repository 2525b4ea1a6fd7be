// engine/control/tuning.cpp: gains placed by one rule (bandwidth, damping,
// integral pole) on a joint's inertia and motor constants, checked against
// what the closed loop then does: a single joint's response to an initial
// error, simulated by the engine, against the closed forms of the rule's
// second- and third-order loops.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>

#include "engine/control/controller.hpp"
#include "engine/control/plan.hpp"
#include "engine/control/tuning.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/step.hpp"
#include "engine/control/task_freedom.hpp"
#include "support/experiment_scenes.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

constexpr double kPi = std::numbers::pi;

// One link turning in a vertical plane, driven by the small servo (gear 50):
// I = 1 kg x (0.15 m)^2 + 0.01 + Jm 5e-7 x 50^2 = 0.03375 kg m^2. Gravity off
// makes the loop exactly linear (one joint has no Coriolis term).
Model one_joint(MotorModel motor, bool gravity = false) {
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.01}});
  m.effects.motor = motor;
  m.effects.gravity = gravity;
  m.effects.damping = true;
  m.motors = {small_servo()};
  finalize(m);
  return m;
}

// A controller holding q_d = 0 with the rule's gains, the plant started at q0.
std::shared_ptr<Controller> holding(const Model& m, const TuningRule& rule, double q0,
                                    double sample_period = 0) {
  auto plan = std::make_shared<Plan>();
  plan->dt = 1.0;
  plan->q = plan->qd = plan->v_ff = {Eigen::VectorXd::Zero(1)};
  plan->hand = {Eigen::Vector3d::Zero()};
  auto c = std::make_shared<Controller>();
  c->spec.kind = ControllerSpec::Kind::pd;
  const TunedGains g = tune_gains(m, Eigen::VectorXd::Zero(1), rule);
  c->spec.kp = g.kp, c->spec.kd = g.kd, c->spec.ki = g.ki;
  c->spec.loop.sample_period = sample_period;
  c->plan = plan;
  c->plant_start = Eigen::VectorXd::Constant(1, q0);
  return c;
}

struct Response {
  std::vector<double> t, q;
};

Response respond(const Model& model, std::shared_ptr<Controller> c, double duration,
                 double h) {
  Model m = model;
  m.options.step = h;
  m.options.duration = duration;
  Data data(m);
  data.controller = std::move(c);
  reset(m, data);
  Response r;
  while (data.t < duration - h / 2 && !data.failure) {
    r.t.push_back(data.t);
    r.q.push_back(data.x[0]);
    step(m, data);
  }
  REQUIRE_FALSE(data.failure);
  return r;
}

// [s] the first time the response falls through `level`, interpolated.
double crossing(const Response& r, double level) {
  for (std::size_t k = 1; k < r.q.size(); ++k)
    if (r.q[k - 1] > level && r.q[k] <= level)
      return r.t[k - 1] + (r.t[k] - r.t[k - 1]) * (r.q[k - 1] - level) / (r.q[k - 1] - r.q[k]);
  FAIL("never crossed ", level);
  return 0;
}

}  // namespace

TEST_CASE("tuning: a joint's loop is I = M_jj + Jm, g = Km / R, c = Km^2 / R + D + Dm") {
  const Model m = one_joint(MotorModel::quasi_static);
  const TunedGains g = tune_gains(m, Eigen::VectorXd::Zero(1), {10.0, 1.0, 0.5});
  CHECK(g.inertia[0] == doctest::Approx(1.0 * 0.15 * 0.15 + 0.01 + 5e-7 * 2500).epsilon(1e-12));
  const double w = 2 * kPi * 10, I = g.inertia[0], gain = 0.03 * 50 / 2.0;
  const double c = 1.5 * 1.5 / 2.0 + 1e-6 * 2500;
  // (s^2 + 2 w s + w^2)(s + w/2) = s^3 + 2.5 w s^2 + 2 w^2 s + 0.5 w^3
  CHECK(g.kp[0] == doctest::Approx(2 * w * w * I / gain).epsilon(1e-12));
  CHECK(g.kd[0] == doctest::Approx((2.5 * w * I - c) / gain).epsilon(1e-12));
  CHECK(g.ki[0] == doctest::Approx(0.5 * w * w * w * I / gain).epsilon(1e-12));
  CHECK(g.warnings.empty());
  // The closed loop has the rule's poles: -w (twice) and -w/2.
  const JointLoop loop = joint_loop(m, Eigen::MatrixXd::Constant(1, 1, I), 0);
  const auto poles = closed_loop_poles(loop, g.kp[0], g.kd[0], g.ki[0]);
  REQUIRE(poles.size() == 3);
  for (const auto& p : poles) CHECK(std::abs(p.imag()) < 1e-5 * w);  // a double root: ~sqrt(eps) apart
  CHECK(poles[0].real() == doctest::Approx(-w).epsilon(1e-6));
  CHECK(poles[1].real() == doctest::Approx(-w).epsilon(1e-6));
  CHECK(poles[2].real() == doctest::Approx(-w / 2).epsilon(1e-9));
}

TEST_CASE("tuning: a joint tuned for B Hz with damping 0.5 overshoots and peaks as the formula says") {
  // Released from q0 with no velocity, the PD loop's error is the standard
  // second-order step response upside down: overshoot exp(-pi z / sqrt(1 - z^2))
  // at t_p = pi / (w sqrt(1 - z^2)). Quasi-static electrics and continuous
  // control are the rule's own assumptions: the loop is exactly the formula's,
  // so the tolerances are the integration's (rk4 at 10 us: below 1e-9) and
  // the peak's sampling on the 10 us grid (t_p to 2e-4 of itself). From
  // 8 Hz up the rule needs Kd > 0 (below, the back-EMF alone damps more);
  // q0 = 0.01 rad keeps the command (Kp q0 = 7.1 V at 20 Hz) under 24 V.
  const double q0 = 0.01, zeta = 0.5;
  const double factor = std::sqrt(1 - zeta * zeta);
  for (const double bandwidth : {8.0, 10.0, 20.0}) {
    CAPTURE(bandwidth);
    const Model m = one_joint(MotorModel::quasi_static);
    const Response r = respond(m, holding(m, {bandwidth, zeta, 0}, q0), 0.5, 1e-5);
    const auto low = std::min_element(r.q.begin(), r.q.end());
    const double overshoot = -*low / q0;
    const double t_peak = r.t[std::size_t(low - r.q.begin())];
    const double w = 2 * kPi * bandwidth;
    CHECK(overshoot == doctest::Approx(std::exp(-kPi * zeta / factor)).epsilon(1e-6));
    CHECK(t_peak == doctest::Approx(kPi / (w * factor)).epsilon(2e-4));
  }
}

TEST_CASE("tuning: damping 1 rises from 90 % to 10 % in 3.358 / w, without overshoot") {
  // Critically damped: q / q0 = (1 + w t) exp(-w t); the 90 % and 10 % points
  // are at w t = 0.5318 and 3.8897 (solved below by bisection, not typed).
  const auto level_time = [](double level) {
    double lo = 0, hi = 20;
    for (int i = 0; i < 200; ++i) {
      const double mid = (lo + hi) / 2;
      ((1 + mid) * std::exp(-mid) > level ? lo : hi) = mid;
    }
    return lo;
  };
  const double rise = level_time(0.1) - level_time(0.9);
  CHECK(rise == doctest::Approx(3.358).epsilon(1e-3));
  const double q0 = 0.05, bandwidth = 10;
  const double w = 2 * kPi * bandwidth;
  SUBCASE("quasi-static electrics, the rule's own model: to the interpolation's 1e-4") {
    const Model m = one_joint(MotorModel::quasi_static);
    const Response r = respond(m, holding(m, {bandwidth, 1.0, 0}, q0), 0.5, 1e-5);
    CHECK(crossing(r, 0.1 * q0) - crossing(r, 0.9 * q0) == doctest::Approx(rise / w).epsilon(1e-4));
    CHECK(*std::min_element(r.q.begin(), r.q.end()) > -1e-6 * q0);
  }
  SUBCASE("full electrics: L / R = 0.25 ms is neglected by the rule, w L / R = 0.016: within 1 %") {
    const Model m = one_joint(MotorModel::full);
    const Response r = respond(m, holding(m, {bandwidth, 1.0, 0}, q0), 0.5, 1e-5);
    const double measured = crossing(r, 0.1 * q0) - crossing(r, 0.9 * q0);
    MESSAGE("full electrics: rise ", measured, " s against the rule's ", rise / w, " s");
    CHECK(measured == doctest::Approx(rise / w).epsilon(0.01));
  }
}

TEST_CASE("tuning: PID in a 10 kHz loop follows the rule's third-order loop") {
  // The continuous PID closed loop with states (int q, q, q'):
  //   I q''' = -g Ki q - g Kp q' - (g Kd + c) q''
  // solved exactly (matrix exponential), against the engine running the
  // sampled loop (hold, backward-difference velocity, the integral of past
  // samples). The sampled loop lags by about 1.5 T, w 1.5 T = 0.009 rad at
  // 10 Hz: its response stays within 1 % of q0 of the continuous one (0.26 % measured). The
  // PD loop differs from it by over 10 % of q0 (checked), so the bound tells
  // the two apart.
  const double q0 = 0.05, T = 1e-4;
  const TuningRule rule{10.0, 1.0, 0.5};
  const Model m = one_joint(MotorModel::quasi_static);
  const TunedGains g = tune_gains(m, Eigen::VectorXd::Zero(1), rule);
  const JointLoop loop = joint_loop(m, Eigen::MatrixXd::Constant(1, 1, g.inertia[0]), 0);
  Eigen::Matrix3d A;
  A << 0, 1, 0, 0, 0, 1, -loop.gain * g.ki[0] / loop.inertia, -loop.gain * g.kp[0] / loop.inertia,
      -(loop.gain * g.kd[0] + loop.damping) / loop.inertia;
  const Eigen::Vector3d x0(0, q0, 0);
  const Response pid = respond(m, holding(m, rule, q0, T), 0.4, T);
  const Response pd = respond(m, holding(m, {10.0, 1.0, 0}, q0, T), 0.4, T);
  double worst = 0, apart = 0;
  for (std::size_t k = 0; k < pid.t.size(); ++k) {
    const double exact = ((A * pid.t[k]).exp() * x0)[1];
    worst = std::max(worst, std::abs(pid.q[k] - exact));
    apart = std::max(apart, std::abs(pd.q[k] - exact));
  }
  MESSAGE("PID sampled at 10 kHz: largest departure from the continuous loop ", worst / q0,
          " of q0; the PD loop's ", apart / q0);
  CHECK(worst < 0.01 * q0);
  CHECK(apart > 0.1 * q0);
}

TEST_CASE("tuning: integral action removes the static sag that PD leaves under gravity") {
  // Held horizontal against gravity, PD settles where g Kp e = m g l_c:
  // e = 1.4715 N m / (g Kp); PID settles at e = 0.
  const Model m = one_joint(MotorModel::quasi_static, true);
  const double torque = 1.0 * 9.81 * 0.15;
  const TuningRule pd_rule{10.0, 1.0, 0}, pid_rule{10.0, 1.0, 0.5};
  const TunedGains g = tune_gains(m, Eigen::VectorXd::Zero(1), pd_rule);
  const double sag = torque / (0.75 * g.kp[0]);
  const Response pd = respond(m, holding(m, pd_rule, 0, 1e-3), 1.5, 1e-3);
  const Response pid = respond(m, holding(m, pid_rule, 0, 1e-3), 1.5, 1e-3);
  // The arm sags downward: q < 0 in the x-z plane with axes along -y.
  CHECK(std::abs(pd.q.back()) == doctest::Approx(sag).epsilon(1e-3));
  CHECK(std::abs(pid.q.back()) < 1e-3 * sag);
}

TEST_CASE("tuning: the integral stops while the command is at the voltage limit and pushing") {
  // 1 rad of error asks for about 350 V of a 24 V amplifier: the loop starts
  // saturated. Conditional integration: at a sample whose command sits at
  // the limit with the error pushing it further, the integral keeps its value.
  Model m = one_joint(MotorModel::quasi_static);
  m.options.step = 1e-3;
  m.options.duration = 1.0;
  Data data(m);
  data.controller = holding(m, {10.0, 1.0, 0.5}, 1.0, 1e-3);
  reset(m, data);
  int held_at_limit = 0, integrating = 0;
  double before = data.loop.integral[0];
  long sample = data.loop.next_sample;
  while (data.t < 1.0 - 1e-6 && !data.failure) {
    step(m, data);
    if (data.loop.next_sample == sample) continue;
    sample = data.loop.next_sample;
    const double v = data.loop.held[0], e = -data.loop.q_measured[0];
    if (std::abs(v) >= m.voltage_limit[0] && e * v > 0) {
      ++held_at_limit;
      CHECK(data.loop.integral[0] == before);
    } else {
      integrating += data.loop.integral[0] != before;
    }
    before = data.loop.integral[0];
  }
  REQUIRE_FALSE(data.failure);
  CHECK(held_at_limit > 10);
  CHECK(integrating > 100);
  CHECK(std::abs(data.x[0]) < 1e-3);  // and it still arrives
}

TEST_CASE("tuning: a joint damped beyond the rule gets Kd 0 and a warning with its real poles") {
  // At 1 Hz the rule asks 2 w I = 0.42 N m s/rad; the motor's back-EMF alone
  // gives 1.125.
  const Model m = one_joint(MotorModel::quasi_static);
  const TunedGains g = tune_gains(m, Eigen::VectorXd::Zero(1), {1.0, 1.0, 0});
  CHECK(g.kd[0] == 0);
  REQUIRE(g.warnings.size() == 1);
  const std::string& w = g.warnings[0];
  CAPTURE(w);
  CHECK(w.find("joint 0") != std::string::npos);
  CHECK(w.find("Kd is 0") != std::string::npos);
  // Its poles with Kd 0: I s^2 + c s + g Kp, two real roots, printed.
  const JointLoop loop = joint_loop(m, Eigen::MatrixXd::Constant(1, 1, g.inertia[0]), 0);
  const auto poles = closed_loop_poles(loop, g.kp[0], 0, 0);
  for (const auto& p : poles) {
    const std::complex<double> residual =
        loop.inertia * p * p + loop.damping * p + loop.gain * g.kp[0];
    CHECK(std::abs(residual) < 1e-9 * loop.gain * g.kp[0]);
    CHECK(p.imag() == 0);
  }
  CHECK(w.find(significant(poles[0].real(), 3)) != std::string::npos);
  // Under PD the joint keeps a pole at the rule's w = 2 pi rad/s; its own
  // damping puts the other at c / I - w.
  const double wr = 2 * kPi;
  int at_w = 0, at_rest = 0;
  for (const auto& p : poles) {
    at_w += std::abs(p.real() + wr) < 1e-9 * wr;
    at_rest += std::abs(p.real() + (loop.damping / loop.inertia - wr)) < 1e-9 * wr;
  }
  CHECK(at_w == 1);
  CHECK(at_rest == 1);
  // The rule's own pair, -2 pi rad/s twice, is named as what it is not.
  CHECK(w.find("not the rule's -6.28") != std::string::npos);
}

TEST_CASE("tuning: PID on a joint damped beyond the rule keeps the rule's pair; the integral pole moves out") {
  // At 3 Hz with alpha 0.5 the rule asks (2 + 0.5) w I = 1.59 N m s/rad; the
  // joint has c = 1.1275. At 2 Hz it asks 1.06: overdamped. Kd 0 leaves the
  // s^2 coefficient at c / I; the poles are the rule's double -w and
  // a = c / I - 2 w (not alpha w).
  const Model m = one_joint(MotorModel::quasi_static);
  const TunedGains g = tune_gains(m, Eigen::VectorXd::Zero(1), {2.0, 1.0, 0.5});
  CHECK(g.kd[0] == 0);
  REQUIRE(g.warnings.size() == 1);
  const JointLoop loop = joint_loop(m, Eigen::MatrixXd::Constant(1, 1, g.inertia[0]), 0);
  const double w = 2 * kPi * 2, a = loop.damping / loop.inertia - 2 * w;
  CHECK(a > 0.5 * w);
  const auto poles = closed_loop_poles(loop, g.kp[0], 0, g.ki[0]);
  REQUIRE(poles.size() == 3);
  int at_w = 0, at_a = 0;
  for (const auto& p : poles) {
    CHECK(p.imag() == 0);
    at_w += std::abs(p.real() + w) < 1e-6 * w;
    at_a += std::abs(p.real() + a) < 1e-9 * a;
  }
  CHECK(at_w == 2);  // the rule's double pole
  CHECK(at_a == 1);
  // Still PID: it removes a constant disturbance (Ki > 0), and the pair is
  // what the warning's first poles name.
  CHECK(g.ki[0] > 0);
  CHECK(g.warnings[0].find("poles are " + significant(-w, 3) + ", " + significant(-w, 3) + ", " +
                           significant(-a, 3) + " rad/s") != std::string::npos);
}

TEST_CASE("joints held by the table: a sticking elbow on link 1 holds joints 0 and 1; sliding or held up, none") {
  // The writing arm's elbow at the end of link 1: sticking (Coulomb
  // friction) it fixes joints 0 and 1; on a frictionless table (one row,
  // the table's normal) it fixes none; held 2 cm above, the table holds none.
  // (make_controller's use of it: the shipped experiment, test_scenario_task.cpp.)
  testing::WritingArm on;
  testing::ExperimentScene scene = on.scene();
  const Eigen::VectorXd q0 = start_pose(scene.model, scene.experiment);
  Model sticking = scene.model;
  sticking.effects.friction = true;
  sticking.contact.friction.mu = 0.6;
  finalize(sticking);
  REQUIRE(sticking.has_coulomb_friction());
  CHECK(joints_held_by_table(sticking, scene.experiment, q0) ==
        std::vector<bool>{true, true, false, false});
  Model sliding = scene.model;
  sliding.effects.friction = false;
  finalize(sliding);
  CHECK(joints_held_by_table(sliding, scene.experiment, q0) == std::vector<bool>(4, false));
  testing::WritingArm off;
  off.elbow_on = false;
  const testing::ExperimentScene up = off.scene();
  CHECK(joints_held_by_table(sticking, up.experiment, q0) == std::vector<bool>(4, false));
}
