// elbowsim compare RUN_DIR RUN_DIR ... [--out DIR] [--expect EXPR ...]:
// one report comparing recorded runs, a verdict on stdout, and --expect
// checks over the runs' summaries addressed by run label (folder name).
#include <iostream>
#include <set>
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "app/output/run_folder.hpp"
#include "app/scenario/scenario_keys.hpp"
#include "report/compare_report.hpp"

namespace elbowsim {

namespace {

namespace fs = std::filesystem;

// Loads every folder; labels are --label's, else the folder names made unique.
std::vector<report::RunData> load_runs(const std::vector<std::string>& folders,
                                       const std::vector<std::string>& given) {
  std::vector<report::RunData> runs;
  std::vector<std::string> names;
  for (const std::string& folder : folders) {
    runs.push_back(load_run_folder(folder));
    names.push_back(runs.back().label);
  }
  const auto labels = given.empty() ? report::unique_labels(names) : given;
  for (std::size_t k = 0; k < runs.size(); ++k) runs[k].label = labels[k];
  return runs;
}

// --label: one per run, each unique and usable in --expect paths.
std::string labels_problem(const CompareArguments& args) {
  if (args.labels.empty()) return "";
  if (args.labels.size() != args.folders.size())
    return "--label given " + std::to_string(args.labels.size()) + " times for " +
           std::to_string(args.folders.size()) + " runs: give one per run, in order";
  std::set<std::string> seen;
  for (const std::string& l : args.labels) {
    if (l.empty() || l.find_first_of(". <>=!&|()\"") != std::string::npos)
      return "--label \"" + l + "\": a label is letters, digits, _ or - (it starts --expect paths)";
    if (!seen.insert(l).second) return "--label " + l + " is given twice";
  }
  return "";
}

// The scenario keys that differ between the runs' scenario.yaml files.
std::vector<std::pair<std::string, std::vector<std::string>>> differing(const std::vector<report::RunData>& runs) {
  std::vector<std::string> texts;
  for (const report::RunData& r : runs) texts.push_back(r.scenario_yaml);
  std::vector<std::pair<std::string, std::vector<std::string>>> out;
  for (const KeyDifference& d : differing_keys(texts)) out.emplace_back(d.key, d.values);
  return out;
}

// Default output: "compare" beside the first run folder.
fs::path default_out(const std::string& first) {
  return fs::weakly_canonical(fs::absolute(first)).parent_path() / "compare";
}

}  // namespace

void print_verdict(const report::Comparison& comparison) {
  for (const std::string& sentence : comparison.verdict) std::cout << sentence << '\n';
}

int compare_command(const CompareArguments& args) {
  if (args.folders.size() < 2) {
    std::cerr << "error: compare needs two or more run folders\n";
    return exit_bad_input;
  }
  if (!expectations_well_formed(args.expect)) return exit_bad_input;
  if (const std::string problem = labels_problem(args); !problem.empty()) {
    std::cerr << "error: compare: " << problem << '\n';
    return exit_bad_input;
  }
  std::vector<report::RunData> runs;
  try {
    runs = load_runs(args.folders, args.labels);
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
    const auto keys = differing(runs);
    const report::ComparisonFiles files = report::write_comparison_report(runs, out, {}, false, keys);
    print_verdict(files.comparison);
    for (const auto& [key, values] : keys) {
      std::cout << "differs: " << key << ":";
      for (std::size_t r = 0; r < runs.size(); ++r)
        std::cout << " " << runs[r].label << " " << (values[r].empty() ? "(not set)" : values[r]) << (r + 1 < runs.size() ? "," : "");
      std::cout << '\n';
    }
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
