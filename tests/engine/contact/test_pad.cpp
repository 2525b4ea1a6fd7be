// engine/contact/pad.cpp: a compliant (Kelvin-Voigt) pad on an elbow, checked
// against its closed forms on a lever whose elbow presses the pad straight
// down: the static depth m g l_c / (r k), the contact time and restitution of
// a landing, the energy it loses, and Coulomb friction through the pad.
//
// The lever: one link turning about a horizontal joint, its elbow sphere at r
// along it, the pad's table under the elbow at q = 0. Pressed d = -r sin q
// deep the pad pushes f = k d + c d' straight up at the ball's lowest point,
// whose moment arm is r cos q, so the statics are exact: f r cos q = m g l_c
// cos q. In a landing the lever turns by at most ~1e-4 rad, where
// sin q cos q = q (1 + O(q^2)): the contact is a linear oscillator of mass
// I / r^2 to 1e-8, far inside the 1e-6 the landing checks allow.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/pad.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/contact_scenes.hpp"
#include "support/models.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

struct Lever {
  double length = 0.5, mass = 2.0, com = 0.25, inertia = 0.04;  // inertia about the com [kg m^2]
  double r = 0.4, radius = 0.02;                                // elbow at r, sphere radius
  double joint_inertia() const { return inertia + mass * com * com; }
  double effective_mass() const { return joint_inertia() / (r * r); }  // at the elbow [kg]
  // Pad of stiffness k and damping ratio zeta on the lever's effective mass.
  Pad pad(double k, double zeta) const {
    return Pad{k, 2 * zeta * std::sqrt(k * effective_mass()), 0.005};
  }
  Model model(const Pad& pad, bool gravity, double q0, double qd0, double duration, double step) const {
    Model m = planar_arm({{length, mass, com, inertia}});
    if (!gravity) m.gravity.setZero();
    m.elbows = {Elbow{"elbow", 0, Eigen::Vector3d(r, 0, 0), radius, pad}};
    TableBox box;  // top at -radius: the elbow touches it at q = 0
    box.size = Eigen::Vector3d(2.0, 1.0, 0.1);
    box.center = Eigen::Vector3d(r, 0, -radius - 0.05);
    m.table = {box};
    m.links[0].collision.kind = LinkCollision::Kind::none;
    m.effects.contact = true;
    m.contact.locate_tolerance = 1e-12;
    m.initial.q = Eigen::VectorXd::Constant(1, q0);
    m.initial.qd = Eigen::VectorXd::Constant(1, qd0);
    m.options = {duration, step, IntegratorKind::rk4, DynamicsMethod::crba};
    finalize(m);
    return m;
  }
};

// A Kelvin-Voigt contact that lets go where its force reaches 0 (it never
// pulls): with w0 = sqrt(k / m), zeta < 1, wd = w0 sqrt(1 - zeta^2), the depth
// d(t) = v0 / wd e^(-zeta w0 t) sin(wd t) gives k d + c d' = 0 at
// wd t = pi - 2 asin(zeta), where d' = -v0 e^(-zeta w0 t): the restitution is
// e^(-zeta w0 t_c) exactly.
double contact_time(double k, double m, double zeta) {
  const double w0 = std::sqrt(k / m);
  return (M_PI - 2 * std::asin(zeta)) / (w0 * std::sqrt(1 - zeta * zeta));
}
double restitution(double k, double m, double zeta) {
  return std::exp(-zeta * std::sqrt(k / m) * contact_time(k, m, zeta));
}

}  // namespace

