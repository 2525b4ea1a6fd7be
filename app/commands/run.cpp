#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "app/commands/interrupt.hpp"
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
#include "engine/run/recorder.hpp"
#include "engine/run/simulator.hpp"
#include "report/compare_report.hpp"

namespace elbowsim {

namespace {

// A progress line on stderr, only on a terminal and only once a run has taken
// longer than a second.
std::function<void(double)> terminal_progress() {
  if (!isatty(STDERR_FILENO)) return {};
  const auto start = std::chrono::steady_clock::now();
  return [start](double fraction) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed < 1.0) return;
    std::fprintf(stderr, "\r  %5.1f %%  (%.1f s elapsed)", 100.0 * fraction, elapsed);
    if (fraction >= 1.0) std::fputc('\n', stderr);
  };
}

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
        [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
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
  bool rendered = false;  // video or frames made by this run
  bool recorded() const { return result.trajectory.rows() > 0; }
};

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

// --check-step: the summary's step_check, and one line per metric that moved
// by more than 1 % on stdout.
void add_step_check(const Scenario& scenario, const RunResult& result,
                    nlohmann::ordered_json& summary) {
  try {
    summary["step_check"] = check_step(scenario, result);
  } catch (const std::exception& e) {
    summary["step_check"] = {{"error", e.what()}};
    std::cerr << "warning: --check-step: " << e.what() << '\n';
    return;
  }
  const auto& c = summary["step_check"];
  std::cout << "step check (" << c["half_step"].get<double>() << " s against "
            << c["step"].get<double>() << " s)"
            << (c["valid_at_half_step"].get<bool>() ? "" : ": INVALID at half the step") << '\n';
  for (const auto& [name, m] : c["metrics"].items()) {
    const double change = m["relative_change"].get<double>();
    std::printf("  %-24s %12.6g -> %12.6g %s  (%.2g relative%s)\n", name.c_str(),
                m["value"].get<double>(), m["at_half_step"].get<double>(),
                m["unit"].get<std::string>().c_str(), change, change > 0.01 ? ", more than 1 %" : "");
  }
  std::fflush(stdout);
}

RunOutcome simulate_one(const Scenario& scenario, const std::filesystem::path& folder,
                        const RunArguments& args) {
  RunOutcome outcome;
  outcome.result = simulate_or_fail(scenario);
  const RunResult& result = outcome.result;
  outcome.summary = run_summary(scenario, result);
  if (args.check_step && result.valid && !interrupt_exit_code()) add_step_check(scenario, result, outcome.summary);
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
  // Interrupted: the data files are written; nothing more is started.
  if (interrupt_exit_code()) {
    std::cerr << "interrupted: wrote what was recorded to " << folder.string() << '\n';
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

// After rendering (`rendered`: its code): the manifest, then the report,
// which reads the folder back and embeds the video only when the manifest
// lists it. Returns exit_io when the manifest cannot be written.
int finish_run(const Scenario& scenario, const std::filesystem::path& folder,
               const RunArguments& args, RunOutcome& outcome, int rendered) {
  try {
    if (outcome.rendered) record_rendered(folder, scenario.output.video, scenario.output.frames);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    outcome.code = exit_io;
    return exit_io;
  }
  const int reported = outcome.recorded() && args.report ? report_outputs(folder) : exit_ok;
  if (outcome.code == exit_ok) outcome.code = rendered != exit_ok ? rendered : reported;
  return exit_ok;
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
      report::write_comparison_tables(report::compare_runs(loaded), tables);
    } else {
      const auto files = report::write_comparison_report(loaded, folder / "compare", tables, video);
      std::cout << "comparison report: " << files.html.string() << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  std::cout << variants.front().model.name << ": " << variants.size() << " variants compared in "
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
  if (!runs.empty()) {
    // Side by side only when every run is drawn.
    const bool all = runs.size() == scenarios.size();
    const std::vector<int> codes =
        render_runs(runs, all ? side_by_side : std::nullopt, side_by_side_code, args.render_jobs);
    for (std::size_t j = 0; j < runs.size(); ++j) {
      rendered[which[j]] = codes[j];
      outcomes[which[j]].rendered = true;
    }
  }
  for (std::size_t k = 0; k < scenarios.size(); ++k)
    if (finish_run(*scenarios[k], folders[k], args, outcomes[k], rendered[k]) == exit_io)
      return exit_io;
  return exit_ok;
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
    if (interrupt_exit_code()) return interrupt_exit_code();  // no more runs, no comparison
    scenarios.push_back(&v);
    folders.push_back(folder / v.variant);
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
  int code = exit_ok;
  nlohmann::ordered_json summaries;  // variant -> summary, for --expect
  for (std::size_t k = 0; k < variants.size(); ++k) {
    if (code == exit_ok) code = outcomes[k].code;
    summaries[variants[k].variant] = outcomes[k].summary;
    records.push_back({variants[k].variant, folders[k]});
  }
  const bool video = side_by_side && std::filesystem::exists(compare / "video.mp4");
  if (compare_variants(args, variants, folder, video) == exit_io) return exit_io;
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
