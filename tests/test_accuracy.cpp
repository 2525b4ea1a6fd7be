// elbowsim accuracy (app/study/work_precision, report/accuracy_report): the
// study's outputs, the verdict recomputed from the CSV it wrote, errors that
// fall as the settings refine, and bad arguments refused before anything runs.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/scenario/scenario.hpp"
#include "app/study/work_precision.hpp"
#include "engine/run/simulator.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;

namespace {

using elbowsim::testing::Outcome;
using elbowsim::testing::scratch;
using elbowsim::testing::slurp;

const std::string kPendulum = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/two_link_pendulum.yaml";

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.push_back(cell), cell.clear();
    else cell += c;
  }
  out.push_back(cell);
  return out;
}

struct Row {
  std::map<std::string, std::string> cells;
  double number(const std::string& key) const { return std::stod(cells.at(key)); }
};

std::vector<Row> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    REQUIRE(cells.size() == header.size());
    Row r;
    for (std::size_t k = 0; k < header.size(); ++k) r.cells[header[k]] = cells[k];
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST_CASE("accuracy: a study of the pendulum — outputs, monotone errors, the verdict from the CSV") {
  const fs::path dir = scratch("accuracy", "pendulum");
  const Outcome o = elbowsim::testing::run_elbowsim(
      "accuracy " + kPendulum + " --points 4 --repeats 1 --out " + dir.string() +
      " --set simulation.duration=1 --set output.every=10");
  INFO(o.output);
  REQUIRE(o.exit_code == 0);
  for (const char* f : {"work_precision.csv", "accuracy.json", "report.html", "plots/run_wp_hand_max.png"})
    CHECK(fs::exists(dir / f));
  const std::vector<Row> rows = read_csv(dir / "work_precision.csv");
  std::map<std::string, std::vector<const Row*>> sweeps;
  for (const Row& r : rows)
    if (r.cells.at("kind") == "sweep") sweeps[r.cells.at("method")].push_back(&r);
  REQUIRE(sweeps.size() == 5);
  for (const auto& [method, points] : sweeps) {
    REQUIRE(points.size() == 4);
    // On this smooth, non-stiff scene every method's hand error falls as its
    // setting refines, and its work (derivative evaluations) rises. CPU time
    // is not compared here: it is the noisy measure the plots show. (Euler's
    // runs complete but fail the energy check: measured, never chosen.)
    for (std::size_t k = 1; k < points.size(); ++k) {
      INFO(method << " point " << k);
      CHECK(points[k]->cells.at("completed") == "true");
      CHECK(points[k]->number("hand_max [m]") < points[k - 1]->number("hand_max [m]"));
      CHECK(points[k]->number("evaluations") > points[k - 1]->number("evaluations"));
    }
  }
  // Nor is it stiff for dopri5: its stiffness test never fired.
  for (const Row& r : rows) CHECK(r.cells.at("stiff_from [s]").empty());
  // The adaptive methods' tolerance proportionality is drawn; every invalid run is
  // listed with its reason under "Omitted".
  CHECK(fs::file_size(dir / "plots" / "run_tolerance.png") > 1000);
  const std::string html = slurp(dir / "report.html");
  const std::size_t omitted = html.find("<h3>Omitted</h3>");
  REQUIRE(omitted != std::string::npos);
  int invalid = 0;
  for (const Row& r : rows) {
    if (r.cells.at("valid") == "true") continue;
    ++invalid;
    CHECK(html.find(r.cells.at("failure").substr(0, 40), omitted) != std::string::npos);
  }
  CHECK(invalid > 0);  // Euler's runs fail the energy check here
  // The verdict names, for each target, the cheapest valid point meeting it.
  std::ifstream json_in(dir / "accuracy.json");
  const nlohmann::json doc = nlohmann::json::parse(json_in);
  const double floor = doc["studies"][0]["reference"]["uncertainty"]["hand_max"].get<double>();
  CHECK(floor < 1e-10);  // the reference resolves far below the finest target
  int judged = 0;
  for (const auto& target : doc["verdict"][0]["targets"]) {
    const double t = target["target"].get<double>();
    const Row* best = nullptr;
    for (const Row& r : rows)
      if (r.cells.at("kind") == "sweep" && r.cells.at("valid") == "true" &&
          r.number("hand_max [m]") <= t && (!best || r.number("cpu_seconds") < best->number("cpu_seconds")))
        best = &r;
    INFO("target " << t);
    if (!best) {
      CHECK(target["met"] == false);
      continue;
    }
    ++judged;
    CHECK(target["method"] == best->cells.at("method"));
    CHECK(target["value"].get<double>() == doctest::Approx(best->number("value")).epsilon(1e-15));
  }
  CHECK(judged >= 2);
  CHECK(o.output.find("cheapest") != std::string::npos);
}

