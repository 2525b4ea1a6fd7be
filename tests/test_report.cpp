// Run reports and comparisons: derived series and metrics, the verdict, and
// the files elbowsim writes (run as a process): report.html's metrics equal
// summary.json, every image and video it names exists and decodes, failures
// are in plain sight, a comparison names every run.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "report/columns.hpp"
#include "report/comparison.hpp"
#include "report/metrics.hpp"
#include "report/plots_aside.hpp"
#include "report/summary_keys.hpp"
#include "report/summary_units.hpp"
#include "report_test_helpers.hpp"
#include "support/approx.hpp"
#include "support/recordings.hpp"

using elbowsim::Recording;
using elbowsim::testing::approx;
using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
namespace r = elbowsim::report;
namespace t = elbowsim::testing;
using t::check_images;
using t::check_links;
using t::sources;

namespace {

// One motor: 1 V into 2 A for 1 s; the elbow rests on [0.5, 1], 1e-8 m deep at
// the end (d = -1e-9 k while resting, 0.2 m before); other columns 0.
Recording small_recording() {
  Recording rec = t::zero_recording({1, true, false, true, {"elbow"}}, 11);
  const elbowsim::TrajectoryLayout& L = rec.layout;
  for (int k = 0; k <= 10; ++k) {
    t::set(rec, k, L.time(), 0.1 * k);
    t::set(rec, k, L.voltage(0), 1.0);
    t::set(rec, k, L.current(0), 2.0);
    t::set(rec, k, L.elbow_resting(0), k >= 5 ? 1.0 : 0.0);
    t::set(rec, k, L.elbow_distance(0), k >= 5 ? -1e-9 * k : 0.2);
  }
  return rec;
}

r::RunData run_with(const std::string& label, double e_in, bool completed = true) {
  r::RunData run;
  run.label = label;
  run.summary = {{"completed", completed},
                 {"failure", completed ? "" : "diverged"},
                 {"final_time", 1.0},
                 {"energy_final", {{"electrical_in", e_in}, {"joule", e_in / 2}}}};
  return run;
}

}  // namespace

TEST_CASE("columns: names through the layout, power, running integral, resting intervals") {
  const Recording rec = small_recording();
  CHECK(r::column_name(rec, rec.layout.current(0)) == "i0");
  CHECK(r::column_unit(rec, rec.layout.current(0)) == "A");
  CHECK(rec.layout.q(1) >= rec.layout.qd(0));  // one joint only: q1 is not a q column
  CHECK(rec.layout.groups().elbows == std::vector<std::string>{"elbow"});
  const auto power = r::electrical_power(rec);
  REQUIRE(power.size() == 11);
  CHECK(power[3] == 2.0);
  const auto time = r::column(rec, rec.layout.time());
  CHECK(approx(r::running_integral(time, power).back(), 2.0, 1e-12));
  const auto on = r::intervals_on(time, r::column(rec, rec.layout.elbow_resting(0)));
  REQUIRE(on.size() == 1);
  CHECK(approx(on[0].begin, 0.5, 1e-12));
  CHECK(approx(on[0].end, 1.0, 1e-12));
}

TEST_CASE("metrics: summary.json leaves in file order with units; trajectory figures") {
  const Json summary = Json::parse(R"({"steps": 5, "energy_final": {"joule": 1.5, "friction": null},
                                       "completed": false, "scenario": "x", "effects": ["a"],
                                       "metrics": {"current_peak": [0.5, 0.25]}})");
  const auto metrics = r::summary_metrics(summary);
  REQUIRE(metrics.size() == 6);
  CHECK(metrics[0].path == "steps");
  CHECK(metrics[1].path == "energy_final.joule");
  CHECK(metrics[1].unit == "J");
  CHECK(metrics[2].value.is_null());
  CHECK(metrics[3].path == "completed");
  CHECK(metrics[5].path == "metrics.current_peak.1");
  CHECK(metrics[5].unit == "A");

  // A run folder whose summary.json has no metrics: computed from its trajectory.
  r::RunData run;
  run.trajectory = small_recording();
  const auto derived = r::run_metrics(run);
  const auto value = [&](const std::string& path) {
    const r::Metric* m = r::find_metric(derived, path);
    REQUIRE_MESSAGE(m != nullptr, path);
    return m->value.get<double>();
  };
  CHECK(approx(value("metrics.current_rms.0"), 2.0, 1e-12));
  CHECK(approx(value("metrics.energy_in_per_joint.0"), 2.0, 1e-12));
  CHECK(approx(value("metrics.rest_fraction.elbow"), 0.5, 1e-12));
  CHECK(approx(value("metrics.elbow_drift_max.elbow"), 1e-8, 1e-20));
}

