// Variants (named sets of overrides: the loader's checks, then `elbowsim run`
// writing one folder per variant and comparison.csv/.json) and
// `elbowsim sweep` (sweep.csv). The command line runs as a process.
#include <doctest/doctest.h>

#include "support/process.hpp"
#include "support/scratch.hpp"
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"
#include "test_scenario_helpers.hpp"

namespace fs = std::filesystem;
using elbowsim::load_scenario_variant_text;
using namespace scenario_test;

namespace {

using elbowsim::testing::Outcome;
using elbowsim::testing::scratch;
using elbowsim::testing::slurp;

Outcome run(const std::string& arguments) { return elbowsim::testing::run_elbowsim(arguments); }

// A CSV file as rows of cells (no quoted fields in these tables).
std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(slurp(path));
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) rows.back().push_back(cell);
    if (!line.empty() && line.back() == ',') rows.back().push_back("");
  }
  return rows;
}

// The summary.json value a table column names: "name [unit]" -> name, looked
// up in "metrics" if the summary has it, else as a dotted path
// ("energy_final.joule"); "name[i]" is item i of an array.
// The summary.json value at a comparison column or metric path
// ("energy_final.joule [J]", "metrics.current_peak.0").
nlohmann::json summary_value(const nlohmann::json& summary, std::string column) {
  column = column.substr(0, column.find(" ["));
  std::string pointer;
  for (char c : column) pointer += c == '.' ? '/' : c;
  return summary.at(nlohmann::json::json_pointer("/" + pointer));
}

// Every metric cell of `row` (columns from `first` on, up to " rel" ones)
// equals the number in `summary`.
void check_row_matches(const std::vector<std::string>& header, const std::vector<std::string>& row,
                       std::size_t first, const nlohmann::json& summary) {
  REQUIRE(row.size() == header.size());
  for (std::size_t c = first; c < header.size(); ++c) {
    if (header[c].ends_with(" rel")) break;
    INFO("column " << header[c]);
    const nlohmann::json expected = summary_value(summary, header[c]);
    if (expected.is_null()) {
      CHECK(row[c].empty());
    } else {
      CHECK(std::stod(row[c]) == expected.get<double>());
    }
  }
}

const std::string kPendulumFile =
    std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/two_link_pendulum.yaml";

// The pendulum with two variants; "variants:" is at line `kVariantsLine`.
std::string pendulum_with(const std::string& variants) {
  return slurp(kPendulumFile) + "\nvariants:\n" + variants;
}
int variants_line() {
  const std::string text = slurp(kPendulumFile);
  return static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 2;
}

fs::path write_scene(const fs::path& dir, const std::string& text) {
  const fs::path file = dir / "scene.yaml";
  std::ofstream(file) << text;
  return file;
}

