// The Monte Carlo study: the uncertainty: section (expansion, nominal values,
// errors), the draws (seeded, independent of the number taken), and
// `elbowsim montecarlo` as a process (same seed -> same bytes whatever
// --jobs; identical variants -> no significant difference).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/study/draws.hpp"
#include "app/study/paired_verdict.hpp"
#include "report/statistics.hpp"
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

TEST_CASE("cli: montecarlo: same seed -> same bytes (jobs 1 or 2); identical variants -> no difference" * doctest::test_suite("long")) {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo");
  const fs::path file = dir / "holding.yaml";
  std::ofstream(file) << kHolding << "variants: {a: {}, b: {}}\n";
  auto run = [&](const std::string& out, const std::string& options) {
    return elbowsim::testing::run_elbowsim("montecarlo " + file.string() + " --samples 15 --out " +
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
  CHECK(doc["samples"] == 15);
  CHECK(doc["min_interval_draws"] == 15);
  CHECK(doc["invalid"].empty());
  const auto& energy = doc["pairs"][0]["energy_drawn"];
  CHECK(energy["statistic"] == "ratio");
  CHECK(energy["ci95"][0].get<double>() <= 1.0);
  CHECK(energy["ci95"][1].get<double>() >= 1.0);
  const auto& net = doc["pairs"][0]["energy_in"];
  CHECK(net["statistic"] == "difference");
  CHECK(net["ci95"][0].get<double>() <= 0.0);
  CHECK(net["ci95"][1].get<double>() >= 0.0);
  const std::string verdict = doc["verdict"][0];
  CHECK(verdict.starts_with(
      "electrical energy drawn from the supply: no significant difference between a and b"));
  CHECK(first.output.find("no significant difference") != std::string::npos);

  // The draws vary the plant: link 0's mass differs between draws.
  CHECK(doc["metrics"]["a"]["energy_in"]["valid"] == 15);
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

TEST_CASE("cli: run: the step check runs by default: the run at half the step, every metric's change and floor") {
  const fs::path dir = elbowsim::testing::scratch("cli", "check_step");
  const fs::path file = dir / "holding.yaml";
  std::ofstream(file) << kHolding;
  const auto out = elbowsim::testing::run_elbowsim("run " + file.string() + " --no-report --out " +
                                                   (dir / "run").string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  CHECK(out.output.find("accuracy at half the step (0.0005 s)") != std::string::npos);
  const auto summary = nlohmann::json::parse(elbowsim::testing::slurp(dir / "run" / "summary.json"));
  const auto& check = summary["step_check"];
  CHECK(check["step"] == 1e-3);
  CHECK(check["half_step"] == 5e-4);
  CHECK(check["refinement"] == "half the step (0.0005 s)");
  CHECK(check["valid_at_half_step"] == true);
  const auto& energy = check["metrics"]["energy_in"];
  CHECK(energy["value"] == summary["metrics"]["energy_in"]);  // this run's own value
  CHECK(energy["at_half_step"].get<double>() != energy["value"].get<double>());
  CHECK(energy["relative_change"].get<double>() < 1e-3);  // converged energy
  CHECK(energy["floor"].get<double>() ==
        std::abs(energy["value"].get<double>() - energy["at_half_step"].get<double>()));
  CHECK(energy["below_floor"] == false);
  CHECK(check["metrics"].contains("hand_error_rms"));
  // Each metric below 10 x its floor is listed, and only those.
  for (const auto& [name, m] : check["metrics"].items()) {
    const bool below = std::abs(m["value"].get<double>()) < 10 * m["floor"].get<double>();
    CAPTURE(name);
    CHECK(m["below_floor"].get<bool>() == below);
    const auto& list = check["below_floor"];
    CHECK((std::find(list.begin(), list.end(), name) != list.end()) == below);
  }
  // --check-step (older scripts) is accepted; --no-check-step: no second run, no step_check.
  const auto old = elbowsim::testing::run_elbowsim("run " + file.string() +
                                                   " --no-report --check-step --out " + (dir / "old").string());
  CHECK(old.exit_code == 0);
  const auto plain = elbowsim::testing::run_elbowsim("run " + file.string() +
                                                     " --no-report --no-check-step --out " + (dir / "plain").string());
  REQUIRE(plain.exit_code == 0);
  CHECK(plain.output.find("accuracy at") == std::string::npos);
  CHECK_FALSE(nlohmann::json::parse(elbowsim::testing::slurp(dir / "plain" / "summary.json"))
                  .contains("step_check"));
}

TEST_CASE(
    "paired verdict: stated when the interval excludes 1 or 0, refused below the floor or with "
    "invalid draws") {
  using elbowsim::study::PairedSamples;
  PairedSamples s;
  s.a = "on";
  s.b = "off";
  s.draws = 20;
  for (int i = 0; i < 20; ++i) {
    const double x = 1.0 + 0.1 * i;
    s.b_values["energy_drawn"].push_back(x);
    s.a_values["energy_drawn"].push_back(0.5 * x);
    // The net energy has both signs: the motors fed back more in some draws.
    s.b_values["energy_in"].push_back(x - 1.5);
    s.a_values["energy_in"].push_back(0.5 * x - 1.5);
    s.b_values["hand_error_rms"].push_back(1e-3 * x);
    s.a_values["hand_error_rms"].push_back(1e-3 * x * (i % 2 ? 1.2 : 0.8));  // as often above as below
    for (const char* m : {"energy_drawn", "energy_in", "hand_error_rms"})
      s.draw_index[m].push_back(i);
  }
  s.floor_a = s.floor_b = 1e-7;
  auto verdict = [](const PairedSamples& p) {
    return elbowsim::study::paired_verdict(p, 1)["verdict"].get<std::vector<std::string>>();
  };
  auto v = verdict(s);
  REQUIRE(v.size() == 3);
  CHECK(v[0].starts_with(
      "electrical energy drawn from the supply: on 50 % lower than off (paired 95 % CI of "
      "on/off: 0.5–0.5, 20 draws; on lower in 100 % of draws)"));
  // The mean difference: 0.5 x the mean of 1.0 .. 2.9, 0.975 J.
  CHECK(v[1].starts_with(
      "net electrical energy (drawn − regenerated): on 975 mJ lower than off (paired 95 % "
      "CI of on − off: "));
  CHECK(v[2].starts_with("RMS hand error: no significant difference between on and off"));
  auto json = elbowsim::study::paired_verdict(s, 1);
  CHECK(json["energy_in"]["statistic"] == "difference");
  CHECK(json["energy_in"]["unit"] == "J");
  CHECK(json["energy_in"]["difference"].get<double>() == doctest::Approx(-0.975));
  CHECK(json["energy_in"]["outcome"] == "lower");
  CHECK(json["energy_drawn"]["outcome"] == "lower");
  CHECK_FALSE(json["energy_drawn"].contains("reason"));

  PairedSamples floor = s;  // errors of 1-3 mm against a 0.2 mm floor: below 10 x
  floor.floor_a = 2e-4;
  CHECK(verdict(floor)[2] ==
        "RMS hand error, on against off: no verdict (the medians (1.86 mm, 1.95 mm) are not above 10 x the "
        "accuracy floor "
        "(200 µm, 100 nm; step halving of the nominal runs): they measure the integrator, not the "
        "arm)");

  PairedSamples invalid = s;  // 3 of 20 draws with an invalid run: 15 % > 10 %
  invalid.dropped = 3;
  v = verdict(invalid);
  CHECK(v[0] ==
        "electrical energy drawn from the supply, on against off: no verdict (3 of 20 draws have an invalid run; "
        "a verdict allows 10 %)");
  PairedSamples one = s;  // 1 of 20: the verdict stands, the draw is named as left out
  one.dropped = 1;
  v = verdict(one);
  REQUIRE(v.size() == 4);
  CHECK(v[0].starts_with("electrical energy drawn from the supply: on 50 % lower"));
  CHECK(v[3] == "1 of 20 draws left out: a run of the pair was invalid (listed below)");
}

TEST_CASE(
    "paired verdict: a statistic that cannot be computed gives its reason and draws; the rest "
    "stand") {
  using elbowsim::study::PairedSamples;
  PairedSamples s;
  s.a = "on";
  s.b = "off";
  s.draws = 15;
  for (int i = 0; i < 15; ++i) {
    const double x = 1.0 + 0.1 * i;
    s.b_values["energy_drawn"].push_back(x);
    s.a_values["energy_drawn"].push_back(i == 4 || i == 9 ? 0.0
                                                          : 0.5 * x);  // drew nothing: no ratio
    s.b_values["hand_error_rms"].push_back(1e-3 * x);
    s.a_values["hand_error_rms"].push_back(0.3e-3 * x);
    for (const char* m : {"energy_drawn", "hand_error_rms"}) s.draw_index[m].push_back(100 + i);
  }                                                      // no energy_in: not recorded
  const auto p = elbowsim::study::paired_verdict(s, 1);  // does not throw
  const auto v = p["verdict"].get<std::vector<std::string>>();
  REQUIRE(v.size() == 3);
  CHECK(v[0] ==
        "electrical energy drawn from the supply, on against off: no verdict (a ratio needs values > 0; 2 pairs "
        "have a value <= 0 or not finite: draws 104, 109)");
  CHECK(p["energy_drawn"]["outcome"] == "no verdict");
  CHECK(p["energy_drawn"]["draws"] == nlohmann::json::array({104, 109}));
  CHECK_FALSE(p["energy_drawn"].contains("ratio"));
  CHECK(v[1] ==
        "net electrical energy (drawn − regenerated), on against off: no verdict (energy_in is not recorded in "
        "these runs)");
  CHECK(v[2].starts_with("RMS hand error: on 70 % lower than off"));
  CHECK(p["hand_error_rms"]["outcome"] == "lower");

  // Three draws: the ratio, no interval and no verdict (the issue's 0.145-inf).
  PairedSamples three = s;
  for (auto* values : {&three.a_values, &three.b_values})
    for (auto& [m, x] : *values) x.resize(3);
  const auto q = elbowsim::study::paired_verdict(three, 1);
  CHECK(q["hand_error_rms"]["ratio"].get<double>() == doctest::Approx(0.3));
  CHECK_FALSE(q["hand_error_rms"].contains("ci95"));
  CHECK(q["hand_error_rms"]["outcome"] == "no verdict");
  CHECK(q["verdict"][2] == "RMS hand error, on against off: no verdict (3 pairs; an interval needs at least 15)");
}

namespace {

// A two-link arm whose motors lower it 20 cm under gravity in 0.4 s, against
// the same arm holding still. Lowering, the motors brake (low resistance,
// geared 100:1 and 30:1) and feed back more than they draw: a negative net
// electrical energy in every draw; holding draws a little.
const std::string kLowering = yaml(R"(
name: two_link
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 0.5, com: 0.08, inertia: 0.002, radius: 0.03}
initial: {q: [0.6, -1.5]}
simulation: {duration: 0.6}
motors:
  default: {resistance: 0.25, torque_constant: 0.05}
  joints: [{gear_ratio: 100}, {gear_ratio: 30}]
task: {path: line, origin: start, points: [start, [0, 0, -0.2]], duration: 0.4, start_delay: 0.05}
controller: {type: pd_feedforward, kd: [2, 0.5]}
variants:
  lowered: {}
  held: {task.path: hold, task.points: [start]}
uncertainty:
  seed: 3
  parameters:
    robot.planar.links[*].mass: {uniform: 0.1}
    motors.default.resistance: {uniform: 0.1}
)");

std::vector<double> numbers(const nlohmann::json& array) {
  std::vector<double> out;
  for (const auto& v : array) out.push_back(v.get<double>());
  return out;
}

}  // namespace

TEST_CASE(
    "cli: montecarlo: draws whose net energy is negative finish (exit 0) with every statistic") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_regenerating");
  const fs::path file = dir / "lowering.yaml";
  std::ofstream(file) << kLowering;
  const auto r = elbowsim::testing::run_elbowsim(
      "montecarlo " + file.string() + " --samples 15 --jobs 2 --out " + (dir / "mc").string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  auto doc = nlohmann::json::parse(elbowsim::testing::slurp(dir / "mc" / "montecarlo.json"));
  CHECK(doc["invalid"].empty());
  // The negative net energy really occurs: every lowering draw regenerates more than it draws.
  const std::vector<double> net = numbers(doc["draws"]["lowered"]["energy_in"]);
  const std::vector<double> drawn = numbers(doc["draws"]["lowered"]["energy_drawn"]);
  const std::vector<double> fed_back = numbers(doc["draws"]["lowered"]["energy_regenerated"]);
  REQUIRE(net.size() == 15);
  for (std::size_t d = 0; d < net.size(); ++d) {
    CHECK(net[d] < -1.0);
    CHECK(drawn[d] > 0);
    CHECK(net[d] == doctest::Approx(drawn[d] - fed_back[d]).epsilon(1e-9));
  }
  for (double held : numbers(doc["draws"]["held"]["energy_in"])) CHECK(held > 0);
  // samples.csv holds them.
  CHECK(elbowsim::testing::slurp(dir / "mc" / "samples.csv").find(",lowered,true,") !=
        std::string::npos);

  // Every statistic computed: the ratio of drawn energy, the difference of
  // net energy (negative: lowered - held), the ratio of hand errors.
  auto& pair = doc["pairs"][0];
  CHECK(pair["energy_drawn"]["statistic"] == "ratio");
  CHECK(pair["energy_drawn"]["ratio"].get<double>() > 1);
  CHECK(pair["energy_drawn"]["outcome"] == "higher");
  CHECK(pair["energy_in"]["statistic"] == "difference");
  CHECK(pair["energy_in"]["difference"].get<double>() < -1);
  CHECK(pair["energy_in"]["ci95"][1].get<double>() < 0);
  CHECK(pair["energy_in"]["outcome"] == "lower");
  CHECK(pair["hand_error_rms"].contains("ci95"));
  CHECK(r.output.find("net electrical energy (drawn − regenerated): lowered ") !=
        std::string::npos);
  // The net energy's interval on a linear scale (negative), the never-negative
  // regenerated energy's on a log scale; held regenerates nothing: [0, 0].
  auto& lowered = doc["metrics"]["lowered"];
  CHECK(lowered["energy_in"]["scale"] == "linear");
  CHECK(lowered["energy_in"]["ci95"][1].get<double>() < 0);
  CHECK(lowered["energy_regenerated"]["scale"] == "log");
  CHECK(lowered["energy_regenerated"]["ci95"][0].get<double>() > 0);
  CHECK(doc["metrics"]["held"]["energy_regenerated"]["ci95"] == nlohmann::json::array({0.0, 0.0}));
  // The report quotes SI numbers: millijoules, micrometres.
  const std::string html = elbowsim::testing::slurp(dir / "mc" / "report.html");
  CHECK(html.find(" mJ") != std::string::npos);
  CHECK(html.find(" µm") != std::string::npos);
  CHECK(html.find("difference A − B") != std::string::npos);
}

TEST_CASE("cli: montecarlo --variants runs those variants in that order (the ratio is the first's over the second's); an unknown or repeated name is a usage error") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_variants");
  const fs::path file = dir / "lowering.yaml";
  std::ofstream(file) << kLowering;
  auto run = [&](const std::string& variants, const std::string& out) {
    return elbowsim::testing::run_elbowsim("montecarlo " + file.string() + " --samples 3 --jobs 2 --no-report --variants " +
                                           variants + " --out " + (dir / out).string());
  };
  const auto both = run("held,lowered", "swapped");
  INFO(both.output);
  REQUIRE(both.exit_code == 0);
  const auto doc = nlohmann::json::parse(elbowsim::testing::slurp(dir / "swapped" / "montecarlo.json"));
  REQUIRE(doc["pairs"].size() == 1);
  CHECK(doc["pairs"][0]["a"] == "held");
  CHECK(doc["pairs"][0]["b"] == "lowered");
  const auto one = run("held", "one");
  REQUIRE(one.exit_code == 0);
  const auto single = nlohmann::json::parse(elbowsim::testing::slurp(dir / "one" / "montecarlo.json"));
  CHECK(single["pairs"].empty());
  CHECK(single["draws"].contains("held"));
  CHECK_FALSE(single["draws"].contains("lowered"));
  const auto unknown = run("held,raised", "unknown");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.output.find("has no variant \"raised\" (it has lowered, held)") != std::string::npos);
  const auto twice = run("held,held", "twice");
  CHECK(twice.exit_code == 2);
  CHECK(twice.output.find("--variants names held twice") != std::string::npos);
}

TEST_CASE(
    "cli: montecarlo: 3 draws give no interval and no verdict; 30 give log-scale intervals above "
    "0") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_intervals");
  const fs::path file = dir / "lowering.yaml";
  std::ofstream(file) << kLowering;
  auto run = [&](int samples) {
    const std::string out = (dir / std::to_string(samples)).string();
    const auto r =
        elbowsim::testing::run_elbowsim("montecarlo " + file.string() + " --samples " +
                                        std::to_string(samples) + " --jobs 2 --out " + out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return std::make_pair(
        r.output, nlohmann::json::parse(elbowsim::testing::slurp(out + "/montecarlo.json")));
  };
  auto [few_output, few] = run(3);
  for (const char* what : {"electrical energy drawn from the supply",
                           "net electrical energy (drawn − regenerated)", "RMS hand error"})
    CHECK(few_output.find(std::string(what) + ", lowered against held" +
                          ": no verdict (3 pairs; an interval needs at least 15)") !=
          std::string::npos);
  CHECK(few_output.find("CI") == std::string::npos);
  for (const auto& [variant, metrics] : few["metrics"].items())
    for (const auto& [name, m] : metrics.items()) {
      CAPTURE(name);
      CHECK_FALSE(m.contains("ci95"));
      CHECK(m.value("no_interval", "") == "3 values; an interval needs at least 15");
    }
  for (const char* m : {"energy_drawn", "energy_in", "hand_error_rms"}) {
    CHECK_FALSE(few["pairs"][0][m].contains("ci95"));
    CHECK(few["pairs"][0][m]["outcome"] == "no verdict");
  }
  CHECK(elbowsim::testing::slurp(dir / "3" / "report.html")
            .find("none: 3 values; an interval needs at least 15") != std::string::npos);

  auto [many_output, many] = run(30);
  for (const char* m : {"energy_drawn", "hand_error_rms"}) {
    CAPTURE(m);
    const auto& ci = many["pairs"][0][m]["ci95"];
    CHECK(ci[0].get<double>() > 0);
    CHECK(std::isfinite(ci[1].get<double>()));
  }
  // The RMS hand error's interval of the mean is the log-scale bootstrap of
  // the 30 values: above 0, and skewed up as they are.
  for (const char* variant : {"lowered", "held"}) {
    CAPTURE(variant);
    auto& m = many["metrics"][variant]["hand_error_rms"];
    CHECK(m["scale"] == "log");
    const std::vector<double> x = numbers(many["draws"][variant]["hand_error_rms"]);
    const elbowsim::report::Interval log = elbowsim::report::bootstrap_mean_log(x, 0.95, 4000, 3);
    CHECK(m["ci95"][0].get<double>() == log.low);
    CHECK(m["ci95"][1].get<double>() == log.high);
    const elbowsim::report::Interval linear = elbowsim::report::bootstrap_mean(x, 0.95, 4000, 3);
    CHECK(log.low != linear.low);  // not the linear interval
    CHECK(log.high != linear.high);
    CHECK(log.low > 0);
    const double mean = m["mean"].get<double>();
    CHECK(log.high - mean > mean - log.low);
  }
}

TEST_CASE(
    "cli: montecarlo over a study: a case whose statistic cannot be computed keeps its row, with "
    "the reason") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_study_reason");
  const fs::path file = dir / "lowering.yaml";
  // Unpowered (0 V, open loop) the arm sinks against its shorted motors: no
  // energy is drawn from the supply in any draw, so no ratio of it.
  std::ofstream(file)
      << kLowering
      << "study: {axes: {drive: {planned: {}, unpowered: {controller.type: open_loop}}}}\n";
  const auto r = elbowsim::testing::run_elbowsim(
      "montecarlo " + file.string() + " --samples 15 --jobs 2 --out " + (dir / "mc").string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  auto study = nlohmann::json::parse(elbowsim::testing::slurp(dir / "mc" / "study.json"));
  REQUIRE(study["cases"].size() == 2);
  auto& unpowered = study["cases"][1];
  CHECK(unpowered["case"] == "unpowered");
  auto& drawn = unpowered["pairs"][0]["energy_drawn"];
  CHECK(drawn["outcome"] == "no verdict");
  CHECK(drawn["reason"] == "a ratio needs values > 0; 15 pairs have a value <= 0 or not finite");
  CHECK(drawn["draws"].size() == 15);
  CHECK_FALSE(drawn.contains("ratio"));
  // The rest of that case is computed: the net energy (0 J in both) and the hand error.
  CHECK(unpowered["pairs"][0]["energy_in"]["outcome"] == "no significant difference");
  CHECK(unpowered["pairs"][0]["hand_error_rms"].contains("ci95"));
  // The planned case has its verdicts.
  CHECK(study["cases"][0]["pairs"][0]["energy_drawn"]["outcome"] == "higher");
  CHECK(study["cases"][0]["pairs"][0]["energy_in"]["outcome"] == "lower");
  // study.csv: a row per case, the reason and the draws in the unpowered one's.
  const std::string csv = elbowsim::testing::slurp(dir / "mc" / "study.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 3);
  CHECK(csv.find("\nunpowered,unpowered,lowered,held,0,,,,,no verdict,,,\"a ratio needs values > 0; "
                 "15 pairs have a "
                 "value <= 0 or not finite: draws 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14\",") !=
        std::string::npos);
  CHECK(study["verdict"][0] ==
        "Electrical energy drawn from the supply, lowered against held: higher in 1 of 2 "
        "cases; no verdict in 1 of 2 cases; lowered lower in 0 of 15 draws, held lower in 15");
  const std::string html = elbowsim::testing::slurp(dir / "mc" / "report.html");
  CHECK(html.find("no verdict: a ratio needs values &gt; 0") != std::string::npos);
}
