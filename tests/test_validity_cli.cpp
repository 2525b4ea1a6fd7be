// Runs that cannot be trusted say so (engine/run/validity.hpp), run as a user
// runs them: exit 3, a message naming the check, the time, the quantity and the
// likely cause; summary.json says valid: false; a comparison gives no verdict.
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/process.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
namespace t = elbowsim::testing;

namespace {

const std::string kExperiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("the experiment beyond its stable step (2.5 ms): invalid (energy balance), exit 3, no verdict" * doctest::test_suite("long")) {
  // Under continuous control rk4 on this arm is stable up to 2.07 ms on the
  // system linearised at initial.q (the warning and the failure say so);
  // poses later in the run lower that a little (at 2 ms one variant's energy
  // balance goes off from t = 2.98 s; at 1.9 ms both runs are valid). (The
  // shipped 1 kHz loop cannot run at a step longer than its period.)
  const fs::path dir = t::scratch("validity", "step_25");
  const t::Outcome r = t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                                       " --no-render --set simulation.step=2.5e-3"
                                       " --set 'controller={type: pd_feedforward, kp: 50, kd: 2}'");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  // The failure leads with its cause, the unstable step, then the symptom.
  CHECK(has(r.output, "error: the rk4 integrator is unstable at the step 0.0025 s"));
  CHECK(has(r.output, "likely as a result, the energy balance is off by"));
  CHECK(has(r.output, "simulation.step"));  // what to change
  // elbow_on runs to the end but its numbers cannot be used; elbow_off's
  // hand goes into the table on the way and stops there.
  for (const char* variant : {"elbow_on", "elbow_off"}) {
    const auto summary = nlohmann::json::parse(t::slurp(dir / variant / "summary.json"));
    CHECK(summary["valid"] == false);
  }
  CHECK(nlohmann::json::parse(t::slurp(dir / "elbow_on" / "summary.json"))["completed"] == true);
  const auto comparison = nlohmann::json::parse(t::slurp(dir / "comparison.json"));
  CHECK(comparison["valid"]["elbow_on"] == false);
  bool refused = false, compared = false;
  for (const auto& sentence : comparison["verdict"]) {
    refused = refused || has(sentence.get<std::string>(), "No verdict");
    compared = compared ||
               has(sentence.get<std::string>(), "electrical energy drawn from the supply") ||
               has(sentence.get<std::string>(), "net electrical energy");
  }
  CHECK(refused);
  CHECK_FALSE(compared);
}

TEST_CASE("an elbow planned to rest beyond the box's edge: exit 3 naming the elbow and the box") {
  const fs::path dir = t::scratch("validity", "beyond_edge");
  // The table moved 12 cm away: the elbow's resting point is past its edge.
  const t::Outcome r =
      t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                      " --no-render --no-report --set 'table.boxes[0].center=[0.77,0,-0.0998938]'");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(has(r.output, "elbow 'elbow' on table box 0"));
  CHECK(has(r.output, "beyond the box's top face"));
}

TEST_CASE("contact off with a table: the physics ignores it, a link that goes in makes the run invalid") {
  const fs::path dir = t::scratch("validity", "contact_off");
  const t::Outcome r = t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                                       " --no-render --no-report --set effects.contact=false --set effects.friction=false"
                                       " --set controller.type=pd --set variants.elbow_off=null");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(has(r.output, "inside table box 0"));
  CHECK(has(r.output, "effects.contact is false"));
}

TEST_CASE("the experiment under PD control: elbow_off's sagging arm lands on the table, no link inside it" * doctest::test_suite("long")) {
  // Without feed-forward the arm sags; with the elbow held up, the hand's link
  // lands on the table and rests there. Valid means the penetration check
  // (contact.penetration_tolerance, every step, every link) held throughout.
  const fs::path dir = t::scratch("validity", "pd");
  const t::Outcome r = t::run_elbowsim("run " + kExperiment + " --out " + dir.string() +
                                       " --no-render --no-report --set controller.type=pd");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto summary = nlohmann::json::parse(t::slurp(dir / "elbow_off" / "summary.json"));
  CHECK(summary["valid"] == true);
  CHECK(summary["contact"]["landings"].get<int>() >= 1);
  const std::string events = t::slurp(dir / "elbow_off" / "events.csv");
  CHECK(has(events, ",link3.end_b,landing,"));
  // Held at the table's top: the constraint's worst violation is far below the tolerance.
  CHECK(summary["contact"]["max_abs_C"].get<double>() < 1e-6);
}

