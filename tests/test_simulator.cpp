// The simulation loop: determinism, no allocation per step, effects that are
// off cost nothing, divergence stops cleanly.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/data.hpp"
#include "engine/run/derivative.hpp"
#include "engine/run/integrator.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/allocations.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("same model twice -> identical recordings, bit for bit") {
  const Model m = driven_arm(IntegratorKind::rk4, 1e-3, 0.5, 0.5e-3);
  const RunResult a = simulate(m, {}), b = simulate(m, {});
  REQUIRE(a.trajectory.values.size() == b.trajectory.values.size());
  CHECK(std::memcmp(a.trajectory.values.data(), b.trajectory.values.data(),
                    a.trajectory.values.size() * sizeof(double)) == 0);
}

TEST_CASE("a simulation step allocates nothing (Eigen guard and global operator new)") {
  for (DynamicsMethod method : {DynamicsMethod::walker_orin, DynamicsMethod::crba, DynamicsMethod::aba}) {
    for (IntegratorKind kind : {IntegratorKind::euler, IntegratorKind::semi_implicit_euler,
                                IntegratorKind::rk4}) {
      Model m = random_chain(7, 3);
      m.options.dynamics = method;
      m.options.integrator = kind;
      Data data(m);
      prepare_integrator(m, data);
      reset_state(m, data);
      integrate_step(m, data);  // warm-up
      CAPTURE(std::string(to_string(method)));
      CAPTURE(std::string(to_string(kind)));
      const long before = allocation_count();
      Eigen::internal::set_is_malloc_allowed(false);
      for (int k = 0; k < 10; ++k) integrate_step(m, data);
      Eigen::internal::set_is_malloc_allowed(true);
      CHECK(allocation_count() == before);
      CHECK(data.x.allFinite());
    }
  }
}

TEST_CASE("effects that are off leave no state and no terms") {
  Model m = pendulum(IntegratorKind::rk4, 1e-3, 0.1);
  Data data(m);
  CHECK(data.x.size() == 2 * 2 + 3);  // no current state without the full motor model
  m.effects.gravity = false;
  finalize(m);
  const RunResult r = simulate(m, {});
  // Released from rest without gravity or input: nothing moves, PE is not computed.
  CHECK(r.energy_final.potential == 0.0);
  CHECK(r.energy_final.kinetic_links == 0.0);
  CHECK(m.active_effects().empty());
  const Model driven = driven_arm(IntegratorKind::rk4, 1e-3, 0.1, 1e-3);
  CHECK(Data(driven).x.size() == 3 * 2 + 3);
  CHECK(driven.active_effects() ==
        std::vector<std::string>{"gravity", "damping", "motor:full", "rotor_inertia"});
}

TEST_CASE("a diverging run stops with a message naming the time and keeps its samples") {
  // Explicit Euler on a stiff spring-free pendulum with a huge step and torque blows up.
  Model m = pendulum(IntegratorKind::euler, 0.05, 200.0);
  InputProfile torque;
  torque.kind = InputProfile::Kind::constant;
  torque.value = 1e4;
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints = {torque, torque};
  finalize(m);
  const RunResult r = simulate(m, {});
  CHECK_FALSE(r.completed);
  CHECK(r.failure.find("diverged at t = ") != std::string::npos);
  CHECK(r.trajectory.rows() > 1);
  for (double v : r.trajectory.values) CHECK(std::isfinite(v));
}
