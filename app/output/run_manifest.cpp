#include "app/output/run_manifest.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/output/atomic_file.hpp"
#include "report/provenance.hpp"

namespace elbowsim {

const std::vector<std::string>& derived_artefacts() {
  static const std::vector<std::string> names{"video.mp4", "frames", "report.html", "plots"};
  return names;
}

std::string manifest_text(const std::vector<std::string>& files) {
  nlohmann::ordered_json j;
  j["provenance"] = report::provenance_json();  // of the last program to write this list
  j["written_by"] = "elbowsim run";
  j["files"] = files;
  return j.dump(2) + "\n";
}

std::optional<std::vector<std::string>> read_manifest(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / kManifestFile;
  if (!std::filesystem::exists(path)) return std::nullopt;
  std::ifstream in(path);
  try {
    const auto j = nlohmann::json::parse(in);
    return j.at("files").get<std::vector<std::string>>();
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": not a manifest: " + e.what());
  }
}

void add_to_manifest(const std::filesystem::path& folder, const std::vector<std::string>& files) {
  auto listed = read_manifest(folder);
  if (!listed) return;
  for (const std::string& f : files)
    if (std::find(listed->begin(), listed->end(), f) == listed->end()) listed->push_back(f);
  write_atomically(folder / kManifestFile,
                   [&](std::ostream& out) { out << manifest_text(*listed); });
}

void record_rendered(const std::filesystem::path& folder, bool video, bool frames) {
  std::vector<std::string> made;
  if (video && std::filesystem::exists(folder / "video.mp4")) made.push_back("video.mp4");
  if (frames && std::filesystem::exists(folder / "frames")) made.push_back("frames/");
  if (!made.empty()) add_to_manifest(folder, made);
}

bool written_by_run(const std::optional<std::vector<std::string>>& manifest,
                    const std::filesystem::path& folder, const std::string& file) {
  if (!std::filesystem::exists(folder / file)) return false;
  if (!manifest) return true;
  for (const std::string& entry : *manifest)
    if (entry == file || (entry.ends_with('/') && file.rfind(entry, 0) == 0)) return true;
  return false;
}

}  // namespace elbowsim
