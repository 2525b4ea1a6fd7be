#include "report/summary_units.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "engine/recording/metrics.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

std::vector<std::string_view> split(std::string_view path) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

// A metric's unit: the vocabulary's, "1" for its ratios and counts; "" for no metric.
std::string metric_unit_of(std::string_view name) {
  const std::string n(name);
  if (!is_metric(n)) return "";
  const std::string unit = metric_unit(n);
  return unit.empty() ? "1" : unit;
}

bool matches(std::string_view pattern, const std::vector<std::string_view>& path) {
  const std::vector<std::string_view> want = split(pattern);
  if (want.size() != path.size()) return false;
  for (std::size_t k = 0; k < want.size(); ++k)
    if (want[k] != "*" && want[k] != path[k]) return false;
  return true;
}

// The key whose path matches `parts`, or nullptr.
const SummaryKey* find_key(const std::vector<std::string_view>& parts) {
  for (const SummaryKey& k : summary_key::kAll)
    if (matches(k.path, parts)) return &k;
  return nullptr;
}

void collect(const nlohmann::ordered_json& node, const std::string& path,
             nlohmann::ordered_json& units) {
  const bool numbers = node.is_array() && !node.empty() &&
                       std::all_of(node.begin(), node.end(), [](const auto& v) { return v.is_number(); });
  if (node.is_number() || numbers) {
    const std::string unit = summary_unit(numbers ? path + ".0" : path);
    if (unit.empty())
      throw std::logic_error("summary.json: no unit for '" + path +
                             "' (report/summary_keys.hpp lists every key with its unit)");
    units[path] = unit;
    return;
  }
  if (node.is_object() || node.is_array())
    for (const auto& [key, value] : node.items())
      collect(value, path.empty() ? key : path + "." + key, units);
}

}  // namespace

std::string summary_unit(std::string_view path) {
  const std::vector<std::string_view> parts = split(path);
  const SummaryKey* key = find_key(parts);
  if (!key) return "";
  if (key->unit != summary_key::kMetricUnit) return std::string(key->unit);
  // "metric": the unit of the metric named after "metrics"
  // (metrics.<name>, step_check.metrics.<name>.value, ...).
  for (std::size_t k = 0; k + 1 < parts.size(); ++k)
    if (parts[k] == summary_key::metrics.name()) return metric_unit_of(parts[k + 1]);
  return "";
}

nlohmann::ordered_json units_json(const nlohmann::ordered_json& summary) {
  nlohmann::ordered_json units = nlohmann::ordered_json::object();
  for (const auto& [key, value] : summary.items())
    if (key != summary_key::units.name()) collect(value, key, units);
  return units;
}

nlohmann::ordered_json with_units(const nlohmann::ordered_json& summary) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  const std::string_view provenance = summary_key::provenance.name(),
                         units = summary_key::units.name();
  if (summary.contains(provenance)) out[provenance] = summary[provenance];
  out[units] = units_json(summary);
  for (const auto& [key, value] : summary.items())
    if (key != provenance && key != units) out[key] = value;
  return out;
}

}  // namespace elbowsim::report