TEST_CASE("pad: a lever resting on its pad sinks to the static depth m g l_c / (r k)") {
  const Lever lever;
  const double k = 1e5;
  const Model m = lever.model(lever.pad(k, 0.5), true, 0.0, 0.0, 0.5, 1e-4);
  const RunResult r = simulate(m, {});
  REQUIRE(r.completed);
  const double expected = lever.mass * 9.81 * lever.com / (lever.r * k);  // 1.2e-4 m
  const double depth = -lever.r * std::sin(last(r, "q0"));
  MESSAGE("static depth ", depth, " m, closed form ", expected, " m");
  // Settled for 0.5 s at zeta w0 = 155 /s (e^-77): what is left is rounding.
  CHECK(std::abs(depth - expected) < 1e-9 * expected);
  CHECK(std::abs(last(r, "fn_elbow") - k * expected) < 1e-8 * k * expected);
  CHECK(last(r, "rest_elbow") == 1);
  // The pad's elastic energy at rest, k d^2 / 2, is in the stored energy.
  CHECK(r.energy_final.pad_elastic == doctest::Approx(0.5 * k * expected * expected).epsilon(1e-8));
}

TEST_CASE("pad: a landing lasts (pi - 2 asin zeta) / w_d and rebounds with e = exp(-zeta w0 t_c)") {
  const Lever lever;
  const double k = 1e5, v_in = 0.01, height = 1e-5;  // [N/m], [m/s] down at the elbow, [m] above
  const double me = lever.effective_mass();
  for (double zeta : {0.0, 0.1, 0.3, 0.7}) {
    CAPTURE(zeta);
    // Turning at v_in / r: the elbow meets the pad (q = 0) at v_in.
    const double q0 = std::asin(height / lever.r);
    const Model m = lever.model(lever.pad(k, zeta), false, q0, -v_in / lever.r, 0.03, 1e-5);
    const RunResult r = simulate(m, {});
    REQUIRE(r.completed);
    const ContactEvent* landing = first_event(r, ContactEvent::Kind::landing);
    const ContactEvent* release = first_event(r, ContactEvent::Kind::release);
    REQUIRE(landing != nullptr);
    REQUIRE(release != nullptr);
    const double t_c = release->t - landing->t;
    const double q = last(r, "q0"), v_out = lever.r * std::cos(q) * last(r, "qd0");
    const double e = v_out / v_in;
    MESSAGE("contact ", t_c, " s (closed form ", contact_time(k, me, zeta), "), e ", e,
            " (closed form ", restitution(k, me, zeta), ")");
    // No force acts before the landing: it comes at q0 / (v_in / r).
    CHECK(landing->t == doctest::Approx(q0 * lever.r / v_in).epsilon(1e-9));
    CHECK(t_c == doctest::Approx(contact_time(k, me, zeta)).epsilon(1e-6));
    CHECK(e == doctest::Approx(restitution(k, me, zeta)).epsilon(1e-6));
    // The pad took what the lever lost: its damping while pressed, and the
    // k d^2 / 2 still in it where it let go (d = c v_out / k there), which it
    // loses as its surface comes back up (time constant c / k).
    const double lost = 0.5 * me * (v_in * v_in - v_out * v_out);
    const double pad = r.energy_final.pad_loss + r.energy_final.pad_elastic;
    if (zeta > 0) CHECK(pad == doctest::Approx(lost).epsilon(1e-6));
    if (zeta == 0) CHECK(std::abs(pad) < 1e-12 * 0.5 * me * v_in * v_in);
    CHECK(r.energy_final.pad_elastic <= 1e-5 * lost);  // relaxed by the end (0.02 s later)
    CHECK(std::abs(r.balance_residual) < 1e-9 * 0.5 * me * v_in * v_in);
    CHECK(r.energy_final.impact_loss == 0.0);  // a pad takes no impulse
  }
}