TEST_CASE("a run whose steps shrink to nothing stops as stalled (exit 3, in seconds), not a hang" * doctest::test_suite("long")) {
  // Without gravity and with continuous control the resting elbow grazes the
  // table: located landings and lift-offs cut the steps to ~1e-9 s at about
  // t = 1.5 s. Before the stall check the run went on for hours.
  const fs::path dir = t::scratch("validity", "stalled");
  const t::Outcome r = t::run_elbowsim(
      "run " + kExperiment + " --out " + dir.string() +
      " --no-render --no-report --set effects.gravity=false --set 'variants={elbow_on: {}}'"
      " --set 'controller={type: pd_feedforward, kp: 50, kd: 2}' --set simulation.step=1e-3");
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(has(r.output, "the run stalled at t = "));
  CHECK(has(r.output, "contact.events: step"));
  // It names the point that grazes (the experiment's elbow is called "elbow").
  CHECK(has(r.output, "(at elbow, where the last event was located"));
  const auto summary = nlohmann::json::parse(t::slurp(dir / "elbow_on" / "summary.json"));
  CHECK(summary["completed"] == false);
  CHECK(summary["final_time"].get<double>() < 4.8);
}

TEST_CASE(
    "a 3-link, 3 kg arm on direct-drive motors (1:1 gear, 0.05 N m/A) warns that they saturate") {
  // Such a motor holds at most Km V_max / R = 0.05 x 24 / 1 = 1.2 N m
  // against the ~8 N m gravity puts on the shoulder: it sits at its voltage
  // limit the whole run. Valid (the numbers are right), but not a design
  // anyone meant: stderr, summary.json and the saturation shares say so.
  const fs::path dir = t::scratch("validity", "weak_motors");
  const fs::path scene = dir / "weak.yaml";
  t::write_file(scene, R"(name: weak_motors
robot:
  planar:
    links:
      - {length: 0.4, mass: 1.0}
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 1.0}
motors:
  default: {resistance: 1.0, inductance: 1.0e-3, torque_constant: 0.05, gear_ratio: 1, rotor_inertia: 0}
initial: {q: [0.3, -0.6, -0.4]}
task: {path: line, duration: 1.0, points: [start, [0.6, 0, 0.1]]}
controller: {type: pd_feedforward}
)");
  const t::Outcome r = t::run_elbowsim("run " + scene.string() + " --out " + (dir / "out").string() +
                                       " --no-render --no-report");
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(has(r.output, "warning: motor 0 is at its voltage limit (24 V) for 100 % of the run"));
  CHECK(has(r.output, "warning: the hand was"));
  const auto summary = nlohmann::json::parse(t::slurp(dir / "out" / "summary.json"));
  CHECK(summary["valid"] == true);
  REQUIRE(summary["saturation_share"].size() == 3);
  CHECK(summary["saturation_share"][0].get<double>() == 1.0);
  bool listed = false;
  for (const auto& w : summary["warnings"]) listed = listed || has(w.get<std::string>(), "saturation_share 5 %");
  CHECK(listed);
  // The threshold is the scenario's: at 100 % nothing is over it.
  const t::Outcome quiet = t::run_elbowsim("run " + scene.string() + " --out " + (dir / "quiet").string() +
                                           " --no-render --no-report --set warnings.saturation_share=1"
                                           " --set warnings.hand_error=10");
  CHECK(quiet.exit_code == 0);
  CHECK_FALSE(has(quiet.output, "voltage limit"));
  CHECK_FALSE(has(quiet.output, "warning: the hand"));
}
