// What a run says about itself, from the command line: every part of the arm that rests on
// the table is reported (summary.json contact.bodies, a warning, the reports' headline and
// verdict), a number below its integration floor is never shown as a result, and validate
// refuses at load what the run would stop at its first step.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/process.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using elbowsim::testing::run_elbowsim;
using elbowsim::testing::slurp;

namespace {

const std::string kExperiment = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";

nlohmann::json summary_of(const fs::path& folder) {
  return nlohmann::json::parse(slurp(folder / "summary.json"));
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The experiment's controller before issue 34: the same gains for both arms, a 1 ms step.
const std::string kSharedGains =
    "--set controller.tuning=null --set simulation.step=1e-3 --set output.every=10";

}  // namespace

TEST_CASE("cli: the PD experiment's held-up arm rests its last link: reported, warned, headlined") {
  // With plain PD the elbow-off arm sags until its last link lies on the table for most of
  // the run; nothing in the scenario declares it. Before contact.bodies the run said only
  // "no elbow rested".
  const fs::path dir = elbowsim::testing::scratch("cli", "pd_bodies");
  // The gains both arms once shared (Kp 50, Kd 2, no integral) at 1 ms: tuned, PID holds the arm up.
  const auto out = run_elbowsim("run " + kExperiment + " --set controller.type=pd " + kSharedGains +
                                " --no-render " +
                                "--no-check-step --out " + dir.string() +
                                " --expect 'elbow_off.contact.bodies.link3.rest_fraction > 0.5'");
  INFO(out.output);
  REQUIRE(out.exit_code == 0);  // valid runs, and the expectation holds
  const auto off = summary_of(dir / "elbow_off");
  const auto& link3 = off["contact"]["bodies"]["link3"];
  CHECK(link3["kind"] == "link");
  CHECK(link3["planned"] == "none");
  CHECK(link3["rest_fraction"].get<double>() > 0.5);
  CHECK(link3["force_mean"].get<double>() > 1.0);  // [N]
  CHECK(link3["force_peak"].get<double>() >= link3["force_mean"].get<double>());
  CHECK(link3["sticks"].get<int>() > 0);
  CHECK(link3["friction_work"].get<double>() > 0);
  // The bodies' friction losses add up to the run's (both integrated with the motion).
  double sum = 0;
  for (const auto& [name, body] : off["contact"]["bodies"].items()) sum += body["friction_work"].get<double>();
  CHECK(sum == doctest::Approx(off["energy_final"]["friction"].get<double>()).epsilon(1e-12));
  CHECK(off["contact"]["bodies"]["elbow"]["planned"] == "above");
  CHECK(off["contact"]["bodies"]["elbow"]["rest_fraction"] == 0.0);
  bool warned = false;
  for (const auto& w : off["warnings"]) warned |= has(w.get<std::string>(), "link3 (link 3's own solid, not a declared elbow) rested on the table");
  CHECK(warned);
  CHECK(has(out.output, "warning: link3 (link 3's own solid"));
  const std::string run_report = slurp(dir / "elbow_off" / "report.html");
  CHECK(has(run_report, "The table also carried link3 (a link, not a declared elbow)"));
  CHECK(has(run_report, "other parts resting on the table"));
  const std::string compare = slurp(dir / "compare" / "report.html");
  CHECK(has(compare, "elbow_off: the table also carried link3"));
  const auto comparison = nlohmann::json::parse(slurp(dir / "comparison.json"));
  bool said = false;
  for (const auto& s : comparison["verdict"]) said |= has(s.get<std::string>(), "elbow_off: the table also carried link3");
  CHECK(said);
}

TEST_CASE("cli: the nominal experiment: no other part rests in either run, and the comparison says same") {
  const fs::path dir = elbowsim::testing::scratch("cli", "nominal_bodies");
  const auto out = run_elbowsim("run " + kExperiment + " --no-render --no-check-step --out " + dir.string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  const std::string compare = slurp(dir / "compare" / "report.html");
  const std::size_t row = compare.find("<tr data-metric=\"contact.bodies\">");
  REQUIRE(row != std::string::npos);
  const std::string cells = compare.substr(row, compare.find("</tr>", row) - row);
  INFO(cells);
  // elbow_on, elbow_off, then elbow_off vs elbow_on
  CHECK(has(cells, "<td class=\"value\">none</td><td class=\"value\">none</td>"));
  CHECK(has(cells, "<td class=\"num same\">same</td>"));
}

TEST_CASE("cli: a continuous-control scene's hand error is below the integration floor, never a result") {
  // The controller knows the plant and sees its true state: what is left of the hand error
  // is the integrator's (tens of nm that move by a quarter at half the step).
  const fs::path dir = elbowsim::testing::scratch("cli", "floor");
  const fs::path file = dir / "continuous.yaml";
  std::ofstream(file) << R"(name: continuous
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.25, mass: 0.6}
motors:
  default: {resistance: 2.0, inductance: 0.5e-3, torque_constant: 0.03, gear_ratio: 100}
initial: {q: [0.3, 0.9]}
task: {path: line, points: [start, [0.3, 0, 0.25]], duration: 1.0, start_delay: 0.1}
controller: {type: pd_feedforward}
)";
  const auto out = run_elbowsim("run " + file.string() + " --no-render --out " + (dir / "run").string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  CHECK(has(out.output, "hand_error_rms"));
  CHECK(has(out.output, "is below the integration floor"));
  const auto s = summary_of(dir / "run");
  const auto& rms = s["step_check"]["metrics"]["hand_error_rms"];
  CHECK(rms["below_floor"] == true);
  CHECK(rms["value"].get<double>() < 10 * rms["floor"].get<double>());
  CHECK(s["step_check"]["metrics"]["energy_in"]["below_floor"] == false);
  const std::string report = slurp(dir / "run" / "report.html");
  CHECK(has(report, "the hand error is below the integration floor"));
  CHECK_FALSE(has(report, "the hand kept to its path within"));
  CHECK(has(report, "hand_path_error: the hand error of"));  // the magnified figure left out
  CHECK_FALSE(fs::exists(dir / "run" / "plots" / "hand_path_error.png"));
}

TEST_CASE("cli: validate refuses an elbow whose link starts inside the table, as run would") {
  // The elbow 10 cm along link 1 instead of 25 cm: the task's first pose puts it on the
  // table, and link 1 (pivoting about it) several cm into the table box.
  const auto v = run_elbowsim("validate " + kExperiment + " --set 'elbows[0].at=0.1'");
  INFO(v.output);
  CHECK(v.exit_code == 2);
  CHECK(has(v.output, "inside table box 0 at the task's first pose"));
  CHECK(has(v.output, "robot.planar.links[1]"));
  const fs::path dir = elbowsim::testing::scratch("cli", "inside");
  const auto r = run_elbowsim("run " + kExperiment + " --set 'elbows[0].at=0.1' --no-render --out " + dir.string());
  CHECK(r.exit_code == 2);  // refused at load, the same message
  CHECK(has(r.output, "inside table box 0 at the task's first pose"));
}

TEST_CASE("cli: validate refuses a task that leaves too few joints for the hand, naming the fix") {
  // Three planar links with the elbow at the end of link 1, sticking (Coulomb friction): its
  // x and z take two of the three joints, and the hand needs two.
  const fs::path dir = elbowsim::testing::scratch("cli", "rows");
  const fs::path file = dir / "three.yaml";
  std::ofstream(file) << R"(name: three
robot:
  planar:
    links:
      - {length: 0.25, mass: 1.0}
      - {length: 0.25, mass: 0.8}
      - {length: 0.2, mass: 0.4}
motors:
  default: {resistance: 2.0, inductance: 0.5e-3, torque_constant: 0.03, gear_ratio: 100}
initial: {q: [0.6, -1.3, 0.9]}
effects: {contact: true, friction: true}
contact: {friction: 0.6}
elbows: [{name: elbow, link: 1, at: 0.25, radius: 0.03}]
table: {boxes: [{center: [0.5, 0, -0.0999], size: [0.8, 0.6, 0.1]}]}
task: {path: line, points: [start, [0.05, 0, 0.02]], origin: start, elbows: [elbow]}
controller: {type: pd_feedforward}
)";
  const auto v = run_elbowsim("validate " + file.string());
  INFO(v.output);
  CHECK(v.exit_code == 2);
  CHECK(has(v.output, "task.elbows"));
  CHECK(has(v.output, "elbow 'elbow' kept on the table and sticking"));
  CHECK(has(v.output, "leave 1 for the hand"));
  CHECK(has(v.output, "effects.friction: false"));
  // Sliding (no friction), its height alone: the task fits, and runs.
  const auto sliding = run_elbowsim("validate " + file.string() + " --set effects.friction=false");
  INFO(sliding.output);
  CHECK(sliding.exit_code == 0);
  const auto ran = run_elbowsim("run " + file.string() + " --set effects.friction=false --no-render " +
                                "--no-report --no-check-step --out " + (dir / "sliding").string());
  INFO(ran.output);
  CHECK(ran.exit_code == 0);
}