TEST_CASE("pad: the energy balance closes to 1e-9 of the flow on a damped, driven lever") {
  // Gravity on, a sine torque rocking the lever on its pad: it presses, lifts
  // off and lands again; every joule is in E_in, E_pad, PE, KE, E_pad_elastic.
  const Lever lever;
  Model m = lever.model(lever.pad(2e4, 0.2), true, 0.01, 0.0, 1.0, 1e-4);
  InputProfile torque;
  torque.kind = InputProfile::Kind::sine;
  torque.offset = 2.0;
  torque.amplitude = 3.5;
  torque.frequency = 3.0;
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints = {torque};
  finalize(m);
  const RunResult r = simulate(m, {});
  REQUIRE(r.completed);
  int landings = 0, releases = 0;
  for (const ContactEvent& e : r.events) {
    landings += e.kind == ContactEvent::Kind::landing;
    releases += e.kind == ContactEvent::Kind::release;
  }
  const double flow = std::abs(r.energy_final.electrical_in) + r.energy_final.pad_loss;
  MESSAGE(landings, " landings, ", releases, " releases; E_pad ", r.energy_final.pad_loss,
          " J; residual ", r.balance_residual, " J of ", flow, " J");
  CHECK(landings >= 2);
  CHECK(releases >= 2);
  CHECK(r.energy_final.pad_loss > 0);
  CHECK(std::abs(r.balance_residual) < 1e-9 * flow);
}

TEST_CASE("pad: friction through the pad holds inside the cone and slips at its edge, t* = 0.5 s") {
  // The pressed tip (contact_scenes.hpp) on a pad: the table raised by
  // fn / k, so the pad carries fn from the start and the statics are exact;
  // the push ratio(t) = 0.5 + t reaches mu f_n at 0.5 s.
  const PressedTip tip;
  Model m = tip.model(0.5, 1.0, 0.7, 1e-3);
  const double k = 1e6;
  m.elbows[0].pad = Pad{k, 2e3, 0.005};
  m.table[0].center.z() += tip.fn / k;
  m.contact.locate_tolerance = 1e-10;
  finalize(m);
  const RunResult r = simulate(m, {});
  REQUIRE(r.completed);
  const ContactEvent* slip = first_event(r, ContactEvent::Kind::slip);
  REQUIRE(slip != nullptr);
  MESSAGE("slip located at ", slip->t, " s (analytic 0.5 s)");
  CHECK(std::abs(slip->t - 0.5) < 2e-10);
  CHECK(first_event(r, ContactEvent::Kind::release) == nullptr);
  // Up to the slip the tip held still: the pad's force stayed fn.
  CHECK(r.energy_final.pad_loss > 0);  // it slid and pressed after 0.5 s
}

TEST_CASE("pad: prescribe_pad_rows turns a padded row into f_r = f_pad, the others untouched") {
  const Lever lever;
  const Model m = lever.model(lever.pad(1e5, 0.5), true, 0.0, 0.0, 0.1, 1e-4);
  Data data(m);
  ContactData& c = data.contact;
  c.active = {0};
  c.use_rows(1);
  c.A(0, 0) = 0.8;
  c.gamma[0] = 12.5;
  c.rhs[0] = -3.0;
  prescribe_pad_rows(m, c);
  CHECK(c.A(0, 0) == 0.8);
  CHECK(c.rhs[0] == doctest::Approx(0.8 * 12.5));
  CHECK(pad_force(m.elbows[0].pad, -1e-4, -0.01) ==
        doctest::Approx(1e5 * 1e-4 + m.elbows[0].pad.damping * 0.01));
  CHECK(pad_force(m.elbows[0].pad, 1e-6, 0.0) < 0);  // above the table it would pull
}

TEST_CASE("pad: pressed beyond its thickness the pad bottoms out: the run is invalid and says so") {
  // At 1e3 N/m the lever would sink m g l_c / (r k) = 12 mm into a 5 mm pad.
  const Lever lever;
  const Model m = lever.model(lever.pad(1e3, 0.5), true, 0.0, 0.0, 0.5, 1e-4);
  const RunResult r = simulate(m, {});
  INFO(r.failure);
  CHECK_FALSE(r.valid);
  CHECK(r.failure.find("elbow") != std::string::npos);
  CHECK(r.failure.find("the pad bottomed out") != std::string::npos);
  CHECK(r.failure.find("its pad's thickness 0.005 m") != std::string::npos);
  // The same lever on a 5 mm pad of 1e4 N/m sinks 1.2 mm: valid.
  CHECK(simulate(lever.model(lever.pad(1e4, 0.5), true, 0.0, 0.0, 0.5, 1e-4), {}).valid);
}
