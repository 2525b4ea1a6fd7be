// Reports that lead with the answer, and run folders without stale
// artefacts: the first section of a run report holds the headline numbers
// (with units, validity, warnings above them); the lead figures come next;
// a comparison shows differences below their noise floor as "same"; a rerun
// with --no-render leaves no video behind and names none; the compare report
// embeds the side-by-side video only when this run made it.
#include <doctest/doctest.h>

#include <regex>

#include "engine/recording/number_text.hpp"
#include "report/comparison.hpp"
#include "report/energy_flow.hpp"
#include "report_test_helpers.hpp"
#include "support/approx.hpp"

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
namespace r = elbowsim::report;
namespace t = elbowsim::testing;

namespace {

const std::string kScenes = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/";

// The text of <section id="id"> ... </section>; empty when there is none.
std::string section(const std::string& html, const std::string& id) {
  const auto start = html.find("<section id=\"" + id + "\">");
  if (start == std::string::npos) return "";
  return html.substr(start, html.find("</section>", start) - start);
}

// The value cell of the headline row for `metric`.
std::string headline_cell(const std::string& headline, const std::string& metric) {
  std::smatch m;
  const std::regex row("<tr data-metric=\"" + std::regex_replace(metric, std::regex("\\."), "\\.") +
                       "\"><th scope=\"row\">[^<]*</th><td class=\"value[^\"]*\">([^<]*)</td>");
  return std::regex_search(headline, m, row) ? m[1].str() : "";
}

// The difference cells (the "... vs ..." column) of a comparison table.
std::vector<std::string> difference_cells(const std::string& html, const std::string& id) {
  const auto start = html.find("<table id=\"" + id + "\"");
  if (start == std::string::npos) return {};
  const std::string table = html.substr(start, html.find("</table>", start) - start);
  static const std::regex cell("<td class=\"num (same|differs)\">([^<]*)</td>");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(table.begin(), table.end(), cell);
       it != std::sregex_iterator(); ++it)
    out.push_back((*it)[2]);
  return out;
}

Json summary_of(const fs::path& folder) { return Json::parse(t::slurp(folder / "summary.json")); }

}  // namespace

TEST_CASE("run report: the first section states the headline numbers, warnings above them") {
  const auto dir = t::scratch("report_lead", "headline");
  // A rating far below the current the joint needs: a warning in summary.json.
  const auto out =
      t::run_elbowsim("run " + kScenes + "elbow_experiment.yaml --out " + dir.string() +
                      " --no-render --set simulation.duration=0.5"
                      " --set 'motors.joints[2].rated_current=0.01'");
  REQUIRE(out.exit_code == 0);
  const fs::path run = dir / "elbow_on";
  const std::string html = t::slurp(run / "report.html");
  const Json s = summary_of(run);
  REQUIRE(!s["warnings"].empty());

  // Order: title, warnings, the headline section, then the lead figures, then the rest.
  const auto warnings = html.find("id=\"warnings\"");
  const auto headline = html.find("<section id=\"headline\">");
  REQUIRE(warnings != std::string::npos);
  REQUIRE(headline != std::string::npos);
  CHECK(html.find("<section") == headline);  // the first section
  CHECK(warnings < headline);
  CHECK(html.find(s["warnings"][0].get<std::string>().substr(0, 30)) < headline);
  CHECK(headline < html.find("<section id=\"hand-path\">"));
  CHECK(html.find("<section id=\"hand-path\">") < html.find("<section id=\"energy\">"));
  CHECK(html.find("<section id=\"energy\">") < html.find("<section id=\"plots\">"));
  CHECK(html.find("<section id=\"plots\">") < html.find("<section id=\"run\">"));
  CHECK(html.find("<h1>elbow_experiment · elbow_on</h1>") != std::string::npos);  // the variant

  // The headline numbers: summary.json's, with their units, and the validity.
  const std::string lead = section(html, "headline");
  CHECK(headline_cell(lead, "valid") == "valid");
  const auto m = s["metrics"];
  CHECK(headline_cell(lead, "metrics.hand_error_rms") ==
        elbowsim::quantity(m["hand_error_rms"].get<double>(), "m"));
  CHECK(headline_cell(lead, "metrics.hand_error_max") ==
        elbowsim::quantity(m["hand_error_max"].get<double>(), "m"));
  CHECK(headline_cell(lead, "energy_final.joule") ==
        elbowsim::quantity(s["energy_final"]["joule"].get<double>(), "J"));
  CHECK(headline_cell(lead, "energy_final.electrical_in")
            .starts_with(elbowsim::quantity(s["energy_final"]["electrical_in"].get<double>(), "J") +
                         " (drawn "));
  CHECK(headline_cell(lead, "metrics.power_peak") ==
        elbowsim::quantity(m["power_peak"].get<double>(), "W"));
  CHECK(headline_cell(lead, "metrics.rest_fraction") == "100 % of the run");
  CHECK(lead.find("accuracy check") != std::string::npos);

  // The lead figures: the hand path in x–z (and magnified), the energy waterfall.
  for (const char* png :
       {"plots/hand_path.png", "plots/hand_path_error.png", "plots/energy_flow.png"})
    CHECK(section(html, png == std::string("plots/energy_flow.png") ? "energy" : "hand-path")
              .find(png) != std::string::npos);
  t::check_images(run, html, 12);
  // Titles carry the variant.
  CHECK(html.find("alt=\"Joint angles — elbow_experiment · elbow_on\"") != std::string::npos);
  const std::string off = t::slurp(dir / "elbow_off" / "report.html");
  CHECK(off.find("alt=\"Joint angles — elbow_experiment · elbow_off\"") != std::string::npos);
  // The energy section explains E_in, and why the Joule loss exceeds it when it does.
  const std::string energy = section(html, "energy");
  CHECK(energy.find("E_in = drawn − regenerated") != std::string::npos);
  CHECK((energy.find("exceeds the electrical energy in") != std::string::npos) ==
        (s["energy_final"]["joule"].get<double>() >
         s["energy_final"]["electrical_in"].get<double>()));
}

