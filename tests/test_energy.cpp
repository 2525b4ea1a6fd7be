// Energy accounting: the balance E_in - losses - change of stored energy
// closes up to integration error, and the error falls with the step.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("energy balance residual < 1e-6 E_in for a damped motor-driven run, falling with step") {
  // L/R = 0.25 ms: at these steps the electrics are resolved (at 1 ms they are
  // stiff and the residual is ~1e-5 E_in, see docs/model.md).
  double previous = 1e300;
  for (double step : {2e-4, 1e-4, 5e-5}) {
    CAPTURE(step);
    const RunResult r = simulate(driven_arm(IntegratorKind::rk4, step, 2.0, 0.5e-3), {});
    REQUIRE(r.completed);
    const double relative = std::abs(r.balance_residual) / r.energy_final.electrical_in;
    MESSAGE("step ", step, ": |residual| / E_in = ", relative, ", E_in = ",
            r.energy_final.electrical_in, " J");
    CHECK(r.energy_final.joule > 0);
    CHECK(r.energy_final.viscous > 0);
    CHECK(relative < previous);
    previous = relative;
  }
  CHECK(previous < 1e-6);
}

TEST_CASE("energy: every term is recorded and the stored energy matches 1/2 qd^T (M+Jm) qd + PE") {
  const RunResult r = simulate(driven_arm(IntegratorKind::rk4, 1e-3, 0.3, 0.5e-3), {});
  const Recording& t = r.trajectory;
  for (const char* name : {"E_in", "E_joule", "E_viscous", "KE_links", "KE_rotors", "PE",
                           "E_magnetic", "balance_residual"})
    CHECK(t.column(name) >= 0);
  CHECK(r.energy_final.kinetic_rotors > 0);
  CHECK(r.energy_final.magnetic > 0);
}

TEST_CASE("energy without motors: input is the work of the applied torques") {
  Model m = pendulum(IntegratorKind::rk4, 1e-3, 1.0);
  InputProfile torque;
  torque.kind = InputProfile::Kind::constant;
  torque.value = 2.0;
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints = {torque, InputProfile{}};
  finalize(m);
  const RunResult r = simulate(m, {});
  // The work of a constant torque on joint 0 is 2 N m times its angle change.
  const double dq0 = r.trajectory.at(r.trajectory.rows() - 1, 1) - r.trajectory.at(0, 1);
  CHECK(r.energy_final.electrical_in == doctest::Approx(2.0 * dq0).epsilon(1e-9));
  CHECK(std::abs(r.balance_residual) < 1e-9 * std::abs(r.energy_final.electrical_in) + 1e-12);
}
