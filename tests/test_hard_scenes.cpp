// scenarios/hard/: scenes that stress the numerics, each against a reference
// computed independently of the run it checks, with the bound stated.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/run/simulator.hpp"

using namespace elbowsim;

namespace {

const std::string kHard = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/hard/";

double last(const RunResult& r, const std::string& column) {
  return r.trajectory.at(r.trajectory.rows() - 1, r.trajectory.column(column));
}

RunResult run(const Scenario& s) { return simulate(s.model, s.experiment, RunOptions{s.output.every, {}}); }

}  // namespace

TEST_CASE("hard: stiff electrics (L/R = 1 us at 1 ms rows): ros34pw2 matches an explicit reference") {
  const Scenario shipped = load_scenario(kHard + "stiff_electrics.yaml");
  const RunResult r = run(shipped);
  INFO(r.failure);
  REQUIRE(r.valid);
  // The reference: explicit dopri5 at rtol 1e-9 (its steps held near its
  // stability limit, ~3 us), an independent method on the same equations.
  const Scenario explicit_reference = load_scenario(
      kHard + "stiff_electrics.yaml",
      {"simulation.integrator=dopri5", "simulation.rtol=1e-9", "simulation.atol=1e-12"});
  const RunResult ref = run(explicit_reference);
  REQUIRE(ref.valid);
  double angle = 0, current = 0, peak = 0;
  for (int j = 0; j < 4; ++j) {
    const std::string k = std::to_string(j);
    angle = std::max(angle, std::abs(last(r, "q" + k) - last(ref, "q" + k)));
    current = std::max(current, std::abs(last(r, "i" + k) - last(ref, "i" + k)));
    peak = std::max(peak, r.metrics.find("current_peak")->values[static_cast<std::size_t>(j)]);
  }
  MESSAGE("ros34pw2: ", r.steps, " steps, ", r.work.evaluations, " evaluations; dopri5 reference ",
          ref.steps, " steps; final |dq| ", angle, " rad, |di| ", current, " A; peak current ", peak, " A");
  // rtol 1e-6 on angles of order 1 rad and currents of order 1 A: the final
  // error within 10 x tol (global error accumulates over the steps).
  CHECK(angle < 1e-5);
  CHECK(current < 1e-5);
  CHECK(peak < 24.0);  // below the stall current v_max / R: nothing blew up
  CHECK(r.steps < ref.steps / 100);  // and the implicit method is the cheap one here
}

TEST_CASE("hard: stiff electrics with the fixed-step rk4: stopped early, and the message names the fix") {
  const Scenario fixed = load_scenario(
      kHard + "stiff_electrics.yaml",
      {"simulation.integrator=rk4", "simulation.rtol=null", "simulation.atol=null"});
  const RunResult r = run(fixed);
  CHECK_FALSE(r.valid);
  CHECK_FALSE(r.completed);
  CHECK(r.final_time < 0.1);
  CHECK(r.failure.find("diverged") != std::string::npos);
  CHECK(r.failure.find("use simulation.integrator: ros34pw2") != std::string::npos);
  bool warned = false;
  for (const std::string& w : r.warnings) warned = warned || w.find("L/R = 1e-06 s") != std::string::npos;
  CHECK(warned);
}