TEST_CASE("compare: two identical runs show every metric as the same, timing as timing") {
  const auto dir = t::scratch("report_lead", "identical");
  for (const char* name : {"a", "b"})
    REQUIRE(t::run_elbowsim("run " + kScenes + "elbow_rest.yaml --out " + (dir / name).string() +
                            " --no-render --no-report --set simulation.duration=0.3")
                .exit_code == 0);
  REQUIRE(t::run_elbowsim("compare " + (dir / "a").string() + " " + (dir / "b").string() +
                          " --out " + (dir / "ab").string())
              .exit_code == 0);
  const std::string html = t::slurp(dir / "ab" / "report.html");
  std::size_t rows = 0;
  for (const char* id :
       {"comparison-metrics", "comparison-numerics", "comparison-settings", "headline-table"})
    for (const std::string& cell : difference_cells(html, id)) {
      INFO(id << ": " << cell);
      CHECK(cell == "same");
      ++rows;
    }
  CHECK(rows > 40);
  // Timings are a table of their own, never a percentage.
  const auto timing = difference_cells(html, "comparison-timing");
  CHECK(timing.size() >= 3);
  for (const std::string& cell : timing) {
    INFO(cell);
    CHECK(cell.find('%') == std::string::npos);
  }
  const Json json = Json::parse(t::slurp(dir / "ab" / "comparison.json"));
  for (const Json& m : json["metrics"])
    if (m["kind"] != "timing") CHECK_MESSAGE(m["same"] == true, m["path"]);
}

TEST_CASE("noise floor: a difference of noise is the same, a real one is not") {
  // Two runs that moved joules: a kinetic energy of 1e-21 against 2e-19 J is noise.
  const auto run = [](const std::string& label, double drawn, double kinetic) {
    r::RunData data;
    data.label = label;
    data.summary = {{"completed", true},
                    {"valid", true},
                    {"wall_seconds", label == "a" ? 1.0 : 1.07},
                    {"energy_initial", {{"potential", 1.8}}},
                    {"energy_final",
                     {{"electrical_in", drawn - 0.05},
                      {"joule", drawn},
                      {"kinetic_links", kinetic},
                      {"potential", 1.6},
                      {"drawn", drawn},
                      {"regenerated", 0.05}}},
                    {"balance_residual", 0.0}};
    return data;
  };
  const auto c = r::compare_runs({run("a", 1.86, 2.5e-21), run("b", 15.8, 1.8e-19)});
  const auto row = [&](const std::string& path) -> const r::ComparedMetric& {
    for (const auto& m : c.metrics)
      if (m.path == path) return m;
    FAIL("no row " << path);
    return c.metrics.front();
  };
  CHECK(row("energy_final.kinetic_links").same);
  CHECK(row("energy_final.kinetic_links").floor.value > 1e-3);  // 0.1 % of the 16 J that flowed
  CHECK_FALSE(row("energy_final.electrical_in").same);
  CHECK(row("wall_seconds").kind == r::MetricKind::timing);
  CHECK(row("wall_seconds").same);  // 7 %: timing noise, not a result
  // With --check-step in both summaries the accuracy floor replaces the relative one.
  auto a = run("a", 1.86, 0), b = run("b", 1.87, 0);
  for (auto* x : {&a, &b})
    x->summary["step_check"] = {
        {"metrics", {{"energy_in", {{"value", 1.0}, {"at_half_step", 1.001}}}}}};
  const auto d = r::compare_runs({a, b});
  for (const auto& m : d.metrics)
    if (m.path == "energy_final.electrical_in") {
      CHECK(elbowsim::testing::approx(m.floor.value, 0.002, 1e-12));
      CHECK(m.floor.basis.find("half the step") != std::string::npos);
      CHECK_FALSE(m.same);  // 10 mJ apart, above the 2 mJ floor
    }
}

