// What a scenario leaves to defaults (issue 31): simulation.integrator auto,
// the built-in motor and its rating, and what `validate` and `run` say about
// them.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/run/simulator.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"

using namespace elbowsim;
namespace fs = std::filesystem;
namespace t = elbowsim::testing;

namespace {

const std::string kScenarios = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/";

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

RunResult run(const Scenario& s) {
  return simulate(s.model, s.experiment, RunOptions{s.output.every, {}});
}

// A 3-link, 3 kg arm with a task and no motors section: the built-in motors.
const char* kNewArm = R"(name: new_arm
robot:
  planar:
    links:
      - {length: 0.4, mass: 1.0}
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 1.0}
initial: {q: [0.3, -0.6, -0.4]}
task: {path: line, duration: 1.0, points: [start, [0.6, 0, 0.1]]}
controller: {type: pd_feedforward}
)";

}  // namespace

TEST_CASE(
    "defaults: a stiff motor (L = 1 uH, R = 1 ohm) without an integrator runs valid, near a 1e-5 s "
    "rk4 reference") {
  // scenarios/hard/stiff_electrics.yaml with its integrator (and tolerances) taken out.
  const Scenario s =
      load_scenario(kScenarios + "hard/stiff_electrics.yaml",
                    {"simulation.integrator=null", "simulation.rtol=null", "simulation.atol=null"});
  MESSAGE(s.model.options.integrator_reason);
  CHECK(s.model.options.integrator == IntegratorKind::ros34pw2);
  CHECK(has(s.model.options.integrator_reason, "L/R = 1e-06 s is under a tenth of the step"));
  const RunResult r = run(s);
  INFO(r.failure);
  REQUIRE(r.valid);
  // The reference: the fixed-step rk4 at 1e-5 s (stable: the limit there is
  // 0.93 ms; h R / L = 10), rows every 10 ms like the run's.
  const Scenario fine =
      load_scenario(kScenarios + "hard/stiff_electrics.yaml",
                    {"simulation.integrator=rk4", "simulation.rtol=null", "simulation.atol=null",
                     "simulation.step=1e-5", "output.every=1000"});
  const RunResult ref = run(fine);
  REQUIRE(ref.valid);
  REQUIRE(ref.trajectory.rows() == r.trajectory.rows());
  double worst = 0;
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row) {
    const int t = r.trajectory.layout.time();
    REQUIRE(std::abs(r.trajectory.at(row, t) - ref.trajectory.at(row, t)) < 1e-9);
    for (int j = 0; j < s.model.dof; ++j) {
      const std::string q = 'q' + std::to_string(j);
      worst = std::max(worst, std::abs(r.trajectory.at(row, r.trajectory.column(q)) -
                                       ref.trajectory.at(row, ref.trajectory.column(q))));
    }
  }
  MESSAGE("auto (", r.steps, " ros34pw2 steps) against rk4 at 1e-5 s: largest |dq| ", worst,
          " rad over ", r.trajectory.rows(), " rows");
  // The issue's bound; ros34pw2 at rtol 1e-6 stays far inside it.
  CHECK(worst < 1e-3);
}

TEST_CASE("defaults: auto keeps rk4 on the shipped experiment, byte for byte, and says so" *
          doctest::test_suite("long")) {
  const fs::path dir = t::scratch("defaults", "experiment_auto");
  const std::string experiment = kScenarios + "elbow_experiment.yaml";
  const std::string quiet = " --no-render --no-report --set simulation.duration=1";
  const t::Outcome pinned =
      t::run_elbowsim("run " + experiment + " --out " + (dir / "rk4").string() + quiet);
  const t::Outcome chosen =
      t::run_elbowsim("run " + experiment + " --out " + (dir / "auto").string() + quiet +
                      " --set simulation.integrator=auto");
  INFO(chosen.output);
  REQUIRE(pinned.exit_code == 0);
  REQUIRE(chosen.exit_code == 0);
  CHECK(has(chosen.output, "integrator auto chose rk4: rk4 is stable at 1.5 times the step"));
  CHECK_FALSE(has(pinned.output, "integrator auto"));
  for (const char* variant : {"elbow_on", "elbow_off"}) {
    CAPTURE(variant);
    for (const char* file : {"trajectory.csv", "events.csv"})
      CHECK(t::slurp(dir / "auto" / variant / file) == t::slurp(dir / "rk4" / variant / file));
    const auto settings =
        nlohmann::json::parse(t::slurp(dir / "auto" / variant / "summary.json"))["settings"];
    CHECK(settings["integrator"] == "rk4");
    CHECK(settings["integrator_choice"] == "auto");
    CHECK(has(settings["integrator_reason"].get<std::string>(), "resolves the motor electrics"));
    const auto named =
        nlohmann::json::parse(t::slurp(dir / "rk4" / variant / "summary.json"))["settings"];
    CHECK(named["integrator_choice"] == "scenario");
    CHECK_FALSE(named.contains("integrator_reason"));
  }
}

