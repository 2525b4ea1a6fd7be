// What flips a verdict (app/study/sensitivity.hpp, elbowsim sensitivity): the
// ranking and the crossing on planted synthetic verdicts, then the command on
// a two-link arm where one planted parameter flips the energy verdict, checked
// against a montecarlo run with that parameter set where the command says the
// ratio crosses 1.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/study/sensitivity.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"
#include "test_scenario_helpers.hpp"

namespace fs = std::filesystem;
namespace t = elbowsim::testing;
using elbowsim::study::FactorPoints;
using elbowsim::study::RatioAt;
using elbowsim::study::SensitivityFactor;

namespace {

RatioAt at(double ratio, double low, double high, const char* outcome) { return {ratio, low, high, outcome}; }

SensitivityFactor relative(const std::string& given, double spread) {
  return {given, "uniform", true, -spread, spread, 0};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The two-link arm holding still; the variants differ in where their mass is:
// "loaded" carries 0.5 kg in its hand, "heavy_forearm" 0.1 kg and a forearm
// 0.7 kg heavier. The hand's mass drawn ±50 % (around each variant's own)
// decides which draws less energy; the links' masses (±2 %) hardly matter.
const std::string kPlanted = R"(name: planted
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 0.5, com: 0.08, inertia: 0.002, radius: 0.03}
hand_load: {mass: 0.2}
simulation: {duration: 0.3}
task: {path: hold}
controller: {type: pd_feedforward}
uncertainty:
  seed: 3
  parameters:
    hand_load.mass: {uniform: 0.5}
    robot.planar.links[*].mass: {uniform: 0.02}
variants:
  loaded: {hand_load.mass: 0.5}
  heavy_forearm: {hand_load.mass: 0.1, "robot.planar.links[1].mass": 1.2}
)";

}  // namespace

TEST_CASE("sensitivity: the planted factor that flips a synthetic verdict ranks first, with its crossing") {
  // Every factor drawn: 0.8 (0.7-0.9), lower. The decoy swings most (0.5 to 0.9)
  // but keeps the verdict; "planted" at its high end gives 1.25 (1.1-1.4),
  // higher: it flips. ln r is linear through the centre (0.8 at u = 0, 1.25 =
  // 1 / 0.8 at u = +0.1), so it crosses 1 at u = +0.05 exactly.
  const RatioAt nominal = at(0.8, 0.7, 0.9, "lower");
  const std::vector<FactorPoints> factors{
      {relative("decoy", 0.1), at(0.5, 0.45, 0.55, "lower"), at(0.9, 0.85, 0.95, "lower")},
      {relative("quiet", 0.1), at(0.79, 0.7, 0.88, "lower"), at(0.81, 0.72, 0.9, "lower")},
      {relative("planted", 0.1), at(0.64, 0.6, 0.7, "lower"), at(1.25, 1.1, 1.4, "higher")},
      {relative("blurs", 0.1), at(0.8, 0.7, 0.9, "lower"), at(0.95, 0.85, 1.05, "no significant difference")}};
  const auto doc = elbowsim::study::sensitivity_of("energy_drawn", "energy", "a", "b", nominal, factors);
  const auto& ranked = doc["factors"];
  REQUIRE(ranked.size() == 4);
  CHECK(ranked[0]["given"] == "planted");
  CHECK(ranked[0]["effect"] == "flips");
  CHECK(ranked[0]["crosses"]["end"] == "high");
  CHECK(ranked[0]["crosses"]["at"].get<double>() == doctest::Approx(0.05).epsilon(1e-12));
  CHECK(ranked[0]["swing"].get<double>() == doctest::Approx(std::log(1.25 / 0.64)));
  // Then the one that removes the difference, then the rest by swing.
  CHECK(ranked[1]["given"] == "blurs");
  CHECK(ranked[1]["effect"] == "removes");
  CHECK(ranked[1]["crosses"].is_null());  // 0.95 is still below 1
  CHECK(ranked[2]["given"] == "decoy");
  CHECK(ranked[3]["given"] == "quiet");
  CHECK(ranked[3]["effect"] == "none");
  const auto& sentences = doc["sentences"];
  REQUIRE(sentences.size() == 3);  // the centre, the flip, the blur
  CHECK(has(sentences[0].get<std::string>(), "every parameter drawn: 0.8 (0.7–0.9), a lower"));
  CHECK(has(sentences[1].get<std::string>(), "planted held at +10 %: 1.25 (1.1–1.4), a higher: the verdict flips"));
  CHECK(has(sentences[1].get<std::string>(), "crosses 1 near +5 %"));
  CHECK(has(sentences[2].get<std::string>(), "blurs held at +10 %"));
  CHECK(has(sentences[2].get<std::string>(), "the difference is gone"));

  // Nothing changes the verdict: the sentence names the largest swing.
  const auto calm = elbowsim::study::sensitivity_of("energy_drawn", "energy", "a", "b", nominal,
                                                    {factors[1], factors[0]});
  CHECK(calm["factors"][0]["given"] == "decoy");
  REQUIRE(calm["sentences"].size() == 2);
  CHECK(has(calm["sentences"][1].get<std::string>(),
            "No parameter held at either end of its range changes the verdict; the largest swing: decoy"));
}