TEST_CASE("accuracy: dopri5 on the elbow at rest (L/R 0.25 ms) is marked stiff: it rejects a step per step at any rtol") {
  const fs::path dir = scratch("accuracy", "stiff");
  const Outcome o = elbowsim::testing::run_elbowsim(
      "accuracy " + std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_rest.yaml --methods dopri5 --points 2"
      " --repeats 1 --no-alternatives --set simulation.duration=0.3 --out " + dir.string());
  INFO(o.output);
  REQUIRE(o.exit_code == 0);
  const std::vector<Row> rows = read_csv(dir / "work_precision.csv");
  REQUIRE(rows.size() == 2);
  for (const Row& r : rows) {
    // The stability edge, not rtol 1e-3 or 1e-4, sets the step: about as many
    // rejected steps as accepted, and the test fires within the first 20 ms.
    CHECK(r.number("stiff_from [s]") > 0);
    CHECK(r.number("stiff_from [s]") < 0.02);
    CHECK(r.number("rejected_steps") > 0.5 * r.number("steps"));
  }
  CHECK(slurp(dir / "report.html").find("stiff from") != std::string::npos);
}

TEST_CASE("accuracy: from 6 repeats a setting is timed until its median's 95 % interval is within 5 % (or 100 timings)") {
  const fs::path dir = scratch("accuracy", "timing");
  const Outcome o = elbowsim::testing::run_elbowsim(
      "accuracy " + kPendulum + " --methods rk4 --points 2 --repeats 6 --no-alternatives --out " +
      dir.string() + " --set simulation.duration=0.2");
  INFO(o.output);
  REQUIRE(o.exit_code == 0);
  const std::vector<Row> rows = read_csv(dir / "work_precision.csv");
  REQUIRE(rows.size() == 2);
  for (const Row& r : rows) {
    const double m = r.number("cpu_seconds"), low = r.number("cpu_low [s]"), high = r.number("cpu_high [s]");
    const double repeats = r.number("repeats");
    INFO("median " << m << " s in [" << low << ", " << high << "] after " << repeats << " timings");
    CHECK(repeats >= 6);
    CHECK(low <= m);
    CHECK(m <= high);
    CHECK((repeats == 100 || (high - m <= 0.05 * m && m - low <= 0.05 * m)));
  }
  // Fewer than 6 timings have no interval: the columns stay empty.
  const Outcome once = elbowsim::testing::run_elbowsim(
      "accuracy " + kPendulum + " --methods rk4 --points 2 --repeats 1 --no-alternatives --out " +
      (dir / "once").string() + " --set simulation.duration=0.2");
  REQUIRE(once.exit_code == 0);
  for (const Row& r : read_csv(dir / "once" / "work_precision.csv")) {
    CHECK(r.cells.at("repeats") == "1");
    CHECK(r.cells.at("cpu_low [s]").empty());
  }
}

TEST_CASE("accuracy: bad arguments exit 2 and write nothing") {
  const fs::path dir = scratch("accuracy", "bad");
  const Outcome unknown = elbowsim::testing::run_elbowsim("accuracy " + kPendulum + " --methods rk4,rk5 --out " + dir.string());
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.output.find("unknown method \"rk5\"") != std::string::npos);
  const Outcome variant = elbowsim::testing::run_elbowsim("accuracy " + kPendulum + " --variant x --out " + dir.string());
  CHECK(variant.exit_code == 2);
  CHECK(variant.output.find("has no variants") != std::string::npos);
  const Outcome points = elbowsim::testing::run_elbowsim("accuracy " + kPendulum + " --points 1 --out " + dir.string());
  CHECK(points.exit_code == 2);
  CHECK_FALSE(fs::exists(dir / "accuracy.json"));
}

TEST_CASE("compare_runs: errors against a reference at the same rows; different times refused") {
  using namespace elbowsim;
  const Scenario s = load_scenario(kPendulum, {"simulation.duration=0.2"});
  const RunResult a = simulate(s.model, s.experiment, RunOptions{10, {}});
  const study::RunErrors same = study::compare_runs(a, a);
  CHECK(same.hand_max == 0);
  CHECK(same.angle_final == 0);
  CHECK(same.rows == 21);
  CHECK(std::isnan(same.force_max));  // no contact columns
  Model half = s.model;
  half.options.step /= 2;
  const RunResult b = simulate(half, s.experiment, RunOptions{20, {}});
  const study::RunErrors e = study::compare_runs(a, b);
  CHECK(e.hand_max > 0);
  CHECK(e.hand_rms <= e.hand_max);
  CHECK(e.angle_final <= e.angle_max);
  const RunResult c = simulate(half, s.experiment, RunOptions{10, {}});  // rows every 5 ms
  CHECK_THROWS_AS(study::compare_runs(a, c), std::invalid_argument);
}
