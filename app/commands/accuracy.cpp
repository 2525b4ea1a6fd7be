// elbowsim accuracy: what accuracy costs in time on a scenario (a
// work-precision study, app/study/work_precision.hpp), for each of its
// variants (or --variant NAME), into DIR: work_precision.csv, accuracy.json
// (with the verdict), report.html and plots/.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

#include "app/commands/commands.hpp"
#include "app/commands/interrupt.hpp"
#include "app/output/atomic_file.hpp"
#include "app/output/folder_lock.hpp"
#include "app/scenario/scenario.hpp"
#include "app/study/work_precision.hpp"
#include "report/accuracy_report.hpp"
#include "report/provenance.hpp"

namespace elbowsim {

namespace {

using Json = nlohmann::ordered_json;

int usage_error(const std::string& message) {
  std::cerr << "error: accuracy: " << message << '\n';
  return exit_bad_input;
}

// "rk4, dopri5" -> the integrators; "" -> all. Empty vector and a message when unknown.
std::vector<IntegratorKind> parse_methods(const std::string& text, std::string& problem) {
  std::vector<IntegratorKind> out;
  if (text.empty()) return out;
  const IntegratorKind all[] = {IntegratorKind::euler, IntegratorKind::semi_implicit_euler,
                                IntegratorKind::rk4, IntegratorKind::dopri5, IntegratorKind::ros34pw2};
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    std::string name = text.substr(start, comma - start);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    bool found = false;
    for (IntegratorKind k : all)
      if (name == to_string(k)) out.push_back(k), found = true;
    if (!found) {
      problem = "--methods: unknown method \"" + name +
                "\" (choose from euler, semi_implicit_euler, rk4, dopri5, ros34pw2)";
      return {};
    }
    start = comma + 1;
  }
  return out;
}

}  // namespace

int accuracy_command(const AccuracyArguments& args) {
  std::string problem;
  study::WorkPrecisionOptions options;
  options.methods = parse_methods(args.methods, problem);
  if (!problem.empty()) return usage_error(problem);
  if (args.points < 2 || args.points > 12) return usage_error("--points must be 2 ... 12");
  if (args.repeats < 1 || args.repeats > 100) return usage_error("--repeats must be 1 ... 100");
  options.points = args.points;
  options.repeats = args.repeats;
  options.alternatives = args.alternatives;

  // Load every variant first: a bad one writes nothing.
  std::vector<Scenario> scenarios;
  try {
    const Scenario base = load_scenario(args.scenario, args.sets);
    std::vector<std::string> names;
    for (const auto& [name, overrides] : base.variants) names.push_back(name);
    if (!args.variant.empty()) {
      if (std::find(names.begin(), names.end(), args.variant) == names.end()) {
        std::string known;
        for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
        return usage_error("--variant " + args.variant + ": " + args.scenario +
                           (names.empty() ? " has no variants" : " has the variants " + known));
      }
      names = {args.variant};
    }
    if (names.empty()) scenarios.push_back(base);
    for (const std::string& name : names)
      scenarios.push_back(load_scenario_variant(args.scenario, name, args.sets));
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  const std::filesystem::path folder =
      args.out.value_or(scenarios.front().output.folder + "/accuracy");
  if (folder.empty()) return usage_error("--out needs a folder name");
  try {
    FolderLock lock(folder);
    install_interrupt_handlers();
    options.stop = &interrupt_flag();
    options.progress = [](const std::string& line) { std::cerr << "accuracy: " << line << '\n'; };
    Json doc;
    doc["provenance"] = report::provenance_json();
    doc["scenario"] = scenarios.front().file;
    doc["studies"] = Json::array();
    for (const Scenario& s : scenarios) {
      if (!s.variant.empty()) std::cerr << "accuracy: variant " << s.variant << '\n';
      Json study = study::work_precision(s, options);
      if (interrupt_exit_code()) {
        std::cerr << "interrupted: the study was stopped; nothing written to " << folder.string() << '\n';
        return interrupt_exit_code();
      }
      doc["studies"].push_back(std::move(study));
    }
    doc["verdict"] = report::work_precision_verdict(doc);
    write_atomically(folder / "work_precision.csv",
                     [&](std::ostream& out) { out << report::work_precision_csv(doc); });
    write_atomically(folder / "accuracy.json", [&](std::ostream& out) { out << doc.dump(2) << '\n'; });
    if (interrupt_exit_code()) {  // while the tables were written: they are whole; no report starts
      std::cerr << "interrupted: wrote work_precision.csv and accuracy.json to " << folder.string()
                << "; no report\n";
      return interrupt_exit_code();
    }
    report::write_accuracy_report(doc, folder);
    for (const Json& v : doc["verdict"])
      for (const Json& row : v["targets"])
        std::cout << (v.value("variant", "").empty() ? "" : v.value("variant", "") + ": ")
                  << row.value("text", "") << '\n';
    std::cout << "accuracy: " << folder.string() << "/report.html, work_precision.csv, accuracy.json\n";
    return exit_ok;
  } catch (const FolderInUse& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  } catch (const study::ReferenceInvalid& e) {
    std::cerr << "error: accuracy: " << e.what() << '\n';
    return exit_run_failed;
  } catch (const std::exception& e) {  // a file not written
    std::cerr << "error: accuracy: " << e.what() << '\n';
    return exit_io;
  }
}

}  // namespace elbowsim