TEST_CASE("verdict: computed from the numbers") {
  SUBCASE("less energy, with the percentage of the other run's") {
    const auto c = r::compare_runs({run_with("on", 4.0), run_with("off", 5.0)});
    REQUIRE(c.verdict.size() == 2);
    CHECK(c.verdict[0] == "on: 20 % less net electrical energy than off (4 J vs 5 J).");
    CHECK(c.verdict[1].find("not compared") != std::string::npos);
  }
  SUBCASE("the lower run is named whichever comes first") {
    const auto c = r::compare_runs({run_with("a", 9.0), run_with("b", 3.0)});
    CHECK(c.verdict[0] == "b: 67 % less net electrical energy than a (3 J vs 9 J).");
  }
  SUBCASE("accuracy from summary.json's task metrics") {
    auto a = run_with("on", 2.0), b = run_with("off", 8.0);
    a.summary["metrics"] = {{"hand_error_rms", 1e-8}};
    b.summary["metrics"] = {{"hand_error_rms", 4e-8}};
    // The controller knows the plant and sees the true state: integration error, no verdict.
    const auto exact = r::compare_runs({a, b});
    REQUIRE(exact.verdict.size() == 2);
    CHECK(exact.verdict[0] == "on: 75 % less net electrical energy than off (2 J vs 8 J).");
    CHECK(exact.verdict[1].starts_with("Hand accuracy: no verdict."));
    CHECK(exact.verdict[1].find("integration error") != std::string::npos);
    CHECK(exact.verdict[1].find("on: 75 % smaller RMS hand error than off (10 nm vs 40 nm).") !=
          std::string::npos);
    // A controller that believes another plant: the difference, with its caveat.
    a.summary["controller_model"] = {"robot.planar.links[0].mass=1.1"};
    b.summary["control_loop"] = {{"sample_rate", 1000.0}};
    const auto c = r::compare_runs({a, b});
    REQUIRE(c.verdict.size() == 3);
    CHECK(c.verdict[1] == "on: 75 % smaller RMS hand error than off (10 nm vs 40 nm).");
    CHECK(c.verdict[2].find("no confidence interval") != std::string::npos);
  }
  SUBCASE("within the noise floor (0.1 % of the energy that flowed) is the same") {
    const auto c = r::compare_runs({run_with("a", 10.0), run_with("b", 10.009)});
    CHECK(c.verdict[0].find("the same net electrical energy within its noise floor") !=
          std::string::npos);
    const auto d = r::compare_runs({run_with("a", 10.0), run_with("b", 10.2)});
    CHECK(d.verdict[0] == "a: 2.0 % less net electrical energy than b (10 J vs 10.2 J).");
    // Above a smaller floor (the step check's: twice 1e-6 J) but under 0.05 %:
    // two significant digits, not "0.0 %".
    auto e = run_with("a", 10.0), f = run_with("b", 10.003);
    e.summary["step_check"]["metrics"]["energy_in"] = {{"value", 10.0}, {"at_half_step", 10.000001}};
    f.summary["step_check"]["metrics"]["energy_in"] = {{"value", 10.003}, {"at_half_step", 10.003001}};
    const auto tiny = r::compare_runs({e, f});
    CHECK(tiny.verdict[0] == "a: 0.03 % less net electrical energy than b (10 J vs 10.003 J).");
  }
  SUBCASE(
      "motors that feed back more than they draw: drawn energy as a percentage, net as a "
      "difference") {
    // The supply's energy is positive: the percentage is of it.
    auto on = run_with("on", -0.1), off = run_with("off", 15.5);
    on.summary["energy_final"]["drawn"] = 2.08;
    off.summary["energy_final"]["drawn"] = 15.9;
    CHECK(r::compare_runs({on, off}).verdict[0] ==
          "on: 87 % less electrical energy drawn from the supply than off (2.08 J vs 15.9 J).");
    // Without the drawn energy, a net energy of either sign is compared in J:
    // never "112 % less" (4.5 J of 4 J).
    CHECK(r::compare_runs({run_with("on", -0.5), run_with("off", 4.0)}).verdict[0] ==
          "on: 4.5 J less net electrical energy than off (-500 mJ vs 4 J).");
    CHECK(r::compare_runs({run_with("on", -0.5), run_with("off", -2.0)}).verdict[0] ==
          "off: 1.5 J less net electrical energy than on (-2 J vs -500 mJ).");
    // A run that drew nothing: no percentage of the drawn energy, the net in J.
    off.summary["energy_final"]["drawn"] = 0.0;
    CHECK(r::compare_runs({on, off}).verdict[0] ==
          "on: 15.6 J less net electrical energy than off (-100 mJ vs 15.5 J).");
  }
  SUBCASE("no energy at all") {
    const auto c = r::compare_runs({run_with("a", 0.0), run_with("b", 0.0)});
    CHECK(c.verdict[0].find("No run drew electrical energy") == 0);
  }
  SUBCASE("a failed run is named first") {
    const auto c = r::compare_runs({run_with("a", 1.0), run_with("b", 2.0, false)});
    CHECK(c.verdict[0].find("b did not complete (diverged)") == 0);
  }
  SUBCASE("relative differences are to the first run") {
    const auto c = r::compare_runs({run_with("a", 4.0), run_with("b", 5.0)});
    // Numbers only (the flag "completed" is per run): final_time, then energy_final.electrical_in.
    const auto& row = c.metrics[1];
    REQUIRE(row.path == "energy_final.electrical_in");
    CHECK(approx(*row.relative[1], 0.25, 1e-12));
    CHECK(r::comparison_json(c)["metrics"][1]["relative"]["b"] == 0.25);
    CHECK(r::comparison_json(c)["completed"]["a"] == true);
  }
  CHECK(r::unique_labels({"run", "x", "run"}) == std::vector<std::string>{"run", "x", "run_2"});
}

