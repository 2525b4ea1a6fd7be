// The Monte Carlo study: the uncertainty: section (expansion, nominal values,
// errors), the draws (seeded, independent of the number taken), and
// `elbowsim montecarlo` as a process (same seed -> same bytes whatever
// --jobs; identical variants -> no significant difference).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/study/draws.hpp"
#include "app/study/paired_verdict.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"
#include "test_scenario_helpers.hpp"

namespace fs = std::filesystem;
using elbowsim::UncertainParameter;
using namespace scenario_test;

namespace {

// A two-link arm holding its hand still under PD + feed-forward, 1 s.
const std::string kHolding = two_link_with(R"(
task: {path: hold}
controller: {type: pd_feedforward}
uncertainty:
  seed: 7
  parameters:
    robot.planar.links[*].mass: {uniform: 0.1}
    robot.planar.links[1].com: {normal: 0.05}
    hand_load.mass: {range: [0, 0.2]}
)");

}  // namespace

TEST_CASE("uncertainty: [*] expands to every item, with each nominal value; range needs none") {
  const Scenario s = load(kHolding);
  const auto& p = s.uncertainty.parameters;
  REQUIRE(p.size() == 4);
  CHECK(s.uncertainty.seed == 7);
  CHECK(p[0].key == "robot.planar.links[0].mass");
  CHECK(p[0].given == "robot.planar.links[*].mass");
  CHECK(p[0].nominal == 1.0);
  CHECK(p[1].key == "robot.planar.links[1].mass");
  CHECK(p[1].nominal == 0.5);
  CHECK(p[2].law == UncertainParameter::Law::normal);
  CHECK(p[2].nominal == 0.08);
  CHECK(p[3].law == UncertainParameter::Law::range);
  CHECK(std::isnan(p[3].nominal));
  CHECK(s.model.links[0].mass == 1.0);  // a single run is the nominal plant
}

TEST_CASE("uncertainty errors: keys, laws, missing nominal values") {
  auto with = [](const char* parameters) {
    return two_link_with((std::string("uncertainty:\n  parameters:\n") + parameters).c_str());
  };
  CHECK_ERROR(with("    robot.planar.links[0].mas: {uniform: 0.1}\n"), "x.yaml:11:5:",
              "uncertainty.parameters.robot.planar.links[0].mas", "not given in the scenario");
  CHECK_ERROR(with("    robot.planar.links[4].mass: {uniform: 0.1}\n"), "x.yaml:11:5:",
              "uncertainty.parameters.robot.planar.links[4].mass", "out of range");
  CHECK_ERROR(with("    robot.planar.links[1].mass: {uniform: 1.5}\n"), "x.yaml:11:",
              "uncertainty.parameters.robot.planar.links[1].mass.uniform", "spread of 1 or more");
  CHECK_ERROR(with("    robot.planar.links[1].mass: {gauss: 0.1}\n"), "x.yaml:11:",
              "uncertainty.parameters.robot.planar.links[1].mass.gauss", "unknown key");
  CHECK_ERROR(with("    robot.planar.links[1].mass: {uniform: 0.1, normal: 0.1}\n"), "x.yaml:11:",
              "uncertainty.parameters.robot.planar.links[1].mass", "give one law");
  CHECK_ERROR(with("    hand_load.mass: {range: [0.2, 0]}\n"), "x.yaml:11:",
              "uncertainty.parameters.hand_load.mass.range", "low <= high");
  CHECK_ERROR(with("    simulation.step: {uniform: 0.1}\n"), "x.yaml:11:5:",
              "uncertainty.parameters.simulation.step", "only plant parameters");
  CHECK_ERROR(with("    robot.planar.links[*].mass: {uniform: 0.1}\n    robot.planar.links[0].mass: {uniform: 0.2}\n"),
              "x.yaml:12:5:",
              "uncertainty.parameters.robot.planar.links[0].mass", "drawn twice");
}

