#include "report/metrics.hpp"

#include <algorithm>
#include <cmath>

#include "report/columns.hpp"

namespace elbowsim::report {

namespace {

void flatten(const nlohmann::ordered_json& node, const std::string& path,
             std::vector<Metric>& out) {
  if (node.is_object() || node.is_array()) {  // lists by index: metrics.current_peak.0
    for (const auto& [key, value] : node.items())
      flatten(value, path.empty() ? key : path + "." + key, out);
    return;
  }
  if (node.is_number() || node.is_boolean() || node.is_null())
    out.push_back({path, node, metric_unit(path)});
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The unit of a summary.json "metrics" entry (the run's task metrics), from its name.
std::string run_metric_unit(const std::string& name) {
  if (starts_with(name, "hand_error")) return "m";
  if (starts_with(name, "energy") || starts_with(name, "joule")) return "J";
  if (starts_with(name, "current")) return "A";
  if (name.find("force") != std::string::npos) return "N";
  if (starts_with(name, "time")) return "s";
  return "";
}

void add(std::vector<Metric>& out, const std::string& path, double value, const char* unit) {
  out.push_back({"trajectory." + path, value, unit});
}

double peak_abs(const std::vector<double>& y) {
  double peak = 0;
  for (double v : y)
    if (std::isfinite(v)) peak = std::max(peak, std::abs(v));
  return peak;
}

// sqrt(integral y^2 dt / duration): the RMS over time, not over samples.
double rms(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> square(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) square[k] = y[k] * y[k];
  const double duration = t.back() - t.front();
  return duration > 0 ? std::sqrt(running_integral(t, square).back() / duration) : peak_abs(y);
}

void motor_metrics(const Recording& rec, const std::vector<double>& t, std::vector<Metric>& out) {
  for (const std::string& i : indexed_columns(rec, "i")) {
    add(out, "peak_abs_current." + i, peak_abs(column(rec, i)), "A");
    add(out, "rms_current." + i, rms(t, column(rec, i)), "A");
  }
  const auto power = electrical_power(rec);
  if (power.empty()) return;
  add(out, "electrical_energy_from_samples", running_integral(t, power).back(), "J");
  add(out, "peak_electrical_power", *std::max_element(power.begin(), power.end()), "W");
}

void elbow_metrics(const Recording& rec, const std::vector<double>& t, std::vector<Metric>& out) {
  const double duration = t.back() - t.front();
  for (const std::string& elbow : elbow_names(rec)) {
    const auto fn = column(rec, "fn_" + elbow), d = column(rec, "d_" + elbow);
    const auto rest = column(rec, "rest_" + elbow);
    if (!fn.empty()) add(out, "peak_normal_force." + elbow, peak_abs(fn), "N");
    if (rest.empty()) continue;
    double resting = 0, worst = 0;
    for (const auto& i : intervals_on(t, rest)) resting += i.end - i.begin;
    for (std::size_t k = 0; k < std::min(d.size(), rest.size()); ++k)
      if (rest[k] >= 0.5 && std::isfinite(d[k])) worst = std::max(worst, std::abs(d[k]));
    add(out, "rest_fraction." + elbow, duration > 0 ? resting / duration : rest[0], "");
    if (!d.empty()) add(out, "max_abs_d_resting." + elbow, worst, "m");
  }
}

void hand_metrics(const Recording& rec, const std::vector<double>& t, std::vector<Metric>& out) {
  const auto x = column(rec, "hand_x"), y = column(rec, "hand_y"), z = column(rec, "hand_z");
  if (!x.empty() && !y.empty() && !z.empty()) {
    double length = 0;
    for (std::size_t k = 1; k < x.size(); ++k)
      length += std::hypot(x[k] - x[k - 1], y[k] - y[k - 1], z[k] - z[k - 1]);
    add(out, "hand_path_length", length, "m");
  }
  const auto error = column(rec, "hand_error");
  if (error.empty()) return;
  add(out, "rms_hand_error", rms(t, error), "m");
  add(out, "peak_hand_error", peak_abs(error), "m");
}

}  // namespace

std::string metric_unit(const std::string& path) {
  if (starts_with(path, "energy_initial.") || starts_with(path, "energy_final.")) return "J";
  if (path == "balance_residual" || path == "max_abs_balance_residual") return "J";
  if (path == "final_time" || path == "wall_seconds" || path == "settings.step" ||
      path == "settings.duration")
    return "s";
  if (path == "model.total_mass") return "kg";
  if (path == "contact.max_abs_C") return "m";
  if (path == "contact.max_abs_Jc_qd") return "m/s";
  if (starts_with(path, "metrics.")) return run_metric_unit(path.substr(8));
  return "";
}

std::vector<Metric> summary_metrics(const nlohmann::ordered_json& summary) {
  std::vector<Metric> out;
  if (summary.is_object()) flatten(summary, "", out);
  return out;
}

std::vector<Metric> trajectory_metrics(const Recording& rec) {
  std::vector<Metric> out;
  const auto t = column(rec, "time");
  if (t.empty()) return out;
  add(out, "samples", static_cast<double>(t.size()), "");
  motor_metrics(rec, t, out);
  elbow_metrics(rec, t, out);
  hand_metrics(rec, t, out);
  return out;
}

const Metric* find_metric(const std::vector<Metric>& metrics, const std::string& path) {
  for (const Metric& m : metrics)
    if (m.path == path) return &m;
  return nullptr;
}

}  // namespace elbowsim::report