// ---- run folders and the HTML ----------------------------------------------

namespace {

const std::string kScenes = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/";

struct Cell {
  std::string metric, value, shown;
};

// The metrics table's cells: data-metric, data-value and the text shown.
std::vector<Cell> table_cells(const std::string& html, const std::string& id) {
  const auto start = html.find("<table id=\"" + id + "\"");
  REQUIRE(start != std::string::npos);
  const std::string table = html.substr(start, html.find("</table>", start) - start);
  static const std::regex cell("data-metric=\"([^\"]*)\" data-value=\"([^\"]*)\">([^<]*)</td>");
  std::vector<Cell> cells;
  for (auto it = std::sregex_iterator(table.begin(), table.end(), cell);
       it != std::sregex_iterator(); ++it)
    cells.push_back({(*it)[1], (*it)[2], (*it)[3]});
  return cells;
}

// summary.json's numbers and flags by dotted path (list entries by index).
void flatten(const Json& node, const std::string& path, std::map<std::string, Json>& out) {
  if (node.is_object() || node.is_array())
    for (const auto& [key, value] : node.items())
      flatten(value, path.empty() ? key : path + "." + key, out);
  else if (node.is_number() || node.is_boolean() || node.is_null())
    out[path] = node;
}

}  // namespace

TEST_CASE("report.html: metrics equal summary.json; every image resolves and decodes") {
  const auto dir = t::scratch("report", "run");
  const auto run = dir / "elbow_rest";
  const auto out = t::run_elbowsim("run " + kScenes + "elbow_rest.yaml --out " + run.string() +
                                   " --no-render --set simulation.duration=0.5");
  REQUIRE(out.exit_code == 0);
  CHECK(out.output.find("report: ") != std::string::npos);
  const std::string html = t::slurp(run / "report.html");
  REQUIRE(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(html.find("<h1>elbow_rest</h1>") != std::string::npos);
  CHECK(html.find("rk4, step 0.001 s, duration 0.5 s") != std::string::npos);
  CHECK(html.find("stabilization:baumgarte") != std::string::npos);

  // The metrics table: exactly summary.json's numbers and flags, in its order.
  std::map<std::string, Json> expected;
  flatten(Json::parse(t::slurp(run / "summary.json")), "", expected);
  const auto cells = table_cells(html, "metrics");
  CHECK(cells.size() == expected.size());
  std::set<std::string> seen;
  for (const Cell& c : cells) {
    INFO(c.metric);
    REQUIRE(expected.count(c.metric));
    seen.insert(c.metric);
    const Json& want = expected[c.metric];
    if (want.is_boolean()) {
      CHECK(c.value == (want.get<bool>() ? "true" : "false"));
    } else if (want.is_number()) {
      CHECK(std::stod(c.value) == want.get<double>());  // exact: round-trip digits
      CHECK(approx(std::stod(c.shown), want.get<double>(), 1e-300, 5e-6));
    }
  }
  CHECK(seen.size() == expected.size());
  // Plots: joint angles, hand, motors, power, energy, contact, residuals.
  check_images(run, html, 10);
  check_links(run, html);
  for (const char* name :
       {"joint_angles", "contact_forces", "constraint_residual", "energy_balance"})
    CHECK(html.find(std::string("plots/") + name + ".png") != std::string::npos);
  CHECK(sources(html, "video").empty());  // no video.mp4 in this folder
}

TEST_CASE("report: rebuilt from the folder alone; the video is embedded when the run made it") {
  const auto dir = t::scratch("report", "rebuild");
  const auto run = dir / "r";
  REQUIRE(t::run_elbowsim("run " + kScenes + "default.yaml --out " + run.string() +
                          " --no-render --no-report --set simulation.duration=0.3")
              .exit_code == 0);
  CHECK_FALSE(fs::exists(run / "report.html"));  // --no-report
  // A video put there by hand is not this run's: not embedded.
  std::ofstream(run / "video.mp4") << "not really a video";
  REQUIRE(t::run_elbowsim("report " + run.string()).exit_code == 0);
  CHECK(sources(t::slurp(run / "report.html"), "video").empty());
  // One the manifest lists (as `elbowsim render` adds it) is.
  std::string manifest = t::slurp(run / "manifest.json");
  manifest.replace(manifest.find("\"summary.json\""), 14, "\"summary.json\", \"video.mp4\"");
  std::ofstream(run / "manifest.json") << manifest;
  const auto out = t::run_elbowsim("report " + run.string());
  REQUIRE(out.exit_code == 0);
  const std::string html = t::slurp(run / "report.html");
  REQUIRE(sources(html, "video") == std::vector<std::string>{"video.mp4"});
  check_links(run, html);
  check_images(run, html, 8);
  // No contact in this scene: the contact plots are listed as not plotted, not drawn.
  CHECK(html.find("plots/contact_forces.png") == std::string::npos);
  CHECK(html.find("contact_forces: no elbow columns") != std::string::npos);
}

TEST_CASE("report: a run that failed says why, at the top") {
  const auto dir = t::scratch("report", "failed");
  const auto run = dir / "diverged";
  const auto out =
      t::run_elbowsim("run " + kScenes + "default.yaml --out " + run.string() +
                      " --no-render --set simulation.step=0.05 --set simulation.integrator=euler");
  REQUIRE(out.exit_code == 3);
  const std::string html = t::slurp(run / "report.html");
  const auto failure = html.find("<div class=\"failure\" id=\"failure\"");
  REQUIRE(failure != std::string::npos);
  CHECK(failure < html.find("<section id=\"run\">"));
  const Json summary = Json::parse(t::slurp(run / "summary.json"));
  CHECK(html.find(summary["failure"].get<std::string>().substr(0, 40)) != std::string::npos);
  CHECK(html.find("STOPPED EARLY") != std::string::npos);
  check_images(run, html, 1);
}

TEST_CASE("report: missing files are reported, a non-folder is bad input") {
  const auto dir = t::scratch("report", "missing");
  CHECK(t::run_elbowsim("report " + (dir / "nothing").string()).exit_code == 2);
  CHECK(t::run_elbowsim("report " + dir.string()).exit_code == 2);  // no summary, no trajectory
  REQUIRE(t::run_elbowsim("run " + kScenes + "default.yaml --out " + (dir / "r").string() +
                          " --no-render --no-report --set simulation.duration=0.1")
              .exit_code == 0);
  fs::remove(dir / "r" / "trajectory.csv");
  REQUIRE(t::run_elbowsim("report " + (dir / "r").string()).exit_code == 0);
  const std::string html = t::slurp(dir / "r" / "report.html");
  CHECK(html.find("trajectory.csv: not in the run folder") != std::string::npos);
  CHECK(table_cells(html, "metrics").size() > 10);
}

TEST_CASE("compare: names every run, a computed verdict, hand paths, energy terms, overlays") {
  const auto dir = t::scratch("report", "compare");
  const std::string args = " --no-render --no-report --set simulation.duration=0.5";
  REQUIRE(t::run_elbowsim("run " + kScenes + "elbow_rest.yaml --out " +
                          (dir / "elbow-on").string() + args)
              .exit_code == 0);
  REQUIRE(t::run_elbowsim("run " + kScenes + "elbow_rest.yaml --out " +
                          (dir / "elbow-off").string() + args +
                          " --set 'inputs.voltage[0].offset=4.86'")
              .exit_code == 0);
  const auto out = t::run_elbowsim("compare " + (dir / "elbow-on").string() + " " +
                                   (dir / "elbow-off").string());
  REQUIRE(out.exit_code == 0);
  const auto folder = dir / "compare";  // default: beside the first run
  const std::string html = t::slurp(folder / "report.html");
  for (const char* label : {"elbow-on", "elbow-off"}) {
    CHECK(html.find(std::string("<th>") + label + "</th>") != std::string::npos);
    CHECK(html.find(std::string("data-run=\"") + label + "\"") != std::string::npos);
  }
  // The verdict's percentage follows from the two summaries: of the energy
  // drawn from the supply.
  const auto drawn = [&](const char* run) {
    return Json::parse(t::slurp(dir / run / "summary.json"))["energy_final"]["drawn"].get<double>();
  };
  const double on = drawn("elbow-on"), off = drawn("elbow-off");
  REQUIRE(on > 0);
  REQUIRE(on < off);
  char sentence[128];
  std::snprintf(sentence, sizeof sentence,
                "elbow-on: %.0f %% less electrical energy drawn from the supply than elbow-off",
                100 * (off - on) / off);
  CHECK(out.output.find(sentence) != std::string::npos);
  CHECK(html.find(sentence) != std::string::npos);
  const Json json = Json::parse(t::slurp(folder / "comparison.json"));
  CHECK(json["runs"] == Json::array({"elbow-on", "elbow-off"}));
  CHECK(json["verdict"][0].get<std::string>().find(sentence) == 0);
  check_images(folder, html, 4);
  check_links(folder, html);  // links to each run's report.html
  for (const char* png : {"plots/hand_path.png", "plots/energy_terms.png", "plots/energy.png"})
    CHECK(html.find(png) != std::string::npos);
  // Comparing one folder is a usage error.
  CHECK(t::run_elbowsim("compare " + (dir / "elbow-on").string()).exit_code == 2);
}

TEST_CASE(
    "a report is all or nothing: a failed one leaves the earlier plots, a kept one only its own") {
  const fs::path folder = t::scratch("report", "plots_aside");
  auto write = [](const fs::path& file, const std::string& text) { std::ofstream(file) << text; };
  auto listing = [&] {
    std::set<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(folder))
      names.insert(fs::relative(e.path(), folder).generic_string());
    return names;
  };
  fs::create_directories(folder / "plots");
  write(folder / "plots" / "old.png", "old");
  write(folder / "report.html", "old report");
  const std::set<std::string> before = listing();

  // Fails after its first plot: the earlier plots come back, the new one goes.
  try {
    r::PlotsAside aside(folder);
    CHECK_FALSE(fs::exists(folder / "plots"));
    fs::create_directories(folder / "plots");
    write(folder / "plots" / "new.png", "new");
    throw std::runtime_error("disk full");
  } catch (const std::runtime_error&) {
  }
  CHECK(listing() == before);
  CHECK(t::slurp(folder / "plots" / "old.png") == "old");

  // A plots.old left by a process that died mid-report is put back first.
  fs::rename(folder / "plots", folder / "plots.old");
  fs::create_directories(folder / "plots");
  write(folder / "plots" / "half.png", "half");
  {
    r::PlotsAside aside(folder);
    fs::create_directories(folder / "plots");
    write(folder / "plots" / "new.png", "new");
    aside.keep();
  }
  CHECK(listing() == std::set<std::string>{"plots", "plots/new.png", "report.html"});
}

