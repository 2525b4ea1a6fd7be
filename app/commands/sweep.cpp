// elbowsim sweep: one run of a scenario (with its variants, if any) per value
// of one key, into DIR/<key>=<value>/ (and <variant>/ below), then
// DIR/sweep.csv with one row per (value, variant). Serves the
// accuracy-vs-speed study (task.duration) and the elbow-position study
// (elbows[0].at).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>

#include "app/commands/commands.hpp"
#include "app/commands/interrupt.hpp"
#include "app/output/atomic_file.hpp"
#include "app/output/folder_lock.hpp"
#include "app/output/run_folder.hpp"
#include "app/scenario/scenario.hpp"
#include "engine/recording/number_text.hpp"
#include "report/comparison.hpp"
#include "report/sweep_plots.hpp"

namespace elbowsim {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// "8, 6,4" -> {"8", "6", "4"}.
std::vector<std::string> split_values(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    out.push_back(trim(text.substr(start, comma - start)));
  out.push_back(trim(text.substr(start)));
  return out;
}

int usage_error(const std::string& message) {
  std::cerr << "error: sweep: " << message << '\n';
  return exit_bad_input;
}

// Each value becomes a folder name and a sweep.csv cell.
std::string check_values(const std::string& key, const std::vector<std::string>& values) {
  if (key.empty() || key.find('=') != std::string::npos)
    return "--key needs a key path, e.g. --key task.duration";
  std::set<std::string> seen;
  for (const std::string& v : values) {
    if (v.empty()) return "--values needs a comma-separated list, e.g. --values 8,6,4";
    if (v.find('/') != std::string::npos) return "a value must not contain '/' (got " + v + ")";
    if (!seen.insert(v).second) return "value " + v + " is given twice";
  }
  return "";
}

}  // namespace

int sweep_command(const SweepArguments& args) {
  if (!expectations_well_formed(args.run.expect)) return exit_bad_input;
  const std::vector<std::string> values = split_values(args.values);
  if (const std::string problem = check_values(args.key, values); !problem.empty())
    return usage_error(problem);
  // Load every value first (the swept key last, after --set): a bad one writes nothing.
  std::vector<RunArguments> runs;
  std::vector<Scenario> scenarios;
  try {
    for (const std::string& v : values) {
      runs.push_back(args.run);
      runs.back().sets.push_back(args.key + "=" + v);
      scenarios.push_back(load_scenario(args.run.scenario, runs.back().sets));
    }
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  const std::filesystem::path folder =
      args.run.out.value_or(scenarios.front().output.folder + "/sweep");
  // One row per run: the value, the variant, the run folder as written.
  std::vector<std::string> row_values, row_variants;
  std::vector<report::RunData> row_runs;
  int code = exit_ok;
  try {
    install_interrupt_handlers();
    const FolderLock lock(folder);  // the whole sweep: one writer at a time
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::vector<RunRecord> records;
      const int c = run_scenario(runs[i], scenarios[i], folder / (args.key + "=" + values[i]), records);
      if (c == exit_io) return exit_io;
      if (interrupt_exit_code()) {  // no more runs, no table (run_scenario said what was kept)
        std::cerr << "interrupted: the sweep stopped at " << args.key << "=" << values[i]
                  << "; sweep.csv not written in " << folder.string() << '\n';
        return interrupt_exit_code();
      }
      if (code == exit_ok) code = c;
      for (const RunRecord& r : records) {
        row_values.push_back(values[i]);
        row_variants.push_back(r.variant);
        row_runs.push_back(load_run_folder(r.folder));
      }
    }
    write_atomically(folder / "sweep.csv", [&](std::ostream& out) {
      report::write_sweep_csv(out, args.key, row_values, row_variants, row_runs);
    });
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  std::cout << "sweep of " << args.key << ": "
            << counted(static_cast<long long>(row_runs.size()), "run") << "; table in "
            << (folder / "sweep.csv").string() << '\n';
  if (interrupt_exit_code()) {  // while the table was written: it is whole; no plots start
    std::cerr << "interrupted: sweep.csv is written; no plots\n";
    return interrupt_exit_code();
  }
  // Plots against the value, when every value is a number.
  std::vector<report::SweepPoint> points;
  for (std::size_t r = 0; r < row_runs.size(); ++r) {
    char* end = nullptr;
    const double x = std::strtod(row_values[r].c_str(), &end);
    if (end == row_values[r].c_str() || *end) return code;
    points.push_back({x, row_variants[r], row_runs[r].summary});
  }
  try {
    for (const auto& png : report::write_sweep_plots(args.key, points, folder))
      std::cout << "plot: " << png.string() << '\n';
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  return code;
}

}  // namespace elbowsim