TEST_CASE("sensitivity: the ends of each law; a [*] entry is one factor") {
  const elbowsim::Scenario s = scenario_test::load(scenario_test::two_link_with(R"(
hand_load: {mass: 0.2}
uncertainty:
  parameters:
    robot.planar.links[*].mass: {uniform: 0.1}
    robot.planar.links[0].length: {normal: 0.05}
    hand_load.mass: {range: [0.1, 0.3]}
)"));
  const auto factors = elbowsim::study::sensitivity_factors(s.uncertainty);
  REQUIRE(factors.size() == 3);
  CHECK(factors[0].given == "robot.planar.links[*].mass");
  CHECK(factors[0].low == -0.1);
  CHECK(factors[0].high == 0.1);
  CHECK(factors[1].low == -0.1);  // normal: +-2 sigma
  CHECK(factors[1].high == 0.1);
  CHECK_FALSE(factors[2].relative);
  CHECK(factors[2].low == 0.1);
  CHECK(factors[2].high == 0.3);
  CHECK(factors[2].centre == doctest::Approx(0.2));
  CHECK(elbowsim::study::factor_value(factors[0], -0.1) == "−10 %");
  CHECK(elbowsim::study::factor_value(factors[2], 0.3) == "0.3");
}

TEST_CASE("cli: sensitivity finds the planted parameter that flips the energy verdict, and where") {
  const fs::path dir = t::scratch("cli", "sensitivity");
  const fs::path file = dir / "planted.yaml";
  std::ofstream(file) << kPlanted;
  const auto out = t::run_elbowsim("sensitivity " + file.string() + " --samples 15 --jobs 2 --out " +
                                   (dir / "out").string());
  INFO(out.output);
  REQUIRE(out.exit_code == 0);
  CHECK(has(out.output, "hand_load.mass held at +50 %"));
  CHECK(has(out.output, "the verdict flips"));
  const auto doc = nlohmann::json::parse(t::slurp(dir / "out" / "sensitivity.json"));
  REQUIRE(doc["points"].size() == 5);  // every parameter drawn, then two ends per factor
  const auto& energy = doc["metrics"][0];
  REQUIRE(energy["metric"] == "energy_drawn");
  CHECK(energy["nominal"]["outcome"] == "lower");
  const auto& first = energy["factors"][0];
  CHECK(first["given"] == "hand_load.mass");
  CHECK(first["effect"] == "flips");
  CHECK(first["high"]["outcome"] == "higher");
  CHECK(energy["factors"][1]["effect"] == "none");
  CHECK(energy["factors"][1]["swing"].get<double>() < 0.1 * first["swing"].get<double>());
  const double crossing = first["crosses"]["at"].get<double>();
  MESSAGE("the energy ratio crosses 1 near hand_load.mass x (1 + ", crossing, ")");
  REQUIRE(crossing > 0);
  REQUIRE(crossing < 0.5);

  // The centre point is montecarlo itself: the same bytes from a plain run.
  const auto plain = t::run_elbowsim("montecarlo " + file.string() + " --samples 15 --jobs 1 --no-report --out " +
                                     (dir / "plain").string());
  REQUIRE(plain.exit_code == 0);
  CHECK(t::slurp(dir / "plain" / "montecarlo.json") ==
        t::slurp(dir / "out" / "points" / "every_parameter_drawn" / "montecarlo.json"));
  const auto held = nlohmann::json::parse(
      t::slurp(dir / "out" / "points" / "hand_load_mass-high" / "montecarlo.json"));
  CHECK(held["held"]["hand_load.mass"] == 0.5);

  // Independent of the interpolation: both hands set to their nominal x (1 +
  // crossing), the hand's mass no longer drawn, the ratio is within 5 % of 1
  // (linear interpolation of ln r between the centre and the end: measured 1.2 %).
  std::string at_crossing = kPlanted;
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto k = at_crossing.find(from);
    REQUIRE(k != std::string::npos);
    at_crossing.replace(k, from.size(), to);
  };
  replace("    hand_load.mass: {uniform: 0.5}\n", "");
  replace("loaded: {hand_load.mass: 0.5}", "loaded: {hand_load.mass: " + std::to_string(0.5 * (1 + crossing)) + "}");
  replace("heavy_forearm: {hand_load.mass: 0.1,",
          "heavy_forearm: {hand_load.mass: " + std::to_string(0.1 * (1 + crossing)) + ",");
  std::ofstream(dir / "crossing.yaml") << at_crossing;
  const auto check = t::run_elbowsim("montecarlo " + (dir / "crossing.yaml").string() +
                                     " --samples 15 --no-report --out " + (dir / "crossing").string());
  REQUIRE(check.exit_code == 0);
  const auto there = nlohmann::json::parse(t::slurp(dir / "crossing" / "montecarlo.json"));
  const double ratio = there["pairs"][0]["energy_drawn"]["ratio"].get<double>();
  MESSAGE("energy ratio with the hands set there: ", ratio);
  CHECK(std::abs(std::log(ratio)) < 0.05);

  // The tables and the charts: a row per point and metric; a tornado per ratio.
  const std::string csv = t::slurp(dir / "out" / "sensitivity.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 2 * 5);
  for (const char* png : {"tornado_energy_drawn.png", "tornado_hand_error_rms.png"})
    CHECK(fs::file_size(dir / "out" / "plots" / png) > 1000);
  CHECK(has(t::slurp(dir / "out" / "report.html"), "plots/tornado_energy_drawn.png"));
}

TEST_CASE("cli: sensitivity needs two variants and one case (exit 2, the reason)") {
  const fs::path dir = t::scratch("cli", "sensitivity_refused");
  std::string one = kPlanted;
  one.erase(one.find("variants:"));
  std::ofstream(dir / "one.yaml") << one;
  const auto single = t::run_elbowsim("sensitivity " + (dir / "one.yaml").string() + " --out " +
                                      (dir / "one").string());
  CHECK(single.exit_code == 2);
  CHECK(has(single.output, "needs two variants to compare"));
  std::ofstream(dir / "study.yaml") << kPlanted + "study:\n  axes:\n    time:\n      short: {simulation.duration: 0.2}\n"
                                                  "      long: {}\n";
  const auto study = t::run_elbowsim("sensitivity " + (dir / "study.yaml").string() + " --out " +
                                     (dir / "study").string());
  CHECK(study.exit_code == 2);
  CHECK(has(study.output, "one case at a time: name it with --case"));
  CHECK_FALSE(fs::exists(dir / "study" / "sensitivity.json"));
}

TEST_CASE("cli: sensitivity with three variants compares the first two, or the --variants pair, and runs only those") {
  const fs::path dir = t::scratch("cli", "sensitivity_three");
  std::ofstream(dir / "three.yaml") << kPlanted + "  light: {hand_load.mass: 0.05}\n";
  const auto first_two = t::run_elbowsim("sensitivity " + (dir / "three.yaml").string() +
                                         " --samples 3 --no-report --out " + (dir / "first").string());
  INFO(first_two.output);
  REQUIRE(first_two.exit_code == 0);
  const auto centre = nlohmann::json::parse(
      t::slurp(dir / "first" / "points" / "every_parameter_drawn" / "montecarlo.json"));
  CHECK(centre["draws"].contains("loaded"));
  CHECK(centre["draws"].contains("heavy_forearm"));
  CHECK_FALSE(centre["draws"].contains("light"));  // not run
  const auto named = t::run_elbowsim("sensitivity " + (dir / "three.yaml").string() +
                                     " --samples 3 --no-report --variants light,loaded --out " + (dir / "named").string());
  REQUIRE(named.exit_code == 0);
  const auto doc = nlohmann::json::parse(t::slurp(dir / "named" / "sensitivity.json"));
  CHECK(doc["metrics"][0]["a"] == "light");
  CHECK(doc["metrics"][0]["b"] == "loaded");
  const auto one = t::run_elbowsim("sensitivity " + (dir / "three.yaml").string() +
                                   " --samples 3 --variants light --out " + (dir / "one").string());
  CHECK(one.exit_code == 2);
  CHECK(has(one.output, "--variants needs two variants, A,B (got 1)"));
}
