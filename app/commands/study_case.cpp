// One case of a study, run in this process: each variant of the scenario at
// the case's keys (and, in a Monte Carlo design, its drawn plant under the
// nominal controller, as elbowsim montecarlo draws it), into the case's
// folder, then case.json (app/study/case_record.hpp).
#include <fstream>
#include <iostream>
#include <memory>

#include "app/commands/interrupt.hpp"
#include "app/commands/study_plan.hpp"
#include "app/output/folder_lock.hpp"
#include "app/scenario/scenario.hpp"
#include "app/study/case_record.hpp"
#include "app/study/draws.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim {

namespace {

// Why a run that ended with exit_run_failed failed: its summary's failure.
std::string failure_of(const std::filesystem::path& folder) {
  try {
    std::ifstream in(folder / "summary.json");
    const auto summary = nlohmann::ordered_json::parse(in);
    const std::string failure = summary.value(summary_key::failure.name(), "");
    return failure.empty() ? "the run is invalid (summary.json)" : failure;
  } catch (const std::exception&) {
    return "the run failed (no readable summary.json)";
  }
}

// The scenario of variant `variant` at case `c`. With a draw: the drawn plant
// while the controller believes the nominal one, and the sensors' noise seed
// moved by the draw's index (as in elbowsim montecarlo).
Scenario case_scenario(const StudyPlan& plan, const study::CaseSpec& c, const std::string& variant) {
  std::vector<std::string> sets = plan.design.sets;
  sets.insert(sets.end(), c.overrides.begin(), c.overrides.end());
  Scenario nominal = load_scenario_case(plan.design.scenario, {}, variant, sets);
  if (c.draw < 0) return nominal;
  const study::Draw draw = study::draw_parameters(nominal.uncertainty, plan.seed, c.draw);
  const std::vector<std::string> drawn = study::draw_overrides(nominal.uncertainty, draw);
  sets.insert(sets.end(), drawn.begin(), drawn.end());
  Scenario s = load_scenario_case(plan.design.scenario, {}, variant, sets);
  s.experiment.controller_model =
      std::make_shared<const Model>(nominal.experiment.believed(nominal.model));
  s.experiment.controller.loop.sensors.seed += static_cast<std::uint64_t>(c.draw);
  return s;
}

}  // namespace

int run_study_case(const StudyPlan& plan, const study::CaseSpec& c, bool video) {
  const std::filesystem::path folder = plan.folder / c.folder;
  study::CaseRecord record{c.index, c.folder, "done", {}, {}};
  try {
    const FolderLock lock(folder);  // a case: one writer (shards never share one)
    std::filesystem::remove(folder / study::kCaseFile);  // not finished until written again
    for (const std::string& variant : plan.variants) {
      const std::filesystem::path runs = study::run_folder(folder, variant);
      record.variants.push_back(variant);
      Scenario scenario;
      try {
        scenario = case_scenario(plan, c, variant);
      } catch (const ScenarioError& e) {  // only a draw can fail here: the points were checked
        record.status = "failed";
        record.failures.emplace_back(variant, std::string("the drawn values are not a valid scenario: ") + e.what());
        std::filesystem::create_directories(runs);
        continue;
      }
      if (video) scenario.output.video = true;  // --case K --video: this case's videos, whatever the file says
      RunArguments args;
      args.scenario = plan.design.scenario;
      args.render = video;
      args.report = video;
      // The step check on a point's first draw (or its only run) states the
      // integration floor of the point; its other draws share the settings.
      args.check_step = c.draw <= 0;
      std::vector<RunRecord> records;
      const int code = run_scenario(args, scenario, runs, records);
      if (interrupt_exit_code()) return interrupt_exit_code();
      if (code == exit_io) return exit_io;
      if (code == exit_run_failed) {
        record.status = "failed";
        record.failures.emplace_back(variant, failure_of(runs));
      }
    }
    // A failed draw has no run folder with a manifest: it is recorded without one.
    std::vector<std::string> complete;
    for (const std::string& v : record.variants) {
      bool failed_to_load = false;
      for (const auto& [fv, reason] : record.failures)
        failed_to_load |= fv == v && !std::filesystem::exists(study::run_folder(folder, v) / "manifest.json");
      if (!failed_to_load) complete.push_back(v);
    }
    record.variants = complete;
    study::write_case_record(folder, record);
  } catch (const std::exception& e) {  // FolderInUse, a lock or case.json that cannot be written
    std::cerr << "error: study case " << c.folder << ": " << e.what() << '\n';
    return exit_io;
  }
  std::cout << "case " << c.folder << ": " << record.status << '\n';
  return record.status == "done" ? exit_ok : exit_run_failed;
}

}  // namespace elbowsim
