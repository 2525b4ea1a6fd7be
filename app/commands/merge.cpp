// elbowsim merge DIR...: the table and report of a study (elbowsim study)
// from its case folders: DIR/cases.json names the cases, each finished case
// its runs (case.json), and each run its numbers (summary.json). The
// folders may be one study's shards written apart (each with the same
// cases.json); a case is taken from the first folder that finished it.
// Writes OUT/table.csv, with draws OUT/points.csv, and OUT/report.html.
#include <fstream>
#include <iostream>

#include "app/commands/commands.hpp"
#include "app/output/atomic_file.hpp"
#include "app/study/case_record.hpp"
#include "engine/recording/number_text.hpp"
#include "report/merged_study.hpp"
#include "report/noise_floor.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim {

namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

Json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path.string() + ": not found (is this a study folder? elbowsim study writes it)");
  try {
    return Json::parse(in);
  } catch (const std::exception& e) {
    throw std::invalid_argument(path.string() + ": not readable JSON (" + e.what() + ")");
  }
}

// The rows of case `c` (one per variant) from the first folder that finished it.
void add_case(report::MergedStudy& s, const Json& c, const std::vector<fs::path>& folders) {
  const std::string name = c.at("folder").get<std::string>();
  std::optional<study::CaseRecord> record;
  fs::path where;
  for (const fs::path& f : folders)
    if ((record = study::finished_case(f / name))) {
      where = f / name;
      break;
    }
  for (const std::string& variant : s.variants) {
    report::MergedRow row;
    row.index = c.at("index").get<long>();
    row.folder = name;
    row.values = c.at("values").get<std::vector<std::string>>();
    row.draw = c.at("draw").is_null() ? -1 : c.at("draw").get<long>();
    row.variant = variant;
    row.status = record ? "done" : "missing";
    if (record)
      for (const auto& [v, reason] : record->failures)
        if (v == variant) row.status = "failed", row.failure = reason;
    const fs::path run = study::run_folder(where, variant);
    if (record && fs::exists(run / "summary.json")) {
      row.run = run;
      const Json summary = read_json(run / "summary.json");
      row.valid = summary.value(summary_key::valid.name(), false);
      for (report::Metric& m : report::summary_metrics(summary))
        if (report::metric_kind(m.path) != report::MetricKind::timing) row.metrics.push_back(std::move(m));
    }
    s.rows.push_back(std::move(row));
  }
}

report::MergedStudy merged(const std::vector<fs::path>& folders) {
  const Json manifest = read_json(folders.front() / "cases.json");
  for (std::size_t k = 1; k < folders.size(); ++k) {
    const Json other = read_json(folders[k] / "cases.json");
    for (const char* key : {"set", "columns", "variants", "draws", "cases"})
      if (other.value(key, Json()) != manifest.value(key, Json()))
        throw std::invalid_argument(folders[k].string() + " holds another study than " + folders.front().string() +
                                    " (cases.json differs in \"" + key + "\")");
  }
  report::MergedStudy s;
  s.name = manifest.value("study", "");
  s.scenario = manifest.value("scenario", "");
  s.columns = manifest.at("columns").get<std::vector<std::string>>();
  s.variants = manifest.at("variants").get<std::vector<std::string>>();
  s.draws = manifest.value("draws", 0L);
  for (const Json& c : manifest.at("cases")) add_case(s, c, folders);
  return s;
}

}  // namespace

int merge_command(const MergeArguments& args) {
  std::vector<fs::path> folders(args.folders.begin(), args.folders.end());
  const fs::path out = args.out ? fs::path(*args.out) : folders.front();
  report::MergedStudy s;
  try {
    s = merged(folders);
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: merge: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "error: merge: " << e.what() << '\n';
    return exit_io;
  }
  long done = 0, failed = 0, missing = 0;
  for (const report::MergedRow& r : s.rows) {
    done += r.status == "done";
    failed += r.status == "failed";
    missing += r.status == "missing";
  }
  try {
    fs::create_directories(out);
    write_atomically(out / "table.csv", [&](std::ostream& o) { report::write_merged_table(o, s); });
    if (s.draws > 0)
      write_atomically(out / "points.csv", [&](std::ostream& o) { report::write_points_table(o, s); });
    const fs::path html = report::write_merged_report(s, out);
    std::cout << "study " << s.name << ": " << counted(static_cast<long long>(s.rows.size()), "run")
              << " (" << done << " done, " << failed << " failed, " << missing
              << " missing); table " << (out / "table.csv").string()
              << (s.draws > 0 ? ", points " + (out / "points.csv").string() : "") << ", report "
              << html.string() << '\n';
  } catch (const std::exception& e) {
    std::cerr << "error: merge: " << e.what() << '\n';
    return exit_io;
  }
  if (missing) {
    std::cerr << "warning: " << counted(missing, "run") << (missing == 1 ? " is" : " are")
              << " missing: run the study again (or its shards) to finish them\n";
    return exit_run_failed;
  }
  return exit_ok;
}

}  // namespace elbowsim
