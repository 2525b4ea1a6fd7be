#include "app/study/case_record.hpp"

#include <fstream>

#include "app/output/atomic_file.hpp"
#include "app/output/run_manifest.hpp"
#include "report/provenance.hpp"

namespace elbowsim::study {

namespace {

using Json = nlohmann::ordered_json;

// Every file the run's manifest lists is there ("plots/" a folder).
bool run_complete(const std::filesystem::path& folder) {
  try {
    const auto manifest = read_manifest(folder);
    if (!manifest) return false;
    for (const std::string& file : *manifest)
      if (!std::filesystem::exists(folder / file)) return false;
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

std::filesystem::path run_folder(const std::filesystem::path& case_folder, const std::string& variant) {
  return variant.empty() ? case_folder : case_folder / variant;
}

void write_case_record(const std::filesystem::path& case_folder, const CaseRecord& r) {
  Json doc{{"provenance", report::provenance_json()},
           {"index", r.index},
           {"folder", r.folder},
           {"status", r.status}};
  Json runs = Json::array(), failures = Json::array();
  for (const std::string& v : r.variants) runs.push_back({{"variant", v}, {"folder", v}});
  for (const auto& [variant, reason] : r.failures) failures.push_back({{"variant", variant}, {"reason", reason}});
  doc["runs"] = runs;
  doc["failures"] = failures;
  write_atomically(case_folder / kCaseFile, [&](std::ostream& out) { out << doc.dump(2) << '\n'; });
}

std::optional<CaseRecord> finished_case(const std::filesystem::path& case_folder) {
  std::ifstream in(case_folder / kCaseFile);
  if (!in) return std::nullopt;
  CaseRecord r;
  try {
    const Json doc = Json::parse(in);
    r.index = doc.at("index").get<long>();
    r.folder = doc.at("folder").get<std::string>();
    r.status = doc.at("status").get<std::string>();
    for (const Json& run : doc.at("runs")) r.variants.push_back(run.at("variant").get<std::string>());
    for (const Json& f : doc.at("failures"))
      r.failures.emplace_back(f.at("variant").get<std::string>(), f.at("reason").get<std::string>());
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (r.status != "done" && r.status != "failed") return std::nullopt;
  for (const std::string& v : r.variants)
    if (!run_complete(run_folder(case_folder, v))) return std::nullopt;
  return r;
}

}  // namespace elbowsim::study
