// A scenario's study: section (axes of named levels), its cases (one level of
// each axis) and `elbowsim montecarlo` over them: every case in its own
// folder, study.json / study.csv / report.html over the cases, the same bytes
// whatever --jobs, and --case selecting cases.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "app/study/cases.hpp"
#include "app/study/draws.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"
#include "test_scenario_helpers.hpp"

namespace fs = std::filesystem;
using namespace scenario_test;

namespace {

// The two-link arm holding its hand under a 1 kHz loop with noisy sensors;
// two variants, a 2 x 2 study.
const std::string kStudy = two_link_with(R"(
task: {path: hold}
controller: {type: pd_feedforward, sample_rate: 1000, sensors: {noise: 1.0e-5, seed: 5}}
uncertainty:
  seed: 3
  parameters:
    robot.planar.links[*].mass: {uniform: 0.1}
variants:
  light: {}
  heavy: {hand_load.mass: 0.2}
study:
  axes:
    pose:
      low: {}
      high: {initial.q: [0.5, 0.3]}
    time:
      short: {simulation.duration: 0.3}
      long: {}
)");

std::string case_error(const std::vector<std::string>& levels, const std::string& variant = "") {
  try {
    elbowsim::load_scenario_case_text(kStudy, "x.yaml", levels, variant);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

TEST_CASE("study: axes and levels in file order; a case applies its levels, then the variant") {
  const Scenario s = load(kStudy);
  REQUIRE(s.study.size() == 2);
  CHECK(s.study[0].name == "pose");
  CHECK(s.study[1].name == "time");
  REQUIRE(s.study[0].levels.size() == 2);
  CHECK(s.study[0].levels[0].first == "low");
  CHECK(s.study[0].levels[0].second.empty());
  CHECK(s.study[0].levels[1].second == std::vector<std::string>{"initial.q=[0.5, 0.3]"});
  CHECK(s.model.options.duration == 1.0);  // the file's own values: no level applied
  CHECK(s.study_case.empty());

  const Scenario c = elbowsim::load_scenario_case_text(kStudy, "x.yaml", {"high", "short"}, "heavy");
  CHECK(approx(c.model.initial.q, Eigen::Vector2d(0.5, 0.3)));
  CHECK(c.model.options.duration == 0.3);
  CHECK(c.model.hand_load.mass == 0.2);
  CHECK(c.study.empty());     // a case has no study
  CHECK(c.variants.empty());  // nor, with a variant, variants
  CHECK(c.study_case == std::vector<std::string>{"high", "short"});
  CHECK(c.variant == "heavy");
  CHECK_FALSE(contains(c.resolved_yaml, "study"));  // its scenario.yaml stands alone

  // A variant applies after the levels: it wins where both set a key.
  const Scenario later = elbowsim::load_scenario_case_text(
      two_link_with(R"(
variants: {v: {simulation.duration: 0.7}}
study: {axes: {time: {short: {simulation.duration: 0.3}}}}
)"),
      "x.yaml", {"short"}, "v");
  CHECK(later.model.options.duration == 0.7);
}

TEST_CASE("study errors: names, structure, levels that change the study, bad values, unknown levels") {
  CHECK_ERROR(two_link_with("study: {axes: {speed: {fast-ish: {}}}}\n"), "x.yaml:9:",
              "study.axes.speed.fast-ish", "a study level name must be letters, digits, _ only");
  CHECK_ERROR(two_link_with("study: {axes: {my-axis: {a: {}}}}\n"), "x.yaml:9:", "study.axes.my-axis",
              "a study axis name must be letters, digits, _ only");
  CHECK_ERROR(two_link_with("study: {axes: {speed: {a: {study.axes: 1}}}}\n"), "x.yaml:9:",
              "study.axes.speed.a.study.axes", "a study level cannot change study");
  CHECK_ERROR(two_link_with("study: {axes: {speed: {}}}\n"), "x.yaml:9:", "study.axes.speed",
              "needs at least one study level");
  CHECK_ERROR(two_link_with("study: {axes: [1, 2]}\n"), "x.yaml:9:", "study.axes", "expected a map of axes");
  CHECK_ERROR(two_link_with("study: {levels: {}}\n"), "x.yaml:9:", "study.levels", "allowed here: axes");
  CHECK_ERROR(two_link_with("variants: {a: {study.axes: 1}}\n"), "x.yaml:9:", "variants.a.study.axes",
              "a variant cannot change study");
  // A level's bad value is reported at the level's entry, naming the case,
  // when the case is loaded (montecarlo, validate); a run ignores the study.
  const std::string broken = two_link_with(R"(
study:
  axes:
    time:
      short: {simulation.duration: 0.3}
      broken: {simulation.duration: -1}
)");
  CHECK(error_of(broken).empty());
  std::string bad;
  try {
    elbowsim::load_scenario_case_text(broken, "x.yaml", {"broken"}, "");
  } catch (const ScenarioError& e) {
    bad = e.what();
  }
  INFO(bad);
  CHECK(bad.starts_with("x.yaml:13:"));
  CHECK(contains(bad, "simulation.duration"));
  CHECK(contains(bad, "(in study case broken)"));

  CHECK(contains(case_error({"high", "sometime"}), "study.axes.time: no level named \"sometime\"; it has short, long"));
  CHECK(contains(case_error({"high"}), "the study has 2 axes, the case 1 levels"));
  CHECK(contains(case_error({"low", "long"}, "medium"), "no variant named \"medium\"; it has light, heavy"));
  CHECK(case_error({"low", "long"}, "light").empty());
}

TEST_CASE("study cases: every combination, the first axis slowest; --case selects by levels") {
  const Scenario s = load(kStudy);
  const auto all = elbowsim::study::study_cases(s);
  REQUIRE(all.size() == 4);
  CHECK(all[0].name == "low-short");
  CHECK(all[1].name == "low-long");
  CHECK(all[2].name == "high-short");
  CHECK(all[3].name == "high-long");
  CHECK(all[2].levels == std::vector<std::string>{"high", "short"});
  using elbowsim::study::select_cases;
  CHECK(select_cases(s, "").size() == 4);
  CHECK(select_cases(s, "time=short").size() == 2);
  CHECK(select_cases(s, "time=short,time=long,pose=high").size() == 2);
  const auto one = select_cases(s, "pose=high,time=long");
  REQUIRE(one.size() == 1);
  CHECK(one[0].name == "high-long");
  CHECK_THROWS_WITH_AS(select_cases(s, "pose=middle"),
                       "--case: axis pose has no level \"middle\" (its levels: low, high)",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(select_cases(s, "speed=fast"),
                       "--case: no study axis \"speed\" (the axes: pose, time)", std::invalid_argument);
  CHECK_THROWS_AS(select_cases(s, "pose"), std::invalid_argument);
  const Scenario plain = load(kTwoLink);
  CHECK(elbowsim::study::study_cases(plain).size() == 1);
  CHECK(elbowsim::study::study_cases(plain)[0].name.empty());
  CHECK_THROWS_AS(select_cases(plain, "pose=low"), std::invalid_argument);
}

TEST_CASE("cli: a study of three variants: its report has a ratio plot and table columns for each pair") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_study_three");
  std::string text = kStudy;
  const std::string heavy = "  heavy: {hand_load.mass: 0.2}\n";
  REQUIRE(text.find(heavy) != std::string::npos);
  text.replace(text.find(heavy), heavy.size(), heavy + "  heavier: {hand_load.mass: 0.4}\n");
  std::ofstream(dir / "study.yaml") << text;
  const auto r = elbowsim::testing::run_elbowsim("montecarlo " + (dir / "study.yaml").string() +
                                                 " --samples 3 --jobs 2 --case pose=low,time=short --out " +
                                                 (dir / "out").string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* plot : {"ratios.png", "ratios_light_heavier.png", "ratios_heavy_heavier.png"})
    CHECK(fs::file_size(dir / "out" / "plots" / plot) > 1000);
  const std::string html = elbowsim::testing::slurp(dir / "out" / "report.html");
  for (const char* pair : {"light / heavy", "light / heavier", "heavy / heavier"})
    CHECK(contains(html, std::string("ratio ") + pair));
  CHECK(contains(html, "RMS hand error, heavy against heavier"));
  // --case ran one level of each axis: the report says which, and of what.
  CHECK(contains(html, "pose: low (of low, high); time: short (of short, long)"));
}

TEST_CASE("cli: montecarlo over a study: a folder per case, study files, same bytes with --jobs 1 or 2" * doctest::test_suite("long")) {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_study");
  const fs::path file = dir / "study.yaml";
  std::ofstream(file) << kStudy;
  auto run = [&](const std::string& out, const std::string& options) {
    return elbowsim::testing::run_elbowsim("montecarlo " + file.string() + " --samples 15 --out " +
                                           (dir / out).string() + " " + options);
  };
  const auto one = run("one", "--jobs 1");
  INFO(one.output);
  REQUIRE(one.exit_code == 0);
  REQUIRE(run("two", "--jobs 2 --no-report").exit_code == 0);
  for (const char* f : {"study.json", "study.csv", "low-short/samples.csv", "high-long/montecarlo.json"})
    CHECK(elbowsim::testing::slurp(dir / "one" / f) == elbowsim::testing::slurp(dir / "two" / f));
  for (const char* c : {"low-short", "low-long", "high-short", "high-long"}) {
    CHECK(fs::exists(dir / "one" / c / "report.html"));
    CHECK_FALSE(fs::exists(dir / "two" / c / "report.html"));
  }
  CHECK(lines(elbowsim::testing::slurp(dir / "one" / "study.csv")) == 1 + 4);  // header, a row per case

  const auto doc = nlohmann::json::parse(elbowsim::testing::slurp(dir / "one" / "study.json"));
  REQUIRE(doc["cases"].size() == 4);
  CHECK(doc["cases"][2]["case"] == "high-short");
  CHECK(doc["cases"][2]["levels"]["pose"] == "high");
  CHECK(doc["axes"][1]["levels"][0] == "short");
  // Every case counted once per metric in the tally (alone; "corrected" below).
  for (const char* metric : {"energy_drawn", "energy_in", "hand_error_rms"}) {
    std::size_t counted = 0;
    for (const auto& [outcome, cases] : doc["tally"][0][metric].items()) counted += cases.size();
    CHECK(counted == 4);
  }
  // The heavier hand costs energy in every case: the verdict says so.
  CHECK(doc["tally"][0]["energy_drawn"]["lower"].size() == 4);
  CHECK(contains(
      doc["verdict"][0].get<std::string>(),
      "Electrical energy drawn from the supply, light against heavy: lower in 4 of 4 cases"));
  CHECK(doc["tally"][0]["energy_in"]["lower"].size() == 4);
  // The short cases ran 0.3 s: less energy than the long ones.
  const auto energy = [&](int k) { return doc["cases"][k]["metrics"]["light"]["energy_in"]["mean"].get<double>(); };
  CHECK(energy(0) < energy(1));

  const std::string html = elbowsim::testing::slurp(dir / "one" / "report.html");
  CHECK(contains(html, "<h1>Monte Carlo study over 4 cases: two_link</h1>"));
  CHECK(contains(html, "href=\"high-long/report.html\""));
  CHECK(fs::file_size(dir / "one" / "plots" / "ratios.png") > 1000);

  // Each draw has its own sensor noise: seed 5 + draw, mixed with the case's name.
  using elbowsim::study::case_seed;
  const std::string samples = elbowsim::testing::slurp(dir / "one" / "low-long" / "samples.csv");
  CHECK(contains(samples, "draw,variant,valid,sensor_seed,"));
  CHECK(contains(samples, "\n0,light,true," + std::to_string(case_seed(5, "low-long")) + ","));
  CHECK(contains(samples, "\n5,heavy,true," + std::to_string(case_seed(10, "low-long")) + ","));
  // Each case draws plants of its own: draw 0's link masses differ between two
  // cases (they were the same plant in every case before), and each case's
  // folder records its seed.
  const auto draw_row = [&](const char* c) {
    const std::string text = elbowsim::testing::slurp(dir / "one" / c / "samples.csv");
    const std::size_t at = text.find("\n0,light,");
    return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
  };
  const auto masses = [](const std::string& row) {  // the two drawn masses after draw,variant,valid,seed
    std::vector<std::string> fields;
    std::stringstream in(row);
    for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
    return std::vector<std::string>(fields.begin() + 4, fields.begin() + 6);
  };
  CAPTURE(draw_row("low-short"));
  CAPTURE(draw_row("low-long"));
  CHECK(masses(draw_row("low-short")) != masses(draw_row("low-long")));
  CHECK(masses(draw_row("high-long")) != masses(draw_row("low-long")));
  const auto case_doc =
      nlohmann::json::parse(elbowsim::testing::slurp(dir / "one" / "high-long" / "montecarlo.json"));
  CHECK(case_doc["seed"] == 3);
  CHECK(case_doc["case_seed"] == case_seed(3, "high-long"));
  CHECK(case_seed(3, "") == 3);  // a scenario without a study draws from its seed
  // The verdict over the cases: Holm's correction of each case's sign test,
  // and the draws that favour each side (15 draws in each of the 4 cases).
  const auto& holm = doc["tally"][0]["corrected"]["energy_drawn"];
  CHECK(holm["tests"] == 4);
  CHECK(holm["lower"].size() + holm["higher"].size() + holm["not significant"].size() == 4);
  CHECK(holm["lower"].size() == 4);  // 15 of 15 draws each: p = 2^-14 per case
  const auto& draws = holm["draws"];
  CHECK(draws["a_lower"].get<int>() + draws["b_lower"].get<int>() == 60);
  CHECK(contains(doc["verdict"][0].get<std::string>(),
                 "with Holm's correction over the 4 cases with a verdict (exact sign test on each "
                 "case's draws, family-wise error 5 %): lower in 4, higher in 0, not significant in "
                 "0; light lower in 60 of 60 draws, heavy lower in 0"));
  CHECK(doc["cases"][0]["pairs"][0]["energy_drawn"]["holm"] == "lower");
  CHECK(doc["cases"][0]["pairs"][0]["energy_drawn"]["sign_test_p"].get<double>() ==
        doctest::Approx(std::ldexp(1.0, -14)));
  // study.csv: per compared quantity its statistic, outcome (alone and corrected) and reason.
  const std::string csv = elbowsim::testing::slurp(dir / "one" / "study.csv");
  CHECK(contains(csv,
                 "energy_drawn ratio a/b,energy_drawn ratio low,energy_drawn ratio high,"
                 "energy_drawn a lower share,energy_drawn outcome,energy_drawn outcome (Holm),"
                 "energy_drawn sign test p,energy_drawn reason,"));
  CHECK(contains(
      csv,
      "energy_in difference a-b [J],energy_in difference low [J],energy_in difference high [J],"));

  const auto some = run("some", "--case pose=high --no-report");
  REQUIRE(some.exit_code == 0);
  CHECK(fs::exists(dir / "some" / "high-short"));
  CHECK_FALSE(fs::exists(dir / "some" / "low-short"));
  CHECK(elbowsim::testing::slurp(dir / "some" / "high-long" / "samples.csv") ==
        elbowsim::testing::slurp(dir / "one" / "high-long" / "samples.csv"));
  // validate loads every case: it says how many, and names a broken level.
  const auto checked = elbowsim::testing::run_elbowsim("validate " + file.string());
  CHECK(checked.exit_code == 0);
  CHECK(contains(checked.output, "study      4 cases (2 pose x 2 time), each loaded"));
  const fs::path broken = dir / "broken.yaml";
  std::ofstream(broken) << kStudy << "      never: {simulation.duration: -1}\n";
  const auto refused = elbowsim::testing::run_elbowsim("validate " + broken.string());
  CHECK(refused.exit_code == 2);
  CHECK(contains(refused.output, "simulation.duration: must be > 0"));
  CHECK(contains(refused.output, "(in study case low-never)"));

  const auto bad = run("bad", "--case pose=middle");
  CHECK(bad.exit_code == 2);
  CHECK(contains(bad.output, "axis pose has no level \"middle\""));
  CHECK_FALSE(fs::exists(dir / "bad"));
}

TEST_CASE("cli: montecarlo interrupted: the cases done are kept, the interrupted one and the study tables are not written, exit 130") {
  const fs::path dir = elbowsim::testing::scratch("cli", "montecarlo_interrupt");
  const fs::path file = dir / "study.yaml";
  // Long cases (200 s each) so that the signal comes during the first one.
  std::ofstream(file) << kStudy;
  const fs::path out = dir / "out";
  const auto r = elbowsim::testing::shell(
      "(" + std::string(ELBOWSIM_BINARY) + " montecarlo " + file.string() + " --samples 4 --jobs 2 --out " +
      out.string() + " --set simulation.duration=200 & pid=$!; sleep 1; kill -INT $pid; wait $pid; echo \"exit=$?\")");
  INFO(r.output);
  CHECK(contains(r.output, "exit=130"));
  CHECK(contains(r.output, "interrupted: 0 of 4 cases complete"));
  CHECK_FALSE(fs::exists(out / "study.json"));
  CHECK_FALSE(fs::exists(out / "low-short" / "montecarlo.json"));
  // No case finished: the folder the study created holds nothing of it and
  // is removed with its lock (left as it was); a kept one has no temporaries.
  if (fs::exists(out))
    for (const auto& entry : fs::recursive_directory_iterator(out))
      CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
}