TEST_CASE(
    "defaults: validate notes the integrator auto chose, the built-in motors and missing ratings") {
  const fs::path dir = t::scratch("defaults", "validate");
  write(dir / "new_arm.yaml", kNewArm);
  const t::Outcome builtin = t::run_elbowsim("validate " + (dir / "new_arm.yaml").string());
  INFO(builtin.output);
  CHECK(builtin.exit_code == 0);
  CHECK(has(builtin.output, "integrator auto chose rk4: "));
  CHECK(has(builtin.output, "joints 0, 1 and 2 run the built-in motor"));
  CHECK(has(builtin.output, "rated 1 A"));
  CHECK_FALSE(has(builtin.output, "no rated_current"));  // the built-in motor is rated
  // Its own motors without a rating (and the motor of joint 1 rated).
  const t::Outcome own = t::run_elbowsim(
      "validate " + (dir / "new_arm.yaml").string() +
      " --set 'motors={default: {torque_constant: 0.05}, joints: [{}, {rated_current: 2}, {}]}'");
  INFO(own.output);
  CHECK(has(own.output,
            "motors 0 and 2 have no rated_current: a run cannot warn when they would overheat"));
  CHECK_FALSE(has(own.output, "built-in motor"));
  // A scene that names its integrator: no auto line.
  CHECK_FALSE(has(t::run_elbowsim("validate " + kScenarios + "elbow_experiment.yaml").output,
                  "integrator auto"));
}

TEST_CASE("defaults: a new 3 kg arm on the built-in motors warns they would overheat") {
  // The built-in motor (20 W class, 100:1, rated 1 A) holds the arm easily
  // (Km = 3 N m/A), but the ~8 N m gravity puts on the shoulder takes ~3 A:
  // valid, and the run says the motor could not sustain it.
  const fs::path dir = t::scratch("defaults", "new_arm");
  write(dir / "new_arm.yaml", kNewArm);
  const t::Outcome r = t::run_elbowsim("run " + (dir / "new_arm.yaml").string() + " --out " +
                                       (dir / "out").string() + " --no-render --no-report");
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(has(r.output, "warning: motor 0 carries "));
  CHECK(has(r.output, "times its rated continuous current 1 A"));
  CHECK(has(r.output, "the built-in motor"));
  const auto summary = nlohmann::json::parse(t::slurp(dir / "out" / "summary.json"));
  CHECK(summary["valid"] == true);
}

TEST_CASE("defaults: dopri5 on the elbow at rest (motors' L/R 0.25 ms) says the equations are stiff; ros34pw2 says nothing") {
  // At rtol 1e-3 dopri5 once rejected one step per accepted step here without a word.
  const fs::path dir = t::scratch("defaults", "stiff_dopri5");
  const std::string scene = kScenarios + "elbow_rest.yaml";
  const std::string quiet = " --no-render --no-report --set simulation.rtol=1e-3";
  const t::Outcome explicit_run = t::run_elbowsim("run " + scene + " --out " + (dir / "dopri5").string() +
                                                  quiet + " --set simulation.integrator=dopri5");
  INFO(explicit_run.output);
  REQUIRE(explicit_run.exit_code == 0);
  CHECK(has(explicit_run.output, "the equations are stiff for dopri5 from t = "));
  CHECK(has(explicit_run.output, "simulation.integrator: ros34pw2"));
  const auto summary = nlohmann::json::parse(t::slurp(dir / "dopri5" / "summary.json"));
  int said = 0;
  for (const auto& w : summary["warnings"]) said += has(w.get<std::string>(), "stiff for dopri5");
  CHECK(said == 1);
  const t::Outcome implicit_run = t::run_elbowsim("run " + scene + " --out " + (dir / "ros").string() +
                                                  quiet + " --set simulation.integrator=ros34pw2");
  REQUIRE(implicit_run.exit_code == 0);
  CHECK_FALSE(has(implicit_run.output, "stiff for dopri5"));
}