TEST_CASE("draws: seeded, within their laws, and draw i the same however many are taken") {
  const Scenario s = load(kHolding);
  const auto d3 = elbowsim::study::draw_parameters(s.uncertainty, 7, 3);
  CHECK(d3.u == elbowsim::study::draw_parameters(s.uncertainty, 7, 3).u);
  CHECK(d3.u != elbowsim::study::draw_parameters(s.uncertainty, 8, 3).u);
  CHECK(d3.u != elbowsim::study::draw_parameters(s.uncertainty, 7, 4).u);
  for (long i = 0; i < 500; ++i) {
    const auto d = elbowsim::study::draw_parameters(s.uncertainty, 7, i);
    CHECK(std::abs(d.u[0]) <= 0.1);
    CHECK(std::abs(d.u[2]) <= 3 * 0.05);
    CHECK(d.u[3] >= 0);
    CHECK(d.u[3] <= 0.2);
  }
  const auto overrides = elbowsim::study::draw_overrides(s.uncertainty, d3);
  REQUIRE(overrides.size() == 4);
  CHECK(overrides[0].starts_with("robot.planar.links[0].mass="));
  const double drawn = std::stod(overrides[0].substr(overrides[0].find('=') + 1));
  CHECK(drawn == 1.0 * (1 + d3.u[0]));  // 17 digits: exact
}

TEST_CASE("cli: montecarlo: same seed -> same bytes (jobs 1 or 2); identical variants -> no difference") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo");
  const fs::path file = dir / "holding.yaml";
  std::ofstream(file) << kHolding << "variants: {a: {}, b: {}}\n";
  auto run = [&](const std::string& out, const std::string& options) {
    return elbowsim::testing::run_elbowsim("montecarlo " + file.string() + " --samples 6 --out " +
                                           (dir / out).string() + " " + options);
  };
  const auto first = run("one", "--jobs 1 --no-report");
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  REQUIRE(run("two", "--jobs 2 --no-report").exit_code == 0);
  REQUIRE(run("seed", "--jobs 2 --seed 8").exit_code == 0);  // with its report
  const std::string html = elbowsim::testing::slurp(dir / "seed" / "report.html");
  CHECK(html.find("<h1>Monte Carlo study: two_link</h1>") != std::string::npos);
  CHECK(html.find("id=\"verdict\"") != std::string::npos);
  CHECK(html.find("robot.planar.links[1].com") != std::string::npos);  // the parameters table
  for (const char* png : {"ecdf_hand_error.png", "ecdf_energy.png", "energy_vs_hand_error.png"})
    CHECK(fs::file_size(dir / "seed" / "plots" / png) > 1000);
  CHECK_FALSE(fs::exists(dir / "one" / "report.html"));
  for (const char* f : {"samples.csv", "montecarlo.json"})
    CHECK(elbowsim::testing::slurp(dir / "one" / f) == elbowsim::testing::slurp(dir / "two" / f));
  CHECK(elbowsim::testing::slurp(dir / "one" / "samples.csv") !=
        elbowsim::testing::slurp(dir / "seed" / "samples.csv"));

  const auto doc = nlohmann::json::parse(elbowsim::testing::slurp(dir / "one" / "montecarlo.json"));
  CHECK(doc["seed"] == 7);  // the scenario's
  CHECK(doc["samples"] == 6);
  CHECK(doc["invalid"].empty());
  const auto& energy = doc["pairs"][0]["energy_in"];
  CHECK(energy["ci95"][0].get<double>() <= 1.0);
  CHECK(energy["ci95"][1].get<double>() >= 1.0);
  const std::string verdict = doc["verdict"][0];
  CHECK(verdict.starts_with("electrical energy: no significant difference between a and b"));
  CHECK(first.output.find("no significant difference") != std::string::npos);

  // The draws vary the plant: link 0's mass differs between draws.
  CHECK(doc["metrics"]["a"]["energy_in"]["valid"] == 6);
  const auto& e = doc["draws"]["a"]["energy_in"];
  CHECK(e[0] != e[1]);
}

