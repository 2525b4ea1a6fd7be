#include "report/merged_study.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "report/noise_floor.hpp"
#include "report/statistics.hpp"

namespace elbowsim::report {

namespace {

constexpr double kLevel = 0.95;
constexpr int kResamples = 2000;
constexpr std::uint64_t kSeed = 1;  // the intervals' resampling: fixed, so the table is too

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string cell(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "";
  return value.is_boolean() ? (value.get<bool>() ? "true" : "false") : value.dump();
}

// Every metric path in order of first appearance over the rows.
std::vector<std::pair<std::string, std::string>> metric_columns(const MergedStudy& s) {
  std::vector<std::pair<std::string, std::string>> out;
  std::map<std::string, bool> seen;
  for (const MergedRow& r : s.rows)
    for (const Metric& m : r.metrics)
      if (!seen[m.path]) {
        seen[m.path] = true;
        out.emplace_back(m.path, m.unit);
      }
  return out;
}

std::string number(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x).dump() : ""; }

}  // namespace

const std::vector<std::string>& headline_paths() {
  static const std::vector<std::string> paths = {"metrics.energy_in", "metrics.joule",
                                                 "metrics.hand_error_rms", "metrics.hand_error_max"};
  return paths;
}

Estimate headline_estimate(const std::vector<double>& values, std::size_t h) {
  const Scale scale = headline_paths()[h] == "metrics.energy_in" ? Scale::linear : Scale::log;
  return estimate_mean(values, scale, kLevel, kResamples, kSeed);
}

std::vector<MergedPoint> merged_points(const MergedStudy& s) {
  const long per_point = std::max(1L, s.draws);
  std::vector<MergedPoint> out;
  std::map<std::pair<long, std::string>, std::size_t> index;  // (point, variant) -> out
  for (std::size_t r = 0; r < s.rows.size(); ++r) {
    const MergedRow& row = s.rows[r];
    const auto key = std::make_pair(row.index / per_point, row.variant);
    if (!index.count(key)) {
      index[key] = out.size();
      out.push_back({r, row.variant, 0, 0, std::vector<std::vector<double>>(headline_paths().size())});
    }
    MergedPoint& p = out[index[key]];
    ++p.runs;
    if (row.status != "done" || !row.valid) continue;
    ++p.valid;
    for (std::size_t h = 0; h < headline_paths().size(); ++h)
      if (const Metric* m = find_metric(row.metrics, headline_paths()[h]); m && m->value.is_number())
        p.values[h].push_back(m->value.get<double>());
  }
  return out;
}

void write_merged_table(std::ostream& out, const MergedStudy& s) {
  const auto metrics = metric_columns(s);
  out << "case";
  for (const std::string& c : s.columns) out << ',' << csv_field(c);
  if (s.draws > 0) out << ",draw";
  out << ",variant,status,failure";
  for (const auto& [path, unit] : metrics) out << ',' << csv_field(unit.empty() ? path : path + " [" + unit + "]");
  out << '\n';
  for (const MergedRow& r : s.rows) {
    out << csv_field(r.folder);
    for (const std::string& v : r.values) out << ',' << csv_field(v);
    if (s.draws > 0) out << ',' << r.draw;
    out << ',' << csv_field(r.variant) << ',' << r.status << ',' << csv_field(r.failure);
    for (const auto& [path, unit] : metrics) {
      const Metric* m = find_metric(r.metrics, path);
      out << ',' << (m ? cell(m->value) : "");
    }
    out << '\n';
  }
}

void write_points_table(std::ostream& out, const MergedStudy& s) {
  out << "point";
  for (const std::string& c : s.columns) out << ',' << csv_field(c);
  out << ",variant,runs,valid";
  for (const std::string& h : headline_paths()) {
    const std::string unit = metric_unit(h).empty() ? "" : " [" + metric_unit(h) + "]";
    out << ',' << h << " mean" << unit << ',' << h << " ci95 low," << h << " ci95 high," << h << " median";
  }
  out << '\n';
  const long per_point = std::max(1L, s.draws);
  for (const MergedPoint& p : merged_points(s)) {
    const MergedRow& row = s.rows[p.row];
    out << row.index / per_point;
    for (const std::string& v : row.values) out << ',' << csv_field(v);
    out << ',' << csv_field(p.variant) << ',' << p.runs << ',' << p.valid;
    for (std::size_t h = 0; h < p.values.size(); ++h) {
      if (p.values[h].empty()) {
        out << ",,,,";
        continue;
      }
      const Estimate e = headline_estimate(p.values[h], h);
      out << ',' << number(e.mean) << ',' << (e.ci ? number(e.ci->low) : "") << ','
          << (e.ci ? number(e.ci->high) : "") << ',' << number(e.median);
    }
    out << '\n';
  }
}

}  // namespace elbowsim::report
