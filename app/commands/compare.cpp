// elbowsim compare RUN_DIR RUN_DIR ... [--out DIR] [--expect EXPR ...]:
// one report comparing recorded runs, a verdict on stdout, and --expect
// checks over the runs' summaries addressed by run label (folder name).
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "app/output/run_folder.hpp"
#include "report/compare_report.hpp"

namespace elbowsim {

namespace {

namespace fs = std::filesystem;

// Loads every folder; labels are the folder names, made unique.
std::vector<report::RunData> load_runs(const std::vector<std::string>& folders) {
  std::vector<report::RunData> runs;
  std::vector<std::string> names;
  for (const std::string& folder : folders) {
    runs.push_back(load_run_folder(folder));
    names.push_back(runs.back().label);
  }
  const auto labels = report::unique_labels(names);
  for (std::size_t k = 0; k < runs.size(); ++k) runs[k].label = labels[k];
  return runs;
}

// Default output: "compare" beside the first run folder.
fs::path default_out(const std::string& first) {
  return fs::weakly_canonical(fs::absolute(first)).parent_path() / "compare";
}

}  // namespace

int compare_command(const CompareArguments& args) {
  if (args.folders.size() < 2) {
    std::cerr << "error: compare needs two or more run folders\n";
    return exit_bad_input;
  }
  if (!expectations_well_formed(args.expect)) return exit_bad_input;
  std::vector<report::RunData> runs;
  try {
    runs = load_runs(args.folders);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  const fs::path out = args.out ? fs::path(*args.out) : default_out(args.folders[0]);
  for (const report::RunData& run : runs)
    if (fs::weakly_canonical(fs::absolute(out)) == fs::weakly_canonical(fs::absolute(run.folder))) {
      std::cerr << "error: --out " << out.string() << " is run folder " << run.label
                << ": the comparison would replace its report\n";
      return exit_bad_input;
    }
  try {
    const report::ComparisonFiles files = report::write_comparison_report(runs, out);
    for (const std::string& sentence : files.comparison.verdict) std::cout << sentence << '\n';
    std::cout << "report: " << files.html.string() << '\n';
  } catch (const std::exception& e) {
    std::cerr << "error: compare: " << e.what() << '\n';
    return exit_io;
  }
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const report::RunData& run : runs) metrics[run.label] = run.summary;
  return check_expectations(args.expect, metrics);
}

}  // namespace elbowsim
