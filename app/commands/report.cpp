// elbowsim report RUN_DIR [--expect EXPR ...]: rebuilds report.html and its
// plots from a run folder without simulating; also the --expect checks that
// run, report and compare share.
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "app/output/run_folder.hpp"
#include "app/output/run_manifest.hpp"
#include "report/expect.hpp"
#include "report/run_report.hpp"

namespace elbowsim {

bool expectations_well_formed(const std::vector<std::string>& expressions) {
  bool ok = true;
  report::parse_expectations(expressions, std::cerr, ok);
  return ok;
}

bool expectations_fit(const std::vector<std::string>& expressions,
                      const nlohmann::ordered_json& shape) {
  bool ok = true;
  for (const report::Expectation& e : report::parse_expectations(expressions, std::cerr, ok)) {
    try {
      e.check_paths(shape);
    } catch (const report::ExpectError& error) {
      std::cerr << report::describe(error);
      ok = false;
    }
  }
  return ok;
}

int check_expectations(const std::vector<std::string>& expressions,
                       const nlohmann::ordered_json& metrics) {
  if (expressions.empty()) return exit_ok;
  bool ok = true;
  const auto parsed = report::parse_expectations(expressions, std::cerr, ok);
  if (!ok) return exit_bad_input;
  switch (report::check_expectations(parsed, metrics, std::cout, std::cerr)) {
    case report::ExpectStatus::met:
      return exit_ok;
    case report::ExpectStatus::failed:
      return exit_expectation_failed;
    case report::ExpectStatus::invalid:
      return exit_bad_input;
  }
  return exit_bad_input;
}

namespace {

// Loads the folder and writes its report; the exit code, and the run read.
int write_report(const std::filesystem::path& folder, report::RunData& run) {
  try {
    run = load_run_folder(folder);
  } catch (const NotARunFolder& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  try {
    const report::ReportFiles files = report::write_run_report(run);
    add_to_manifest(folder, {"report.html", "plots/"});
    std::cout << "report: " << files.html.string() << " (" << files.figures.figures.size()
              << " plots)\n";
    return exit_ok;
  } catch (const std::exception& e) {
    std::cerr << "error: report: " << e.what() << '\n';
    return exit_io;
  }
}

}  // namespace

int report_outputs(const std::filesystem::path& folder) {
  report::RunData run;
  return write_report(folder, run);
}

int report_command(const ReportArguments& args) {
  if (!expectations_well_formed(args.expect)) return exit_bad_input;
  report::RunData run;
  const int written = write_report(args.folder, run);
  if (written != exit_ok || args.expect.empty()) return written;
  if (!run.has_summary()) {
    std::cerr << "error: --expect: " << args.folder << " has no readable summary.json\n";
    return exit_bad_input;
  }
  return check_expectations(args.expect, run.summary);
}

}  // namespace elbowsim
