#include "app/study/study_cases.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "report/provenance.hpp"

namespace elbowsim::study {

namespace {

constexpr std::size_t kLabelLength = 48;  // characters after the index

// "elbows[0].at" -> "at"; "task.duration" -> "duration".
std::string short_key(const std::string& key) {
  std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  return safe_label(last.substr(0, last.find('[')));
}

// The name piece of each column: the key's last part, or the whole key made
// safe where two columns share a last part; named levels show alone.
std::vector<std::string> column_labels(const StudyDesign& d, const std::vector<std::string>& columns) {
  std::map<std::string, int> count;
  for (const std::string& c : columns) ++count[short_key(c)];
  std::vector<std::string> out;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const bool named = !d.grid.empty() && d.grid[k].key.empty();
    out.push_back(named ? "" : count[short_key(columns[k])] > 1 ? safe_label(columns[k]) : short_key(columns[k]));
  }
  return out;
}

std::string folder_name(long index, long count, const std::vector<std::string>& parts) {
  std::string number = std::to_string(index);
  const std::size_t width = std::max<std::size_t>(3, std::to_string(std::max(0L, count - 1)).size());
  number.insert(0, width - std::min(width, number.size()), '0');
  std::string label;
  for (const std::string& p : parts)
    if (!p.empty()) label += (label.empty() ? "" : "-") + p;
  if (label.size() > kLabelLength) label.resize(kLabelLength);
  while (!label.empty() && (label.back() == '-' || label.back() == '_')) label.pop_back();
  return label.empty() ? number : number + "-" + label;
}

// The points of the design before draws: overrides and column values.
std::vector<CaseSpec> points(const StudyDesign& d, const std::vector<std::string>& columns) {
  std::vector<CaseSpec> out;
  if (!d.grid.empty()) {
    out.push_back({});
    for (const StudyDesign::Axis& axis : d.grid) {
      std::vector<CaseSpec> next;
      for (const CaseSpec& c : out)
        for (const StudyDesign::Level& level : axis.levels) {
          CaseSpec n = c;
          n.overrides.insert(n.overrides.end(), level.overrides.begin(), level.overrides.end());
          n.values.push_back(level.label);
          next.push_back(std::move(n));
        }
      out = std::move(next);
    }
    return out;
  }
  for (const auto& item : d.list) {
    CaseSpec c;
    c.values.assign(columns.size(), "");
    for (const auto& [key, value] : item) {
      c.overrides.push_back(key + "=" + value);
      c.values[std::find(columns.begin(), columns.end(), key) - columns.begin()] = value;
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

std::string safe_label(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-';
    if (keep) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

std::vector<std::string> case_columns(const StudyDesign& d) {
  std::vector<std::string> columns;
  for (const StudyDesign::Axis& a : d.grid) columns.push_back(a.name);
  for (const auto& item : d.list)
    for (const auto& [key, value] : item)
      if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
  return columns;
}

std::vector<CaseSpec> enumerate_cases(const StudyDesign& d) {
  const std::vector<std::string> columns = case_columns(d);
  const std::vector<std::string> labels = column_labels(d, columns);
  std::vector<CaseSpec> cases;
  for (const CaseSpec& p : points(d, columns))
    for (long draw = d.draws > 0 ? 0 : -1; draw < std::max(0L, d.draws); ++draw) {
      CaseSpec c = p;
      c.draw = draw;
      cases.push_back(std::move(c));
    }
  const long count = static_cast<long>(cases.size());
  for (long k = 0; k < count; ++k) {
    CaseSpec& c = cases[k];
    c.index = k;
    std::vector<std::string> parts;
    for (std::size_t j = 0; j < columns.size(); ++j) {
      if (c.values[j].empty()) continue;
      const std::string value = safe_label(c.values[j]);
      parts.push_back(labels[j].empty() ? value : labels[j] + "_" + value);
    }
    if (c.draw >= 0) parts.push_back('d' + std::to_string(c.draw));
    c.folder = folder_name(k, count, parts);
  }
  return cases;
}

bool in_shard(long index, int shard, int shards) { return index % shards == shard - 1; }

nlohmann::ordered_json cases_manifest(const StudyDesign& d, const std::vector<CaseSpec>& cases,
                                      const std::vector<std::string>& variants, std::uint64_t seed) {
  nlohmann::ordered_json doc;
  doc["provenance"] = report::provenance_json();  // of the process that wrote it first
  doc["study"] = d.name;
  doc["scenario"] = d.scenario;
  doc["set"] = d.sets;
  doc["columns"] = case_columns(d);
  doc["variants"] = variants;
  doc["draws"] = d.draws;
  if (d.draws > 0) doc["seed"] = seed;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const CaseSpec& c : cases) {
    nlohmann::ordered_json row{{"index", c.index}, {"folder", c.folder}, {"overrides", c.overrides}};
    row["values"] = c.values;
    row["draw"] = c.draw >= 0 ? nlohmann::ordered_json(c.draw) : nlohmann::ordered_json(nullptr);
    rows.push_back(row);
  }
  doc["cases"] = rows;
  return doc;
}

}  // namespace elbowsim::study