TEST_CASE("cli: montecarlo refuses a scenario without uncertainty, and bad numbers") {
  const std::string pendulum = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/two_link_pendulum.yaml";
  const auto none = elbowsim::testing::run_elbowsim("montecarlo " + pendulum + " --samples 3");
  CHECK(none.exit_code == 2);
  CHECK(none.output.find("has no uncertainty: parameters") != std::string::npos);
  const auto bad = elbowsim::testing::run_elbowsim("montecarlo " + pendulum + " --samples x");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("--samples needs a whole number") != std::string::npos);
}

TEST_CASE("cli: run --check-step: the run again at half the step, every metric's change in summary.json") {
  const fs::path dir = elbowsim::testing::scratch("cli", "check_step");
  const fs::path file = dir / "holding.yaml";
  std::ofstream(file) << kHolding;
  const auto out = elbowsim::testing::run_elbowsim("run " + file.string() + " --no-report --check-step --out " +
                                                   (dir / "run").string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  CHECK(out.output.find("step check (0.0005 s against 0.001 s)") != std::string::npos);
  const auto summary = nlohmann::json::parse(elbowsim::testing::slurp(dir / "run" / "summary.json"));
  const auto& check = summary["step_check"];
  CHECK(check["step"] == 1e-3);
  CHECK(check["half_step"] == 5e-4);
  CHECK(check["valid_at_half_step"] == true);
  const auto& energy = check["metrics"]["energy_in"];
  CHECK(energy["value"] == summary["metrics"]["energy_in"]);  // this run's own value
  CHECK(energy["at_half_step"].get<double>() != energy["value"].get<double>());
  CHECK(energy["relative_change"].get<double>() < 1e-3);  // converged energy
  CHECK(check["metrics"].contains("hand_error_rms"));
  // Without the flag: no second run, no step_check.
  const auto plain = elbowsim::testing::run_elbowsim("run " + file.string() + " --no-report --out " +
                                                     (dir / "plain").string());
  REQUIRE(plain.exit_code == 0);
  CHECK_FALSE(nlohmann::json::parse(elbowsim::testing::slurp(dir / "plain" / "summary.json"))
                  .contains("step_check"));
}

TEST_CASE("paired verdict: stated when the interval excludes 1, refused below the floor or with invalid draws") {
  using elbowsim::study::PairedSamples;
  PairedSamples s;
  s.a = "on";
  s.b = "off";
  s.draws = 20;
  for (int i = 0; i < 20; ++i) {
    const double x = 1.0 + 0.1 * i;
    s.b_values["energy_in"].push_back(x);
    s.a_values["energy_in"].push_back(0.5 * x);
    s.b_values["hand_error_rms"].push_back(1e-3 * x);
    s.a_values["hand_error_rms"].push_back(1e-3 * x * (i % 2 ? 1.2 : 0.8));  // as often above as below
  }
  s.floor_a = s.floor_b = 1e-7;
  auto verdict = [](const PairedSamples& p) {
    return elbowsim::study::paired_verdict(p, 1)["verdict"].get<std::vector<std::string>>();
  };
  auto v = verdict(s);
  REQUIRE(v.size() == 2);
  CHECK(v[0].starts_with("electrical energy: on 50.0 % lower than off"));
  CHECK(v[1].starts_with("RMS hand error: no significant difference between on and off"));

  PairedSamples floor = s;  // errors of 1-3 mm against a 0.2 mm floor: below 10 x
  floor.floor_a = 2e-4;
  CHECK(verdict(floor)[1].find("not above 10 x the accuracy floor") != std::string::npos);

  PairedSamples invalid = s;  // 3 of 20 draws with an invalid run: 15 % > 10 %
  invalid.dropped = 3;
  v = verdict(invalid);
  CHECK(v[0] == "electrical energy: no verdict (3 of 20 draws have an invalid run)");
  PairedSamples one = s;  // 1 of 20: the verdict stands, the draw is named as left out
  one.dropped = 1;
  v = verdict(one);
  REQUIRE(v.size() == 3);
  CHECK(v[0].starts_with("electrical energy: on 50.0 % lower"));
  CHECK(v[2] == "1 of 20 draws left out: a run of the pair was invalid (listed below)");
}
