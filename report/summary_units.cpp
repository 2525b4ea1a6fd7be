#include "report/summary_units.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "engine/recording/metrics.hpp"

namespace elbowsim::report {

namespace {

struct KeyUnit {
  const char* pattern;  // dotted path; "*" stands for any one key or list index
  const char* unit;
};

// Every number of summary.json (app/output/summary_json.cpp, app/commands/step_check.cpp)
// but the metrics, whose units the metric vocabulary gives (engine/recording/metrics.hpp).
// A key added there without a line here fails units_json, and with it every run.
constexpr KeyUnit kKeyUnits[] = {
    {"model.dof", "1"},
    {"model.total_mass", "kg"},
    {"model.hand_link", "1"},
    {"settings.step", "s"},
    {"settings.duration", "s"},
    {"settings.rtol", "1"},
    {"settings.atol", "state"},
    {"settings.max_step", "s"},
    {"steps", "1"},
    {"integrator_work.*", "1"},
    {"final_time", "s"},
    {"wall_seconds", "s"},
    {"energy_initial.*", "J"},
    {"energy_final.*", "J"},
    {"balance_residual", "J"},
    {"max_abs_balance_residual", "J"},
    {"balance_residual_relative", "1"},
    {"control_loop.sample_rate", "Hz"},
    {"control_loop.delay_samples", "1"},
    {"control_loop.pwm_bits", "1"},
    {"control_loop.encoder_counts_per_rev", "1"},
    {"control_loop.angle_noise", "rad"},
    {"control_loop.velocity_cutoff", "Hz"},
    {"control_loop.noise_seed", "1"},
    {"contact.collision_worlds_built", "1"},
    {"contact.elbows", "1"},
    {"contact.landings", "1"},
    {"contact.releases", "1"},
    {"contact.sticks", "1"},
    {"contact.slips", "1"},
    {"contact.max_abs_C", "m"},
    {"contact.max_abs_Jc_qd", "m/s"},
    {"contact.dependent_steps", "1"},
    {"contact.bodies.*.link", "1"},
    {"contact.bodies.*.rest_fraction", "1"},
    {"contact.bodies.*.force_mean", "N"},
    {"contact.bodies.*.force_peak", "N"},
    {"contact.bodies.*.friction_work", "J"},
    {"contact.bodies.*.landings", "1"},
    {"contact.bodies.*.releases", "1"},
    {"contact.bodies.*.sticks", "1"},
    {"contact.bodies.*.slips", "1"},
    {"saturation_share.*", "1"},
    {"step_check.step", "s"},
    {"step_check.half_step", "s"},
    {"step_check.metrics.*.relative_change", "1"},
};

std::vector<std::string_view> split(std::string_view path) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

bool matches(std::string_view pattern, const std::vector<std::string_view>& path) {
  const std::vector<std::string_view> want = split(pattern);
  if (want.size() != path.size()) return false;
  for (std::size_t k = 0; k < want.size(); ++k)
    if (want[k] != "*" && want[k] != path[k]) return false;
  return true;
}

// A metric's unit: the vocabulary's, "1" for its ratios and counts; "" for no metric.
std::string metric_unit_of(std::string_view name) {
  const std::string n(name);
  if (!is_metric(n)) return "";
  const std::string unit = metric_unit(n);
  return unit.empty() ? "1" : unit;
}

void collect(const nlohmann::ordered_json& node, const std::string& path,
             nlohmann::ordered_json& units) {
  const bool numbers = node.is_array() && !node.empty() &&
                       std::all_of(node.begin(), node.end(), [](const auto& v) { return v.is_number(); });
  if (node.is_number() || numbers) {
    const std::string unit = summary_unit(numbers ? path + ".0" : path);
    if (unit.empty())
      throw std::logic_error("summary.json: no unit for '" + path +
                             "' (report/summary_units.cpp lists every key's unit)");
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
  // metrics.<name> and metrics.<name>.<joint, elbow or index>
  if (parts[0] == "metrics" && (parts.size() == 2 || parts.size() == 3))
    return metric_unit_of(parts[1]);
  // step_check.metrics.<name>.{value, at_half_step, floor}: the metric's own unit
  if (parts.size() == 4 && parts[0] == "step_check" && parts[1] == "metrics" &&
      (parts[3] == "value" || parts[3] == "at_half_step" || parts[3] == "floor"))
    return metric_unit_of(parts[2]);
  for (const KeyUnit& k : kKeyUnits)
    if (matches(k.pattern, parts)) return k.unit;
  return "";
}

nlohmann::ordered_json units_json(const nlohmann::ordered_json& summary) {
  nlohmann::ordered_json units = nlohmann::ordered_json::object();
  for (const auto& [key, value] : summary.items())
    if (key != "units") collect(value, key, units);
  return units;
}

nlohmann::ordered_json with_units(const nlohmann::ordered_json& summary) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  if (summary.contains("provenance")) out["provenance"] = summary["provenance"];
  out["units"] = units_json(summary);
  for (const auto& [key, value] : summary.items())
    if (key != "provenance" && key != "units") out[key] = value;
  return out;
}

}  // namespace elbowsim::report
