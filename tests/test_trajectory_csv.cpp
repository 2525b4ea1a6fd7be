// trajectory.csv through its layout: what the recorder writes is read back
// with the same layout, the same numbers (to the 12 digits written) and the
// same metrics; a header that is not a layout is refused with the column
// named. And a run with variants writes one comparison, not two.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "app/output/trajectory_csv.hpp"
#include "engine/recording/metrics.hpp"
#include "engine/run/simulator.hpp"
#include "support/experiment_scenes.hpp"
#include "support/process.hpp"

using namespace elbowsim;
namespace fs = std::filesystem;

namespace {

// The experiment arm with everything a layout can hold: motors, a hand task
// (desired hand, hand error) and an elbow on the table.
RunResult full_run() {
  testing::WritingArm arm;
  arm.task_duration = 0.3;
  arm.run_duration = 0.4;
  const auto [model, experiment] = arm.scene();
  return simulate(model, experiment, RunOptions{10, {}});
}

Recording round_trip(const Recording& rec, std::string* text = nullptr) {
  std::ostringstream out;
  write_trajectory_csv(out, rec);
  if (text) *text = out.str();
  std::istringstream in(out.str());
  return read_trajectory_csv(in, "trajectory.csv");
}

}  // namespace

TEST_CASE("trajectory.csv: every recorded column is read back through the same layout") {
  const RunResult run = full_run();
  REQUIRE(run.completed);
  const Recording& rec = run.trajectory;
  const TrajectoryLayout& L = rec.layout;
  REQUIRE(L.has_motors());
  REQUIRE(L.has_desired_hand());
  REQUIRE(L.has_contact());
  // The recorder wrote every column (it starts a row as NaN).
  for (double v : rec.values) REQUIRE(std::isfinite(v));

  const Recording back = round_trip(rec);
  CHECK(back.layout.columns().size() == L.columns().size());
  for (std::size_t c = 0; c < L.columns().size(); ++c) {
    CHECK(back.columns()[c].name == rec.columns()[c].name);
    CHECK(back.columns()[c].unit == rec.columns()[c].unit);
  }
  CHECK(back.layout.groups().elbows == L.groups().elbows);
  CHECK(back.layout.hand_error() == L.hand_error());
  CHECK(back.layout.elbow_force(0) == L.elbow_force(0));
  REQUIRE(back.values.size() == rec.values.size());
  // 12 significant digits are written: each value back within 1e-11 relative.
  for (std::size_t k = 0; k < rec.values.size(); ++k)
    CHECK(std::abs(back.values[k] - rec.values[k]) <= 1e-11 * std::abs(rec.values[k]) + 1e-300);

  // The metrics from the file equal the run's (the CSV's rounding only).
  const Metrics a = compute_metrics(rec), b = compute_metrics(back);
  REQUIRE(a.list.size() == b.list.size());
  for (std::size_t m = 0; m < a.list.size(); ++m) {
    CAPTURE(a.list[m].name);
    CHECK(b.list[m].name == a.list[m].name);
    for (std::size_t k = 0; k < a.list[m].values.size(); ++k)
      CHECK(b.list[m].values[k] ==
            doctest::Approx(a.list[m].values[k]).epsilon(1e-9).scale(1e-12));
  }
}

TEST_CASE("trajectory.csv: a header that is not a layout is refused, naming the column") {
  std::string text;
  round_trip(full_run().trajectory, &text);
  auto read = [](const std::string& csv) {
    std::istringstream in(csv);
    return read_trajectory_csv(in, "run/trajectory.csv");
  };
  // A renamed column.
  std::string renamed = text;
  renamed.replace(renamed.find("hand_error [m]"), 14, "hand_err [m]");
  CHECK_THROWS_WITH_AS(read(renamed),
                       doctest::Contains("run/trajectory.csv:1: trajectory column"),
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(read(renamed), doctest::Contains("expected 'hand_error [m]'"),
                       std::runtime_error);
  // A unit changed.
  std::string unit = text;
  unit.replace(unit.find("q0 [rad]"), 8, "q0 [deg]");
  CHECK_THROWS_WITH_AS(read(unit), doctest::Contains("'q0 [deg]', expected 'q0 [rad]'"),
                       std::runtime_error);
}

TEST_CASE("variants write one comparison: comparison.json and .csv beside them, the report in compare/") {
  const fs::path dir = fs::temp_directory_path() / "elbowsim_one_comparison";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/two_link_pendulum.yaml";
  std::ofstream(dir / "scene.yaml") << testing::slurp(scene)
                                    << "\nvariants:\n  a: {}\n  b: {\"robot.planar.links[0].mass\": 2}\n";
  const testing::Outcome r = testing::run_elbowsim(
      "run " + (dir / "scene.yaml").string() + " --out " + (dir / "out").string() +
      " --no-render --set simulation.duration=0.1");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(dir / "out" / "comparison.json"));
  CHECK(fs::exists(dir / "out" / "comparison.csv"));
  CHECK(fs::exists(dir / "out" / "compare" / "report.html"));
  CHECK_FALSE(fs::exists(dir / "out" / "compare" / "comparison.json"));
  // The report links the one comparison.json.
  CHECK(testing::slurp(dir / "out" / "compare" / "report.html").find("../comparison.json") !=
        std::string::npos);
}
