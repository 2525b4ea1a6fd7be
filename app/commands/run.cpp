#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "app/commands/interrupt.hpp"
#include "app/commands/progress.hpp"
#include "app/commands/step_check.hpp"
#include "app/output/atomic_file.hpp"
#include "app/output/events_csv.hpp"
#include "app/output/folder_lock.hpp"
#include "app/output/run_folder.hpp"
#include "app/output/run_manifest.hpp"
#include "app/output/summary_json.hpp"
#include "app/output/trajectory_csv.hpp"
#include "app/scenario/scenario.hpp"
#include "engine/control/inverse_kinematics.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/recorder.hpp"
#include "engine/run/simulator.hpp"
#include "report/compare_report.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim {

namespace key = summary_key;

namespace {

void write_outputs(const Scenario& scenario, const RunResult& result,
                   const nlohmann::ordered_json& summary, const std::filesystem::path& folder) {
  // All or nothing: a full disk leaves the folder's earlier files as they were.
  FileBatch files;
  std::vector<std::string> written;  // the manifest (app/output/run_manifest.hpp)
  const auto write = [&](const char* name, bool wanted,
                         const std::function<void(std::ostream&)>& f) {
    if (!wanted) return files.remove_at_commit(folder / name);  // none of an earlier run's left
    files.add(folder / name, f);
    written.push_back(name);
  };
  write("scenario.yaml", true, [&](std::ostream& out) { out << scenario.resolved_yaml; });
  // A run that never started (its plan failed) has no columns: no table.
  write("trajectory.csv", scenario.output.trajectory && !result.trajectory.columns().empty(),
        [&](std::ostream& out) { write_trajectory_csv(out, result.trajectory); });
  write("events.csv", scenario.model.effects.contact,
        [&](std::ostream& out) { write_events_csv(out, scenario.model, result.events); });
  write("summary.json", scenario.output.summary,
        [&](std::ostream& out) { out << summary_text(summary); });
  // What an earlier run derived from its data (video, frames, report) goes
  // in the same commit: this run's are added to the manifest as they are made.
  for (const std::string& name : derived_artefacts()) files.remove_at_commit(folder / name);
  files.add(folder / kManifestFile, [&](std::ostream& out) { out << manifest_text(written); });
  files.commit();
}

// One run folder, simulated and its data written. Its code: exit_ok,
// exit_io (nothing more to do), exit_run_failed; rendering and the report
// come after (finish_run), once every variant has been simulated, so that
// the variants can be drawn at once. Expectations are the caller's.
struct RunOutcome {
  int code = exit_ok;
  nlohmann::ordered_json summary;  // as written to summary.json
  RunResult result;
  bool rendered = false;  // video or frames made by this run (or its render failed)
  bool reported = false;  // report.html written (or failed)
  bool recorded() const { return result.trajectory.rows() > 0; }
};

// A signal stopped `stage` of the run (or kept it from starting): the
// summary says so, interrupted_stage right after interrupted.
void set_interrupted(nlohmann::ordered_json& summary, const std::string& stage) {
  nlohmann::ordered_json marked;
  for (const auto& [key, value] : summary.items()) {
    if (key == summary_key::interrupted_stage.name()) continue;
    const bool interrupted = key == summary_key::interrupted.name();
    marked[key] = interrupted ? nlohmann::ordered_json(true) : value;
    if (interrupted) marked[summary_key::interrupted_stage.name()] = stage;
  }
  summary = std::move(marked);
}

// A hand task that cannot be followed stops the run before it starts: it
// counts as a run that stopped early (a sweep goes on past an unreachable
// value), with nothing recorded, so nothing to render or report.
RunResult simulate_or_fail(const Scenario& scenario) {
  try {
    return simulate(scenario.model, scenario.experiment,
                    RunOptions{scenario.output.every, terminal_progress(), &interrupt_flag()});
  } catch (const PlanError& e) {
    RunResult failed;
    failed.failure = std::string("the hand task cannot be followed: ") + e.what();
    return failed;
  }
}

// The step check (step_check.hpp) into the summary, and on stdout one line:
// the largest change of a headline metric, then each metric below its floor.
// A signal stops it: no step_check then.
void add_step_check(const Scenario& scenario, const RunResult& result,
                    nlohmann::ordered_json& summary) {
  try {
    nlohmann::ordered_json check = check_step(scenario, result);
    if (interrupt_exit_code()) return set_interrupted(summary, "step_check");
    summary[key::step_check.name()] = std::move(check);
  } catch (const std::exception& e) {
    summary[key::step_check.name()] = {{key::step_check_error.name(), e.what()}};
    std::cerr << "warning: step check: " << e.what() << '\n';
    return;
  }
  const auto& c = summary[key::step_check.name()];
  const auto& metrics = c[key::step_check_metrics.name()];
  const std::string label = scenario.variant.empty() ? scenario.model.name : scenario.variant;
  std::cout << label << ": accuracy at " << c[key::step_check_refinement.name()].get<std::string>();
  if (!c[key::step_check_valid_at_half_step.name()].get<bool>()) {
    std::cout << ": the refined run is NOT VALID ("
              << c.value(key::step_check_failure_at_half_step.name(), "")
              << "); the numbers' accuracy is unknown\n";
    return;
  }
  std::string largest;
  double change = 0;
  const auto relative_change = [&](const char* name) {
    return metrics[name][key::checked_relative_change.name()].get<double>();
  };
  for (const char* name :
       {metric::hand_error_rms, metric::hand_error_max, metric::energy_in, metric::joule})
    if (metrics.contains(name) && relative_change(name) >= change)
      change = relative_change(name), largest = name;
  if (!largest.empty()) std::printf(": %s moves by %.2g %%", largest.c_str(), 100 * change);
  std::cout << '\n';
  for (const auto& name : c[key::step_check_below_floor.name()]) {
    const auto& m = metrics[name.get<std::string>()];
    const std::string unit = m[key::checked_unit.name()].get<std::string>();
    std::printf(
        "  %s %.3g %s is below the integration floor (it moves by %.3g %s when refined): "
        "it measures the integrator, not the arm\n",
        name.get<std::string>().c_str(), m[key::checked_value.name()].get<double>(), unit.c_str(),
        m[key::checked_floor.name()].get<double>(), unit.c_str());
  }
  std::fflush(stdout);
}

RunOutcome simulate_one(const Scenario& scenario, const std::filesystem::path& folder,
                        const RunArguments& args) {
  RunOutcome outcome;
  outcome.result = simulate_or_fail(scenario);
  const RunResult& result = outcome.result;
  outcome.summary = run_summary(scenario, result);
  if (result.interrupted) set_interrupted(outcome.summary, "simulation");
  if (args.check_step && result.valid && !interrupt_exit_code())
    add_step_check(scenario, result, outcome.summary);
  try {
    std::filesystem::create_directories(folder);
    write_outputs(scenario, result, outcome.summary, folder);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    outcome.code = exit_io;
    return outcome;
  }
  if (const Options& o = scenario.model.options; !o.integrator_reason.empty())
    std::cout << "integrator auto chose " << to_string(o.integrator) << ": " << o.integrator_reason
              << '\n';
  for (const std::string& warning : result.warnings) std::cerr << "warning: " << warning << '\n';
  if (result.interrupted) end_progress_line();
  if (!result.completed) {
    std::cerr << "error: " << result.failure << "\n  kept " << result.trajectory.rows()
              << " recorded samples in " << folder.string() << '\n';
  } else if (!result.valid) {
    std::cerr << "error: " << result.failure << "\n  the run reached t = " << result.final_time
              << " s; its outputs in " << folder.string() << " are marked invalid\n";
  } else {
    std::cout << scenario.model.name << ": " << result.steps << " steps to t = "
              << result.final_time << " s in " << result.wall_seconds << " s; outputs in "
              << folder.string() << '\n';
  }
  // Interrupted: the data files are written; nothing more is started
  // (the caller marks the summary and says what was kept: stop_runs).
  if (interrupt_exit_code()) {
    outcome.code = interrupt_exit_code();
    return outcome;
  }
  if (!result.valid) outcome.code = exit_run_failed;
  return outcome;
}

// Whether the run's frames or video are to be drawn (from the recording in
// memory: what it recorded, also when the run stopped early).
bool wants_render(const Scenario& scenario, const RunOutcome& outcome, const RunArguments& args) {
  return outcome.recorded() && args.render && (scenario.output.video || scenario.output.frames);
}

// After rendering: what it made goes in the manifest (the report embeds the
// video only when the manifest lists it). Returns exit_io when the manifest
// cannot be written.
int record_render(const Scenario& scenario, const std::filesystem::path& folder,
                  RunOutcome& outcome) {
  try {
    if (outcome.rendered) record_rendered(folder, scenario.output.video, scenario.output.frames);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    outcome.code = exit_io;
    return exit_io;
  }
  return exit_ok;
}

// The first of the run's stages not done, which a signal seen now stopped or
// kept from starting; "" when none is left. `compared`: the variants'
// comparison comes after the run's own stages.
std::string pending_stage(const Scenario& scenario, const RunOutcome& outcome,
                          const RunArguments& args, bool compared) {
  if (outcome.summary.contains(key::interrupted_stage.name()))  // simulation, step_check
    return outcome.summary[key::interrupted_stage.name()].get<std::string>();
  if (wants_render(scenario, outcome, args) && !outcome.rendered) return "rendering";
  if (outcome.recorded() && args.report && !outcome.reported) return "report";
  return compared ? "comparison" : "";
}

// The files the manifest lists, and those asked for that it does not (not
// made: the signal came first), as "a, b, c".
std::pair<std::string, std::string> kept_and_missing(const Scenario& scenario,
                                                     const std::filesystem::path& folder,
                                                     const RunArguments& args) {
  std::vector<std::string> listed;
  try {
    listed = read_manifest(folder).value_or(std::vector<std::string>{});
  } catch (const std::exception&) {
  }
  const auto has = [&](const std::string& f) {
    return std::find(listed.begin(), listed.end(), f) != listed.end();
  };
  std::string kept, missing;
  for (const std::string& f : listed) kept += (kept.empty() ? "" : ", ") + f;
  for (const auto& [file, wanted] :
       {std::pair<std::string, bool>{"video.mp4", args.render && scenario.output.video},
        {"frames/", args.render && scenario.output.frames},
        {"report.html", args.report}})
    if (wanted && !has(file)) missing += (missing.empty() ? "" : ", ") + file;
  return {kept, missing};
}

// After a signal: each run's summary.json names the first of its stages not
// done (interrupted_stage; rewritten atomically, nothing else touched), and
// stderr says what each folder keeps. Returns the signal's exit code, or
// exit_io when a summary cannot be written.
int stop_runs(const std::vector<const Scenario*>& scenarios,
              const std::vector<std::filesystem::path>& folders, std::vector<RunOutcome>& outcomes,
              const RunArguments& args, bool compared) {
  bool stopped = false;
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    RunOutcome& outcome = outcomes[k];
    const std::string stage = pending_stage(*scenarios[k], outcome, args, compared);
    if (stage.empty()) continue;  // every stage of this run was done
    stopped = true;
    outcome.code = interrupt_exit_code();
    if (!outcome.summary.contains(key::interrupted_stage.name())) {
      set_interrupted(outcome.summary, stage);
      try {
        if (scenarios[k]->output.summary)
          write_atomically(folders[k] / "summary.json",
                           [&](std::ostream& out) { out << summary_text(outcome.summary); });
      } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return exit_io;
      }
    }
    const auto [kept, missing] = kept_and_missing(*scenarios[k], folders[k], args);
    std::cerr << "interrupted (" << stage << "): " << folders[k].string() << " keeps " << kept
              << (scenarios[k]->output.summary ? " (summary.json says interrupted)" : "")
              << (missing.empty() ? "" : "; not made: " + missing) << '\n';
  }
  if (!stopped) std::cerr << "interrupted after the run's last stage: its outputs are complete\n";
  return interrupt_exit_code();
}