TEST_CASE("summary_keys: each key once, with a unit of the fixed set; name and pointer") {
  namespace key = elbowsim::summary_key;
  const std::set<std::string> units{"",   "1", "state", "metric", "s", "m",  "m/s",
                                    "kg", "J", "N",     "A",      "W", "Hz", "rad", "V/rad", "V s/rad", "V/(rad s)", "kg m^2"};
  std::set<std::string> paths;
  for (const elbowsim::SummaryKey& k : key::kAll) {
    CAPTURE(k.path);
    CHECK(paths.insert(std::string(k.path)).second);  // no path twice
    CHECK(units.count(std::string(k.unit)) == 1);
  }
  CHECK(key::contact_max_abs_C.name() == "max_abs_C");
  CHECK(key::final_time.name() == "final_time");
  CHECK(key::contact_max_abs_C.pointer() == "/contact/max_abs_C");
  CHECK(key::metric_path(elbowsim::metric::joule) == "metrics.joule");
  CHECK(key::metric_of("metrics.current_rms.2") == "current_rms");
  CHECK(key::metric_of("metrics").empty());
  CHECK(key::metric_of("metricsx.joule").empty());
  CHECK(key::checked_metric_path("joule") == "step_check.metrics.joule");
}

TEST_CASE("summary_keys: the units of the pattern table the schema replaced, path by path") {
  // Independent of the schema: the table report/summary_units.cpp held before
  // it (one path per pattern, "*" filled in), and the metrics' paths.
  const std::pair<const char*, const char*> before[] = {
      {"model.dof", "1"},
      {"model.total_mass", "kg"},
      {"model.hand_link", "1"},
      {"settings.step", "s"},
      {"settings.duration", "s"},
      {"settings.rtol", "1"},
      {"settings.atol", "state"},
      {"settings.max_step", "s"},
      {"steps", "1"},
      {"integrator_work.evaluations", "1"},
      {"integrator_work.rejected_steps", "1"},
      {"integrator_work.jacobians", "1"},
      {"integrator_work.factorisations", "1"},
      {"final_time", "s"},
      {"wall_seconds", "s"},
      {"energy_initial.potential", "J"},
      {"energy_final.joule", "J"},
      {"balance_residual", "J"},
      {"max_abs_balance_residual", "J"},
      {"balance_residual_relative", "1"},
      {"control_loop.sample_rate", "Hz"},
      {"control_loop.delay_samples", "1"},
      {"control_loop.pwm_bits", "1"},
      {"control_loop.encoder_counts_per_rev", "1"},
      {"control_loop.angle_noise", "rad"},
      {"control_loop.velocity_cutoff", "Hz"},
      {"control_loop.noise_seed", "1"},
      {"contact.collision_worlds_built", "1"},
      {"contact.elbows", "1"},
      {"contact.landings", "1"},
      {"contact.releases", "1"},
      {"contact.sticks", "1"},
      {"contact.slips", "1"},
      {"contact.max_abs_C", "m"},
      {"contact.max_abs_Jc_qd", "m/s"},
      {"contact.dependent_steps", "1"},
      {"contact.bodies.left.link", "1"},
      {"contact.bodies.left.rest_fraction", "1"},
      {"contact.bodies.left.force_mean", "N"},
      {"contact.bodies.link2.force_peak", "N"},
      {"contact.bodies.left.friction_work", "J"},
      {"contact.bodies.left.landings", "1"},
      {"contact.bodies.left.releases", "1"},
      {"contact.bodies.left.sticks", "1"},
      {"contact.bodies.left.slips", "1"},
      {"saturation_share.0", "1"},
      {"saturation_share.3", "1"},
      {"step_check.step", "s"},
      {"step_check.half_step", "s"},
      {"step_check.metrics.joule.relative_change", "1"},
      {"step_check.metrics.hand_error_rms.value", "m"},
      {"step_check.metrics.current_rms.at_half_step", "A"},
      {"step_check.metrics.power_peak.floor", "W"},
      {"metrics.time_in_contact", "s"},
      {"metrics.energy_in_per_joint.1", "J"},
      {"metrics.elbow_drift_max.left", "m"},
      {"metrics.samples", "1"}};
  for (const auto& [path, unit] : before) {
    CAPTURE(path);
    CHECK(r::summary_unit(path) == unit);
  }
  // Not numbers, or not keys: no unit.
  for (const char* path : {"scenario", "settings.integrator", "contact.bodies.left.kind",
                           "step_check.metrics.joule.unit", "step_check.metrics.joule.below_floor",
                           "control_loop", "contact", "metrics.no_such_metric", "steps.0",
                           "step_check.metrics.joule.colour", "contact.max_abs_C.0.1"})
    CHECK_MESSAGE(r::summary_unit(path).empty(), path);
}