std::string error_of_variant(const std::string& text, const std::string& name) {
  try {
    load_scenario_variant_text(text, "x.yaml", name);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

const char* kFast = " --no-render --no-report --set simulation.duration=0.2";

}  // namespace

// ---------------------------------------------------------------------------
// Loader

TEST_CASE("variants: read in order as --set strings; each loads with its overrides") {
  const std::string text = kTwoLink + yaml(R"(
variants:
  elbow_on: {}
  elbow_off: {effects.gravity: false, "robot.planar.links[0].mass": 2, description: "1.0"}
  plain:
)");
  const Scenario s = load(text);
  REQUIRE(s.variants.size() == 3);
  CHECK(s.variants[0].first == "elbow_on");
  CHECK(s.variants[0].second.empty());
  CHECK(s.variants[1].first == "elbow_off");
  CHECK(s.variants[1].second == std::vector<std::string>{"effects.gravity=false",
                                                         "robot.planar.links[0].mass=2",
                                                         "description=\"1.0\""});
  CHECK(s.variants[2].second.empty());
  CHECK(s.model.effects.gravity);

  const Scenario off = load_scenario_variant_text(text, "x.yaml", "elbow_off");
  CHECK(off.variant == "elbow_off");
  CHECK_FALSE(off.model.effects.gravity);
  CHECK(off.model.links[0].mass == 2.0);
  CHECK(off.description == "1.0");  // a quoted value stays a string
  CHECK(off.variants.empty());
  CHECK_FALSE(contains(off.resolved_yaml, "variants"));
  // The command line's --set come after the variant's.
  CHECK(load_scenario_variant_text(text, "x.yaml", "elbow_off", {"effects.gravity=true"})
            .model.effects.gravity);
  CHECK(contains(error_of_variant(text, "nope"),
                 "no variant named \"nope\"; it has elbow_on, "
                 "elbow_off, plain"));
}

TEST_CASE("variants error: a bad key or value names the variant's line") {
  CHECK_ERROR(kTwoLink + yaml(R"(
variants:
  ok: {}
  broken:
    effects.gravty: false
)"),
              "x.yaml:12:5:", "effects.gravty",
              "unknown key \"gravty\" (did you mean \"gravity\"?)");
  CHECK(contains(error_of(kTwoLink + "variants:\n  broken: {effects.gravty: false}\n"),
                 "(in variant broken)"));
  CHECK_ERROR(kTwoLink + "variants:\n  slow: {simulation.step: -1}\n",
              "x.yaml:10:10:", "simulation.step", "must be > 0 (got -1)");
  // A problem the variant causes elsewhere is reported there, naming the variant.
  const std::string err = error_of(kTwoLink +
                                   "task: {path: hold}\ncontroller: {type: pd}\n"
                                   "variants:\n  torque: {effects.motor: none}\n");
  CHECK(err.starts_with("x.yaml:10:"));
  CHECK(contains(err, "controller.type: "));
  CHECK(contains(err, "(in variant torque)"));
}

TEST_CASE("variants error: names and form") {
  CHECK_ERROR(kTwoLink + "variants:\n  a/b: {}\n", "x.yaml:10:3:", "variants.a/b",
              "a variant name must be letters, digits, _ or - only");
  CHECK_ERROR(kTwoLink + "variants:\n  a: {}\n  a: {}\n", "x.yaml:11:3:", "variants.a",
              "duplicate variant \"a\"");
  CHECK_ERROR(kTwoLink + "variants:\n  a: [effects.gravity=false]\n", "x.yaml:10:6:", "variants.a",
              "expected a map of key.path: value overrides");
  CHECK_ERROR(kTwoLink + "variants:\n  a: {variants.b: {}}\n",
              "x.yaml:10:7:", "variants.a.variants.b", "a variant cannot change variants");
  CHECK_ERROR(kTwoLink + "variants: {}\n", "x.yaml:9:11:", "variants",
              "needs at least one variant");
}

// ---------------------------------------------------------------------------
// elbowsim run

TEST_CASE("variants: run writes a folder per variant and a comparison of their summaries") {
  const fs::path dir = scratch("variants", "run");
  const fs::path file =
      write_scene(dir, pendulum_with("  heavy: {\"robot.planar.links[0].mass\": 2.0}\n"
                                     "  light: {\"robot.planar.links[0].mass\": 0.5}\n"));
  const Outcome r = run("run " + file.string() + " --out " + (dir / "out").string() + kFast);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::vector<nlohmann::json> summaries;
  for (const char* v : {"heavy", "light"}) {
    for (const char* f : {"scenario.yaml", "trajectory.csv", "summary.json"})
      CHECK(fs::exists(dir / "out" / v / f));
    summaries.push_back(nlohmann::json::parse(slurp(dir / "out" / v / "summary.json")));
    CHECK_FALSE(contains(slurp(dir / "out" / v / "scenario.yaml"), "variants"));
  }
  CHECK(summaries[0]["model"]["total_mass"].get<double>() == doctest::Approx(2.9));
  CHECK(summaries[1]["model"]["total_mass"].get<double>() == doctest::Approx(1.4));

  const auto csv = read_csv(dir / "out" / "comparison.csv");
  REQUIRE(csv.size() == 3);
  CHECK(csv[0][0] == "variant");
  CHECK(csv[0][1] == "completed");
  CHECK(csv[0].size() > 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(csv[k + 1][0] == (k == 0 ? "heavy" : "light"));
    CHECK(csv[k + 1][1] == "true");
    check_row_matches(csv[0], csv[k + 1], 3, summaries[k]);  // after the run, completed, valid
  }
  const auto json = nlohmann::json::parse(slurp(dir / "out" / "comparison.json"));
  CHECK(json["runs"] == nlohmann::json::array({"heavy", "light"}));
  CHECK(json["reference"] == "heavy");
  REQUIRE(!json["metrics"].empty());
  for (const auto& m : json["metrics"]) {
    INFO(m["path"]);
    for (std::size_t k = 0; k < 2; ++k) {
      const std::string v = k == 0 ? "heavy" : "light";
      CHECK(m["values"][v] == summary_value(summaries[k], m["path"].get<std::string>()));
    }
    CHECK(m["relative"]["heavy"] == 0.0);
    const double a = m["values"]["heavy"].get<double>(), b = m["values"]["light"].get<double>();
    if (a != 0)
      CHECK(m["relative"]["light"].get<double>() == doctest::Approx((b - a) / std::abs(a)));
  }
}

TEST_CASE("variants: a diverging variant keeps its folder, shows completed=false, exits 3") {
  const fs::path dir = scratch("variants", "diverge");
  const fs::path file = write_scene(
      dir,
      pendulum_with(
          "  calm: {}\n"
          "  wild: {simulation.integrator: euler, simulation.step: 0.05,"
          " simulation.duration: 200,"
          " inputs: {torque: [{type: constant, value: 1e4}, {type: constant, value: 1e4}]}}\n"));
  const Outcome r =
      run("run " + file.string() + " --out " + (dir / "out").string() + " --no-render --no-report");
  CHECK(r.exit_code == 3);
  CHECK(fs::exists(dir / "out" / "wild" / "summary.json"));
  const auto csv = read_csv(dir / "out" / "comparison.csv");
  REQUIRE(csv.size() == 3);
  CHECK(csv[1][1] == "true");
  CHECK(csv[2][0] == "wild");
  CHECK(csv[2][1] == "false");
  const auto json = nlohmann::json::parse(slurp(dir / "out" / "comparison.json"));
  CHECK(json["completed"]["wild"] == false);
}

TEST_CASE("variants: a bad variant key exits 2 naming the variant's line; nothing is written") {
  const fs::path dir = scratch("variants", "bad");
  const fs::path file =
      write_scene(dir, pendulum_with("  good: {}\n  bad: {effects.gravty: false}\n"));
  const Outcome r = run("run " + file.string() + " --out " + (dir / "out").string() + kFast);
  CHECK(r.exit_code == 2);
  const std::string where = "scene.yaml:" + std::to_string(variants_line() + 2) + ":";
  CHECK(contains(r.output, where));
  CHECK(contains(r.output, "effects.gravty"));
  CHECK(contains(r.output, "in variant bad"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

// ---------------------------------------------------------------------------
// elbowsim sweep

TEST_CASE("sweep: one folder and one sweep.csv row per value, numbers as in the summaries") {
  const fs::path dir = scratch("variants", "sweep");
  const Outcome r = run("sweep " + kPendulumFile + " --key simulation.duration --values 0.1,0.2" +
                        " --out " + dir.string() + " --no-render --no-report");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto csv = read_csv(dir / "sweep.csv");
  REQUIRE(csv.size() == 3);
  CHECK(csv[0][0] == "simulation.duration");
  CHECK(csv[0][1] == "variant");
  const char* values[] = {"0.1", "0.2"};
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(csv[k + 1][0] == values[k]);
    CHECK(csv[k + 1][1].empty());  // no variants
    CHECK(csv[k + 1][2] == "true");
    const auto summary = nlohmann::json::parse(
        slurp(dir / (std::string("simulation.duration=") + values[k]) / "summary.json"));
    CHECK(summary["settings"]["duration"] == std::stod(values[k]));
    check_row_matches(csv[0], csv[k + 1], 4, summary);  // after value, variant, completed, valid
  }
  // Numeric values also get plots against the value (energy always; the
  // pendulum has no task, so no hand-error plot).
  CHECK(fs::file_size(dir / "sweep_energy.png") > 1000);
  CHECK_FALSE(fs::exists(dir / "sweep_hand_error.png"));
  // A bad value is bad input: exit 2, nothing written.
  const fs::path bad = dir / "bad";
  CHECK(run("sweep " + kPendulumFile + " --key simulation.duration --values 0.1,-1 --out " +
            bad.string())
            .exit_code == 2);
  CHECK_FALSE(fs::exists(bad));
  CHECK(run("sweep " + kPendulumFile + " --key simulation.duration --out " + bad.string())
            .exit_code == 2);
}

TEST_CASE("the shipped experiment runs at a short duration; its comparison has all three arms; the counterbalance cuts the held-up arm's energy") {
  const fs::path dir = scratch("variants", "experiment");
  const std::string scene = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const Outcome r = run("run " + scene + " --out " + dir.string() +
                        " --set task.duration=1.5 --set task.start_delay=0.05 --no-render"
                        " --expect 'elbow_on.metrics.energy_in < elbow_off.metrics.energy_in'"
                        " --expect 'elbow_off_balanced.metrics.energy_in < 0.5 * elbow_off.metrics.energy_in'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto rows = read_csv(dir / "comparison.csv");
  REQUIRE(rows.size() == 4);  // header + elbow_on + elbow_off + elbow_off_balanced
  CHECK(rows[1][0] == "elbow_on");
  CHECK(rows[2][0] == "elbow_off");
  CHECK(rows[3][0] == "elbow_off_balanced");
  // The springs are in the balanced arm's plant and its account, and only there.
  const auto balanced = nlohmann::json::parse(slurp(dir / "elbow_off_balanced" / "summary.json"));
  CHECK(balanced["energy_final"].contains("spring"));
  CHECK(std::abs(balanced["balance_residual"].get<double>()) <
        1e-3 * balanced["energy_final"]["electrical_in"].get<double>());
  CHECK_FALSE(nlohmann::json::parse(slurp(dir / "elbow_off" / "summary.json"))["energy_final"].contains("spring"));
  for (const char* variant : {"elbow_on", "elbow_off", "elbow_off_balanced"}) {
    const auto summary = nlohmann::json::parse(slurp(dir / variant / "summary.json"));
    CHECK(summary["completed"] == true);
    CHECK(summary["valid"] == true);  // with the tuned PID's integral action
    CHECK(summary["controller_gains"]["rule"]["integral"] == 0.5);
    // 1.5 s for the eight loops: the tuned 1 kHz loop's lag and noise give
    // 0.48 mm (on) and 0.51 mm (off) at most, no motor at its limit; a
    // saturated arm misses by millimetres.
    CHECK(summary["metrics"]["hand_error_max"].get<double>() < 1e-3);
    for (const auto& share : summary["saturation_share"]) CHECK(share.get<double>() == 0);
  }
  CHECK(fs::exists(dir / "compare" / "report.html"));
}

TEST_CASE("the experiment with a rubber elbow pad: both arms valid, the pad pressed and accounted") {
  // k 4e4 N/m: the elbow's ~20 N press it about 0.5 mm (a rubber ball of the
  // elbow's size gives 0.4-1.1 mm); c 60 N s/m, a damping ratio near 0.1. The
  // plan still rests the elbow on the table's surface; the integral action
  // stays off the joints the resting elbow holds.
  const fs::path dir = scratch("variants", "experiment_pad");
  const std::string scene = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const Outcome r = run("run " + scene + " --out " + dir.string() +
                        " --set task.duration=1.5 --set task.start_delay=0.05 --no-render"
                        " --set 'contact.pad={stiffness: 4.0e4, damping: 60}'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* variant : {"elbow_on", "elbow_off"}) {
    CAPTURE(variant);
    const auto summary = nlohmann::json::parse(slurp(dir / variant / "summary.json"));
    CHECK(summary["valid"] == true);
    CHECK(std::find(summary["effects"].begin(), summary["effects"].end(), "pads") !=
          summary["effects"].end());
    CHECK(std::abs(summary["balance_residual_relative"].get<double>()) < 1e-3);
  }
  const auto on = nlohmann::json::parse(slurp(dir / "elbow_on" / "summary.json"));
  const auto off = nlohmann::json::parse(slurp(dir / "elbow_off" / "summary.json"));
  // The resting elbow presses its pad for the whole run: elastic energy at
  // the end, losses from its damping; the held-up elbow never touches it.
  CHECK(on["energy_final"]["pad_elastic"].get<double>() > 0);
  CHECK(on["energy_final"]["pad_loss"].get<double>() > 0);
  CHECK(on["contact"]["bodies"]["elbow"]["rest_fraction"].get<double>() > 0.99);
  CHECK(off["energy_final"]["pad_loss"].get<double>() == 0);
  // The pad's depth from its elastic energy, k d^2 / 2: under a millimetre.
  const double depth = std::sqrt(2 * on["energy_final"]["pad_elastic"].get<double>() / 4.0e4);
  MESSAGE("resting elbow's pad depth at the end ", depth, " m");
  CHECK(depth > 1e-4);
  CHECK(depth < 1e-3);
}