// The variants' comparison: comparison.json and comparison.csv in `folder`
// (report/comparison.hpp writes both), and with the report compare/ beside
// them (report.html, plots, and the side-by-side video when this run made it).
int compare_variants(const RunArguments& args, const std::vector<Scenario>& variants,
                     const std::filesystem::path& folder, bool video) {
  try {
    std::vector<report::RunData> loaded;
    for (const Scenario& v : variants) loaded.push_back(load_run_folder(folder / v.variant));
    const report::ComparisonTables tables{folder, "variant"};
    if (!args.report) {
      const report::Comparison comparison = report::compare_runs(loaded);
      report::write_comparison_tables(comparison, tables);
      print_verdict(comparison);
    } else {
      const auto files = report::write_comparison_report(loaded, folder / "compare", tables, video);
      print_verdict(files.comparison);
      std::cout << "comparison report: " << files.html.string() << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  std::cout << variants.front().model.name << ": "
            << counted(static_cast<long long>(variants.size()), "variant") << " compared in "
            << (folder / "comparison.csv").string() << '\n';
  return exit_ok;
}

// Before simulating: a recording that would not fit in memory is refused
// (more than half of this machine's RAM: exit 2, naming the keys that size
// it); over a tenth, a warning. False: refused.
bool recording_fits(const Scenario& s) {
  const double bytes = recording_bytes_estimate(s.model, s.output.every, s.experiment.needs_plan());
  const double ram = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  if (!(ram > 0) || bytes <= 0.1 * ram) return true;
  char text[512];
  std::snprintf(text, sizeof text,
                "%s: the recording would hold ~%.3g GB in memory (simulation.duration %g s / "
                "(simulation.step %g s x output.every %d) rows x its columns x 8 bytes), %s this "
                "machine's %.3g GB",
                s.file.c_str(), bytes / 1e9, s.model.options.duration, s.model.options.step, s.output.every,
                bytes > 0.5 * ram ? "more than half of" : "over a tenth of", ram / 1e9);
  if (bytes <= 0.5 * ram) {
    std::cerr << "warning: " << text << '\n';
    return true;
  }
  std::cerr << "error: " << text << ": raise output.every, or shorten simulation.duration, or lengthen simulation.step\n";
  return false;
}

// Renders the runs that want it, all at once (render_runs), and with a
// side-by-side folder their frames side by side; then finishes each run
// (manifest, report). Returns exit_io on an I/O error that stops everything.
// A signal stops the rendering (a run drawn to its end keeps its video) and
// starts no report: the caller then calls stop_runs.
int render_and_finish(const std::vector<const Scenario*>& scenarios,
                      const std::vector<std::filesystem::path>& folders,
                      std::vector<RunOutcome>& outcomes, const RunArguments& args,
                      const std::optional<std::filesystem::path>& side_by_side,
                      int& side_by_side_code) {
  std::vector<RunToRender> runs;
  std::vector<std::size_t> which;
  for (std::size_t k = 0; k < scenarios.size(); ++k)
    if (wants_render(*scenarios[k], outcomes[k], args)) {
      runs.push_back({scenarios[k], &outcomes[k].result.trajectory, folders[k]});
      which.push_back(k);
    }
  std::vector<int> rendered(scenarios.size(), exit_ok);
  side_by_side_code = exit_ok;
  if (!runs.empty() && !interrupt_exit_code()) {
    // Side by side only when every run is drawn.
    const bool all = runs.size() == scenarios.size();
    const std::vector<int> codes =
        render_runs(runs, all ? side_by_side : std::nullopt, side_by_side_code, args.render_jobs);
    for (std::size_t j = 0; j < runs.size(); ++j) {
      const bool stopped = codes[j] > 128;  // by a signal: nothing of it kept
      rendered[which[j]] = stopped ? exit_ok : codes[j];
      outcomes[which[j]].rendered = !stopped;
    }
  }
  for (std::size_t k = 0; k < scenarios.size(); ++k)
    if (record_render(*scenarios[k], folders[k], outcomes[k]) == exit_io) return exit_io;
  for (std::size_t k = 0; k < scenarios.size(); ++k) {
    if (interrupt_exit_code()) break;  // no report starts after a signal
    RunOutcome& outcome = outcomes[k];
    const int reported = outcome.recorded() && args.report ? report_outputs(folders[k]) : exit_ok;
    outcome.reported = true;
    if (outcome.code == exit_ok) outcome.code = rendered[k] != exit_ok ? rendered[k] : reported;
  }
  return exit_ok;
}

// After a signal, a scenario's variants: stop_runs for those simulated; the
// comparison an earlier run left in `folder` goes (it is of other data), and
// stderr says which variants were not run and that no comparison was made.
int stop_variants(const RunArguments& args, const std::vector<Scenario>& variants,
                  const std::filesystem::path& folder,
                  const std::vector<const Scenario*>& scenarios,
                  const std::vector<std::filesystem::path>& folders,
                  std::vector<RunOutcome>& outcomes) {
  const int code = stop_runs(scenarios, folders, outcomes, args, true);
  try {
    for (const char* table : {"comparison.csv", "comparison.json"})
      std::filesystem::remove(folder / table);
    for (const std::string& name : derived_artefacts())
      std::filesystem::remove_all(folder / "compare" / name);
    std::error_code none;  // compare/ made for the side-by-side, left empty
    if (std::filesystem::is_empty(folder / "compare", none))
      std::filesystem::remove(folder / "compare");
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  std::string not_run;
  for (std::size_t k = scenarios.size(); k < variants.size(); ++k)
    not_run += (not_run.empty() ? "" : ", ") + variants[k].variant;
  std::cerr << "interrupted: no comparison in " << folder.string()
            << (not_run.empty() ? "" : "; not run: " + not_run) << '\n';
  return code;
}

// Each variant into folder/<variant>/ (all loaded first: a bad one writes
// nothing): all simulated, then all rendered at once (with the report, their
// frames side by side into compare/), then each reported, then their
// comparison. A failed run does not stop the others; an I/O error does.
int run_variants(const RunArguments& args, const Scenario& scenario,
                 const std::filesystem::path& folder, std::vector<RunRecord>& records) {
  std::vector<Scenario> variants;
  try {
    for (const auto& [name, overrides] : scenario.variants)
      variants.push_back(load_scenario_variant(args.scenario, name, args.sets));
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  for (const Scenario& v : variants)
    if (!recording_fits(v)) return exit_bad_input;
  std::vector<RunOutcome> outcomes;
  std::vector<const Scenario*> scenarios;
  std::vector<std::filesystem::path> folders;
  for (const Scenario& v : variants) {
    outcomes.push_back(simulate_one(v, folder / v.variant, args));
    if (outcomes.back().code == exit_io) return exit_io;
    scenarios.push_back(&v);
    folders.push_back(folder / v.variant);
    if (interrupt_exit_code())  // no more runs, no comparison
      return stop_variants(args, variants, folder, scenarios, folders, outcomes);
  }
  // compare/ holds only what this run makes: an earlier run's side-by-side
  // video, frames or report go first (a --no-render run must not show an old video).
  const std::filesystem::path compare = folder / "compare";
  std::optional<std::filesystem::path> side_by_side;
  try {
    for (const std::string& name : derived_artefacts()) std::filesystem::remove_all(compare / name);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  const OutputSettings& first = variants.front().output;
  if (args.report && args.render && (first.video || first.frames)) side_by_side = compare;
  int side_code = exit_ok;
  if (render_and_finish(scenarios, folders, outcomes, args, side_by_side, side_code) == exit_io ||
      side_code == exit_io)
    return exit_io;
  if (interrupt_exit_code())  // during rendering or a report, or before the comparison
    return stop_variants(args, variants, folder, scenarios, folders, outcomes);
  int code = exit_ok;
  nlohmann::ordered_json summaries;  // variant -> summary, for --expect
  for (std::size_t k = 0; k < variants.size(); ++k) {
    if (code == exit_ok) code = outcomes[k].code;
    summaries[variants[k].variant] = outcomes[k].summary;
    records.push_back({variants[k].variant, folders[k]});
  }
  const bool video = side_by_side && std::filesystem::exists(compare / "video.mp4");
  if (compare_variants(args, variants, folder, video) == exit_io) return exit_io;
  if (interrupt_exit_code()) {  // during the comparison, which was written whole
    std::cerr << "interrupted after the comparison, the last stage: the outputs are complete\n";
    return interrupt_exit_code();
  }
  // Expectations name the variant first: "elbow_on.energy_final.joule < ...".
  const int checked = check_expectations(args.expect, summaries);
  return code != exit_ok ? code : checked;
}

}  // namespace

nlohmann::ordered_json expectation_shape(const RunArguments& args, const Scenario& scenario) {
  if (scenario.variants.empty()) return summary_shape(scenario, args.check_step);
  nlohmann::ordered_json shape = nlohmann::ordered_json::object();
  for (const auto& [name, overrides] : scenario.variants)
    shape[name] = summary_shape(load_scenario_variant(args.scenario, name, args.sets), args.check_step);
  return shape;
}

int run_scenario(const RunArguments& args, const Scenario& scenario,
                 const std::filesystem::path& folder, std::vector<RunRecord>& records) {
  if (!scenario.variants.empty()) return run_variants(args, scenario, folder, records);
  std::vector<RunOutcome> outcomes{simulate_one(scenario, folder, args)};
  RunOutcome& outcome = outcomes.front();
  if (outcome.code == exit_io) return exit_io;
  int side_code = exit_ok;
  if (!interrupt_exit_code() &&
      render_and_finish({&scenario}, {folder}, outcomes, args, std::nullopt, side_code) == exit_io)
    return exit_io;
  if (interrupt_exit_code()) return stop_runs({&scenario}, {folder}, outcomes, args, false);
  const int checked = check_expectations(args.expect, outcome.summary);
  records.push_back({"", folder});
  return outcome.code != exit_ok ? outcome.code : checked;
}

int run_command(const RunArguments& args) {
  // A malformed --expect is a usage error: found before simulating.
  if (!expectations_well_formed(args.expect)) return exit_bad_input;
  Scenario scenario;
  try {
    scenario = load_scenario(args.scenario, args.sets);
    // A misspelled metric is a usage error too: found before simulating.
    if (!args.expect.empty() && !expectations_fit(args.expect, expectation_shape(args, scenario)))
      return exit_bad_input;
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  if (scenario.variants.empty() && !recording_fits(scenario)) return exit_bad_input;
  const std::filesystem::path folder = args.out.value_or(scenario.output.folder);
  std::vector<RunRecord> records;
  install_interrupt_handlers();
  try {
    const FolderLock lock(folder);  // held until the run's last file is written
    return run_scenario(args, scenario, folder, records);
  } catch (const std::runtime_error& e) {  // FolderInUse, or the lock file
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
}

}  // namespace elbowsim