TEST_CASE("summary_units: every number's unit from one table; a key without one is an error") {
  CHECK(r::summary_unit("final_time") == "s");
  CHECK(r::summary_unit("energy_final.gear_loss") == "J");
  CHECK(r::summary_unit("metrics.hand_error_rms") == "m");
  CHECK(r::summary_unit("metrics.current_peak.1") == "A");      // a joint's element
  CHECK(r::summary_unit("metrics.rest_fraction.elbow") == "1");  // a share: a pure number
  CHECK(r::summary_unit("metrics.samples") == "1");
  CHECK(r::summary_unit("contact.bodies.link3.force_peak") == "N");
  CHECK(r::summary_unit("step_check.metrics.joule.floor") == "J");
  CHECK(r::summary_unit("step_check.metrics.joule.relative_change") == "1");
  CHECK(r::summary_unit("metrics.no_such_metric").empty());
  CHECK(r::summary_unit("contact.bodies.link3.colour").empty());
  CHECK(r::metric_unit("metrics.rest_fraction.elbow").empty());  // reports show no "1"
  CHECK(r::metric_unit("contact.max_abs_Jc_qd") == "m/s");

  const Json summary = Json::parse(R"({"provenance": {"program": "elbowsim"}, "scenario": "s",
      "final_time": 1.5, "valid": true, "metrics": {"current_rms": [0.5, 0.25],
      "rest_fraction": {"elbow": 0.9}}, "contact": {"bodies": {"elbow": {"kind": "elbow",
      "force_mean": 3.0}}}, "warnings": []})");
  const Json units = r::units_json(summary);
  CHECK(units == Json::parse(R"({"final_time": "s", "metrics.current_rms": "A",
      "metrics.rest_fraction.elbow": "1", "contact.bodies.elbow.force_mean": "N"})"));
  const Json written = r::with_units(summary);
  REQUIRE(written.size() == summary.size() + 1);
  auto key = written.begin();
  CHECK(key.key() == "provenance");
  CHECK((++key).key() == "units");
  CHECK((++key).key() == "scenario");

  Json grown = summary;
  grown["contact"]["bodies"]["elbow"]["stiffness"] = 1e5;  // a key added without its unit
  CHECK_THROWS_WITH_AS(r::units_json(grown),
                       doctest::Contains("contact.bodies.elbow.stiffness"), std::logic_error);
}
