#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands/commands.hpp"
#include "app/output/atomic_file.hpp"
#include "app/output/events_csv.hpp"
#include "app/output/summary_json.hpp"
#include "app/output/trajectory_csv.hpp"
#include "app/scenario/scenario.hpp"
#include "engine/simulator.hpp"

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
                   const std::filesystem::path& folder) {
  write_atomically(folder / "scenario.yaml",
                   [&](std::ostream& out) { out << scenario.resolved_yaml; });
  if (scenario.output.trajectory)
    write_atomically(folder / "trajectory.csv",
                     [&](std::ostream& out) { write_trajectory_csv(out, result.trajectory); });
  if (scenario.model.effects.contact)
    write_atomically(folder / "events.csv", [&](std::ostream& out) {
      write_events_csv(out, scenario.model, result.contact);
    });
  if (scenario.output.summary)
    write_atomically(folder / "summary.json", [&](std::ostream& out) {
      out << run_summary(scenario, result).dump(2) << '\n';
    });
}

}  // namespace

int run_command(const RunArguments& args) {
  Scenario scenario;
  try {
    scenario = load_scenario(args.scenario, args.sets);
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  const std::filesystem::path folder = args.out.value_or(scenario.output.folder);
  const RunResult result =
      simulate(scenario.model, RunOptions{scenario.output.every, terminal_progress()});
  try {
    std::filesystem::create_directories(folder);
    write_outputs(scenario, result, folder);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  for (const std::string& warning : result.warnings) std::cerr << "warning: " << warning << '\n';
  if (!result.completed) {
    std::cerr << "error: " << result.failure << "\n  kept " << result.trajectory.rows()
              << " recorded samples in " << folder.string() << '\n';
    return exit_run_failed;
  }
  std::cout << scenario.model.name << ": " << result.steps << " steps to t = "
            << result.final_time << " s in " << result.wall_seconds << " s; outputs in "
            << folder.string() << '\n';
  return exit_ok;
}

}  // namespace elbowsim