TEST_CASE("energy flow: every joule booked; Joule above the energy in is explained") {
  Json s = {{"energy_initial", {{"potential", 1.8}, {"magnetic", 0.0}}},
            {"energy_final",
             {{"electrical_in", 1.8},
              {"drawn", 1.85},
              {"regenerated", 0.05},
              {"joule", 2.0},
              {"viscous", 0.02},
              {"potential", 1.6},
              {"magnetic", 0.0},
              {"friction", 0.0},
              {"impact_loss", 0.0}}},
            {"contact", {{"enabled", true}}},
            {"balance_residual", -0.02}};
  const auto flow = r::energy_flow(s);
  REQUIRE(flow);
  CHECK(elbowsim::testing::approx(flow->total_in, 1.85 + 0.2, 1e-12));
  CHECK(flow->in[0].key == "drawn");
  CHECK(flow->out[0].key == "regenerated");
  double out = 0;
  for (const auto& term : flow->out) out += term.value;
  CHECK(elbowsim::testing::approx(flow->total_in - out, flow->residual, 1e-12));  // closes
  const auto notes = r::energy_flow_notes(*flow);
  REQUIRE(notes.size() >= 2);
  CHECK(notes[1].find("potential energy given up (200 mJ)") != std::string::npos);
  // A hand force's work is not in summary.json: inferred from the residual.
  s["balance_residual"] = 0.5;
  CHECK(r::energy_flow(s)->term("external") > 0.49);
}

TEST_CASE("rerun with --no-render: no video left behind, none named; compare/ likewise") {
  const auto dir = t::scratch("report_lead", "stale");
  // Rendered small and short: each variant's video, and the side-by-side one.
  const std::string run_args = "run " + kScenes + "elbow_experiment.yaml --out " + dir.string() +
                               " --set simulation.duration=0.3 --set 'render.size=[160, 120]'"
                               " --set render.fps=10";
  const auto rendered = t::run_elbowsim(run_args);
  INFO(rendered.output);
  REQUIRE(rendered.exit_code == 0);
  const fs::path run = dir / "elbow_on", compare = dir / "compare";
  REQUIRE(fs::exists(run / "video.mp4"));
  REQUIRE(fs::exists(compare / "video.mp4"));
  CHECK(t::slurp(run / "manifest.json").find("\"video.mp4\"") != std::string::npos);
  CHECK(t::sources(t::slurp(run / "report.html"), "video") ==
        std::vector<std::string>{"video.mp4"});
  // The compare report embeds the side-by-side video this run made.
  const std::string with_video = t::slurp(compare / "report.html");
  CHECK(t::sources(with_video, "video") == std::vector<std::string>{"video.mp4"});
  CHECK(with_video.find("<section id=\"video\">") <
        with_video.find("<section id=\"runs-section\">"));
  // Frames an earlier run wrote (output.frames) are stale too.
  fs::create_directories(run / "frames");
  std::ofstream(run / "frames" / "frame_00000.png") << "a frame of an earlier run";

  REQUIRE(t::run_elbowsim(run_args + " --no-render").exit_code == 0);
  CHECK_FALSE(fs::exists(run / "video.mp4"));
  CHECK_FALSE(fs::exists(run / "frames"));
  CHECK_FALSE(fs::exists(compare / "video.mp4"));
  for (const fs::path& page : {run / "report.html", compare / "report.html"}) {
    const std::string html = t::slurp(page);
    INFO(page.string());
    CHECK(html.find("video.mp4") == std::string::npos);
    CHECK(html.find("<video") == std::string::npos);
  }
  CHECK(t::slurp(run / "manifest.json").find("video") == std::string::npos);
  // A video put in by hand is not the run's: `elbowsim report` does not embed it.
  std::ofstream(run / "video.mp4") << "not this run's";
  REQUIRE(t::run_elbowsim("report " + run.string()).exit_code == 0);
  CHECK(t::slurp(run / "report.html").find("<video") == std::string::npos);
}