TEST_CASE("cli: validate plans and resets as the run does: Painleve's paradox at t = 0 is refused") {
  // scenarios/hard/painleve.yaml stops at t = 0 (exit 3); validate said it was fine.
  const auto v = run_elbowsim("validate " + std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/hard/painleve.yaml");
  INFO(v.output);
  CHECK(v.exit_code == 2);
  CHECK(has(v.output, "the run would stop before its first step: Painleve paradox at t = 0 s"));
  const auto ok = run_elbowsim("validate " + kExperiment);
  CHECK(ok.exit_code == 0);
  CHECK(has(ok.output, "start      elbow_on: planned and reset at t = 0 as the run does: passes"));
  CHECK(has(ok.output, "start      elbow_off: planned and reset at t = 0 as the run does: passes"));
}

TEST_CASE("cli: a Monte Carlo study names the draws in which a link rested on the table" * doctest::test_suite("long")) {
  // The PD experiment again, 3 draws: in each, both arms' last links touch the table (the
  // held-up arm's for almost the whole run).
  const fs::path dir = elbowsim::testing::scratch("cli", "mc_bodies");
  const auto out = run_elbowsim("montecarlo " + kExperiment +
                                " --case task=loops,speed=nominal,elbow=mid,motor=sized --variants elbow_on,elbow_off"
                                " --set controller.type=pd " +
                                kSharedGains + " --samples 3 --no-report --out " + dir.string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  CHECK(has(out.output, "elbow_off: in 3 of 3 draws a part the scene does not plan to rest lay on the table"));
  const auto doc = nlohmann::json::parse(slurp(dir / "loops-nominal-mid-sized" / "montecarlo.json"));
  const auto& off = doc["unplanned_contact"]["elbow_off"];
  CHECK(off["draws"].size() == 3);
  CHECK(off["body"] == "link3");
  CHECK(off["largest_share"].get<double>() > 0.5);
  const std::string samples = slurp(dir / "loops-nominal-mid-sized" / "samples.csv");
  CHECK(has(samples, "unplanned_contact_share,unplanned_contact_body,slips,failure"));
  CHECK(has(samples, ",link3,"));
}

TEST_CASE("cli: a Monte Carlo study counts each run's slips and says which arm's contacts slipped") {
  // mu 0.1 instead of 0.6: the table cannot hold the resting elbow, which sticks
  // and slips over and over (~215 slip events in 1.6 s); the held-up arm touches nothing.
  const fs::path dir = elbowsim::testing::scratch("cli", "mc_slips");
  const auto out = run_elbowsim("montecarlo " + kExperiment +
                                " --case task=loops,speed=nominal,elbow=mid,motor=sized --variants elbow_on,elbow_off"
                                " --set contact.friction.mu=0.1"
                                " --set task.duration=1.5 --set task.start_delay=0.05 --samples 3"
                                " --no-report --out " + dir.string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  CHECK(has(out.output, "elbow_on: its contacts slipped in 3 of 3 draws"));
  CHECK_FALSE(has(out.output, "elbow_off: its contacts slipped"));
  const auto doc = nlohmann::json::parse(slurp(dir / "loops-nominal-mid-sized" / "montecarlo.json"));
  CHECK(doc["slips"]["elbow_on"]["draws_with_slips"] == 3);
  CHECK(doc["slips"]["elbow_on"]["median"].get<long>() > 10);
  CHECK(doc["slips"]["elbow_off"]["draws_with_slips"] == 0);
  const std::string samples = slurp(dir / "loops-nominal-mid-sized" / "samples.csv");
  CHECK(has(samples, "unplanned_contact_body,slips,failure"));
  // Over the study's cases: each case's counts, a verdict line, and study.csv's columns.
  const auto study = nlohmann::json::parse(slurp(dir / "study.json"));
  REQUIRE(study["cases"].size() == 1);
  CHECK(study["cases"][0]["slips"] == doc["slips"]);
  bool said = false;
  for (const auto& line : study["verdict"]) {
    const std::string text = line.get<std::string>();
    said = said || has(text, "elbow_on: its contacts slipped in 1 of 1 cases (3 draws in all, at most " +
                                 std::to_string(doc["slips"]["elbow_on"]["max"].get<long>()) + " slip events a run");
    CHECK_FALSE(has(text, "elbow_off: its contacts slipped"));
  }
  CHECK(said);
  const std::string csv = slurp(dir / "study.csv");
  CHECK(has(csv, ",slips draws a,slips draws b,slips median a,slips median b\n"));
  CHECK(has(csv, ",3,0," + std::to_string(doc["slips"]["elbow_on"]["median"].get<long>()) + ",0\n"));
}
