// Cost of one full step(model, data) (engine/run/step.hpp: detect, active
// set, integrate, events, impacts, stabilise, checks) on scenes with an elbow
// on the table, next to the same scene with contact off, so the price of the
// contact bookkeeping per step can be read off.
//
//   resting: tests' ElbowArm (2 links, torque inputs tau1 = G1/2, tau2 = G2):
//            the elbow rests on the table in static equilibrium.
//   sliding: tests' sliding_arm (3 links, quasi-static servos on slow sines,
//            Baumgarte): the elbow slides along the table.
//   lying7:  a 7-link planar arm lying on two spheres (end of link 2 and of
//            link 6, links 3-6 level on the table), torques half its gravity
//            load plus small sines: with Coulomb friction (mu 0.6) the
//            contacts stick and slip in turn (2 normal rows, plus a tangent
//            row per sticking contact, on 7 joints; counters: the share of
//            steps with a sticking contact and located events per step), without
//            it the same 2 normal rows slide. The s = 7, p = 2 case.
//   far7:    the same arm and torques with its table 5 m below (contact on:
//            detection and checks run, nothing is ever near) and without a
//            table (contact off): what contact costs when no part is near.
//
// RK4, 1 ms steps. reset(model, data) once, then step() repeatedly; every
// 500 steps (0.5 s of simulated time) the state is reset so the elbow stays
// on the table (contact on) or near it (contact off). The resets are outside
// the timing (PauseTiming). Counter (contact on): resting = share of steps
// after which the elbow rests; 1 means the scene stayed in contact throughout
// (checked, not assumed).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/run/step.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;

namespace {

constexpr long kStepsPerReset = 500;

Model resting_arm(bool contact) {
  const testing::ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), 0.0);
  m.effects.contact = contact;
  // Contact off: no table either. With it the arm would sag into the box, and
  // a run that ignores a solid table is invalid (links inside it) and stops.
  if (!contact) m.table.clear();
  finalize(m);
  return m;
}

Model sliding(bool contact) {
  Model m = testing::sliding_arm(Stabilization::baumgarte, 1.0, 1e-3);
  m.effects.contact = contact;
  if (!contact) m.table.clear();  // as resting_arm
  finalize(m);
  return m;
}

Model lying7(bool friction, bool far = false, bool contact = true) {
  constexpr int n = 7;
  constexpr double L = 0.15, z = -0.05, r = 0.02;
  std::vector<testing::PlanarLinkSpec> links(n, {L, 0.5, L / 2, 0.001});
  Model m = testing::planar_arm(links);
  // Link 0 up, link 1 level, link 2 down to z, links 3-6 level at z.
  const double up = 0.6, j2z = L * std::sin(up);
  const double down = std::asin((z - j2z) / L);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
  q[0] = up;
  q[1] = -up;
  q[2] = down;
  q[3] = -down;
  m.elbows = {Elbow{"elbow", 2, Eigen::Vector3d(L, 0, 0), r}, Elbow{"tip", 6, Eigen::Vector3d(L, 0, 0), r}};
  TableBox box;
  box.size = Eigen::Vector3d(2.0, 1.0, 0.1);
  box.center = Eigen::Vector3d(0.5, 0, z - r - 0.05);
  m.table = {box};
  for (Link& link : m.links) link.collision.kind = LinkCollision::Kind::none;
  m.effects.contact = contact;
  m.effects.friction = friction;
  m.contact.friction.mu = 0.6;
  m.initial.q = q;
  if (far) m.table[0].center.z() -= 5.0;
  if (!contact) m.table.clear();
  std::vector<double> frequency(n);
  for (int j = 0; j < n; ++j) frequency[static_cast<std::size_t>(j)] = 1.0 + 0.1 * j;
  testing::gravity_share_with_sines(m, q, 0.5, 0.02, frequency);
  m.options = {1.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

void step_cost(benchmark::State& state, const Model& model) {
  Data data(model);
  reset(model, data);
  long steps = 0, resting = 0, sticking = 0, events = 0;
  for (auto _ : state) {
    step(model, data);
    if (data.failure) {
      state.SkipWithError("the run failed (see Data::failure)");
      break;
    }
    ++steps;
    if (!data.contact.active.empty()) ++resting;
    if (!data.contact.tangent_rows.empty()) ++sticking;
    events += static_cast<long>(data.log.events.size());
    if (data.step_count >= kStepsPerReset) {
      state.PauseTiming();
      reset(model, data);
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(data.x.data());
  }
  // Contact off: no counter (its cv over the repetitions would be 0/0, NaN in the JSON).
  if (model.effects.contact)
    state.counters["resting"] = static_cast<double>(resting) / static_cast<double>(std::max(steps, 1L));
  // Coulomb friction: share of steps with a sticking contact (tangent rows in M*).
  if (model.has_coulomb_friction())
    state.counters["sticking"] = static_cast<double>(sticking) / static_cast<double>(std::max(steps, 1L));
  // Located events (landings, releases, stick and slip) per step: each one
  // redoes the step a few times. Coulomb only: the other scenes locate none
  // (a counter that is 0 in every repetition has a NaN cv in the JSON).
  if (model.has_coulomb_friction())
    state.counters["events"] = static_cast<double>(events) / static_cast<double>(std::max(steps, 1L));
}

}  // namespace

BENCHMARK_CAPTURE(step_cost, resting_contact_off, resting_arm(false));
BENCHMARK_CAPTURE(step_cost, resting_contact_on, resting_arm(true));
BENCHMARK_CAPTURE(step_cost, sliding_contact_off, sliding(false));
BENCHMARK_CAPTURE(step_cost, sliding_contact_on, sliding(true));
BENCHMARK_CAPTURE(step_cost, lying7_frictionless, lying7(false));
BENCHMARK_CAPTURE(step_cost, lying7_coulomb_sticking, lying7(true));
BENCHMARK_CAPTURE(step_cost, far7_contact_on, lying7(false, true, true));
BENCHMARK_CAPTURE(step_cost, far7_contact_off, lying7(false, true, false));

BENCHMARK_MAIN();
