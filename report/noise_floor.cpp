#include "report/noise_floor.hpp"

#include <algorithm>
#include <cmath>

#include "engine/recording/number_text.hpp"
#include "report/energy_flow.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;
namespace key = summary_key;

// Whether `path` lies inside the key's object ("settings.step" inside "settings").
bool inside(const std::string& path, const SummaryKey& k) {
  return path.starts_with(std::string(k.path) + ".");
}

// Whether `path` is the one-value metric `name` ("metrics.<name>").
bool is_metric(const std::string& path, std::string_view name) {
  return path == key::metric_path(name);
}

bool is_energy(const std::string& path) {
  return inside(path, key::energy_final) || path == key::balance_residual.path ||
         path == key::max_abs_balance_residual.path || is_metric(path, metric::energy_in) ||
         is_metric(path, metric::joule) || is_metric(path, metric::energy_drawn) ||
         is_metric(path, metric::energy_regenerated) ||
         key::metric_of(path) == metric::energy_in_per_joint;
}

// The family a metric is scaled with: the path without its joint or elbow
// ("metrics.current_rms.2" -> "metrics.current_rms"); all hand-error
// measures together, all elbow-force measures together.
std::string family(const std::string& path) {
  const std::string_view metric = key::metric_of(path);
  if (metric.starts_with("hand_error_")) return key::metric_path("hand_error");
  if (metric.starts_with("elbow_force_")) return key::metric_path("elbow_force");
  return metric.empty() ? path : key::metric_path(metric);
}

// The energy that flowed in any of the runs: the sources of its account.
double energy_scale(const std::vector<RunData>& runs) {
  double scale = 0;
  for (const RunData& run : runs)
    if (const auto flow = energy_flow(run.summary)) scale = std::max(scale, flow->total_in);
  return scale;
}

double family_scale(const std::string& fam, const std::vector<std::vector<Metric>>& per_run) {
  double scale = 0;
  for (const auto& metrics : per_run)
    for (const Metric& m : metrics)
      if (m.value.is_number() && family(m.path) == fam)
        scale = std::max(scale, std::abs(m.value.get<double>()));
  return scale;
}

double duration_scale(const std::vector<RunData>& runs) {
  double scale = 0;
  for (const RunData& run : runs)
    if (run.has_summary() && run.summary.contains(key::settings.name()))
      scale = std::max(scale,
                       run.summary[key::settings.name()].value(key::settings_duration.name(), 0.0));
  return scale;
}

// step_check's name of the quantity at `path` ("" when it does not check it).
std::string step_check_name(const std::string& path) {
  if (path == key::energy_final_path(Energy::electrical_in)) return "energy_in";
  if (path == key::energy_final_path(Energy::joule)) return "joule";
  if (path == key::energy_final_path(Energy::drawn)) return "energy_drawn";
  if (path == key::energy_final_path(Energy::regenerated)) return "energy_regenerated";
  const std::string_view metric = key::metric_of(path);
  return is_metric(path, metric) ? std::string(metric) : "";
}

// The largest |value - at_half_step| over the runs; negative when a run did not measure it.
double step_change(const std::string& path, const std::vector<RunData>& runs) {
  const std::string name = step_check_name(path);
  if (name.empty() || runs.empty()) return -1;
  double change = 0;
  for (const RunData& run : runs) {
    const Json::json_pointer at(key::json_pointer(key::checked_metric_path(name)));
    if (!run.has_summary() || !run.summary.contains(at)) return -1;
    const Json& m = run.summary[at];
    const std::string_view value = key::checked_value.name(),
                           half = key::checked_at_half_step.name();
    if (!m.value(value, Json()).is_number() || !m.value(half, Json()).is_number()) return -1;
    change = std::max(change, std::abs(m[value].get<double>() - m[half].get<double>()));
  }
  return change;
}

bool exact_kind(const std::string& path) {
  for (const SummaryKey& count : {key::contact_landings, key::contact_releases, key::contact_sticks,
                                  key::contact_slips, key::contact_dependent_steps})
    if (path == count.path) return true;
  return false;
}

std::string relative_basis(const char* what, double scale, const std::string& unit) {
  return "1 % of " + std::string(what) + " (" + quantity(scale, unit) + ")";
}

}  // namespace

const char* to_string(MetricKind kind) {
  switch (kind) {
    case MetricKind::result:
      return "result";
    case MetricKind::numerics:
      return "numerics";
    case MetricKind::timing:
      return "timing";
    case MetricKind::setting:
      return "setting";
  }
  return "result";
}

MetricKind metric_kind(const std::string& path) {
  for (const SummaryKey& k : {key::settings, key::model, key::control_loop, key::energy_initial})
    if (inside(path, k)) return MetricKind::setting;
  if (path == key::step_check_step.path || path == key::step_check_half_step.path ||
      path == key::contact_elbows.path)
    return MetricKind::setting;
  if (path == key::wall_seconds.path || path == key::steps.path ||
      inside(path, key::integrator_work) || is_metric(path, metric::samples) ||
      path == key::contact_collision_worlds_built.path)
    return MetricKind::timing;
  if (inside(path, key::step_check) || path == key::balance_residual.path ||
      path == key::max_abs_balance_residual.path || path == key::balance_residual_relative.path ||
      path == key::contact_max_abs_C.path || path == key::contact_max_abs_Jc_qd.path ||
      path == key::contact_dependent_steps.path || key::metric_of(path) == metric::elbow_drift_max)
    return MetricKind::numerics;
  return MetricKind::result;
}

NoiseFloor noise_floor(const std::string& path, const std::vector<RunData>& runs,
                       const std::vector<std::vector<Metric>>& per_run) {
  const MetricKind kind = metric_kind(path);
  if (kind == MetricKind::setting || kind == MetricKind::timing || exact_kind(path))
    return {0, path == key::wall_seconds.path ? "timing: ratios within 1.25 are noise" : "exact"};
  if (path == key::contact_max_abs_C.path || key::metric_of(path) == metric::elbow_drift_max)
    return {1e-9, "absolute (drift that should be 0)"};
  if (path == key::contact_max_abs_Jc_qd.path) return {1e-9, "absolute (drift that should be 0)"};
  if (path == key::balance_residual_relative.path)
    return {1e-3, "absolute (a residual that should be 0)"};
  if (key::metric_of(path) == metric::rest_fraction) return {0.01, "absolute (a share of the run)"};
  if (const double change = step_change(path, runs); change >= 0)
    return {kStepFloorFactor * change, "twice the change at half the step (--check-step)"};
  if (is_energy(path)) {
    const double scale = energy_scale(runs);
    if (scale > 0)
      return {kEnergyFloor * scale,
              "0.1 % of the energy that flowed (" + quantity(scale, "J") + ")"};
  }
  if (path == key::final_time.path || is_metric(path, metric::time_in_contact)) {
    const double scale = duration_scale(runs);
    return {kRelativeFloor * scale, relative_basis("the duration", scale, "s")};
  }
  const double scale = family_scale(family(path), per_run);
  const std::string unit = metric_unit(path);
  std::string name = family(path);
  if (const std::string_view metric = key::metric_of(name); !metric.empty()) name = metric;
  return {kRelativeFloor * scale,
          relative_basis(("the largest " + name + " of the runs").c_str(), scale, unit)};
}

bool same_within(const std::vector<Json>& values, MetricKind kind, const NoiseFloor& floor,
                 const std::string& path) {
  if (values.empty()) return true;
  const Json& ref = values[0];
  for (const Json& v : values) {
    if (v.is_null() || ref.is_null()) {
      if (v.is_null() != ref.is_null()) return false;
      continue;
    }
    if (!v.is_number() || !ref.is_number()) {
      if (v != ref) return false;
      continue;
    }
    const double a = ref.get<double>(), b = v.get<double>();
    if (path == key::wall_seconds.path) {
      if (!(a > 0 && b > 0 && std::max(a / b, b / a) <= kTimingNoise) && a != b) return false;
      continue;
    }
    if (kind == MetricKind::setting || kind == MetricKind::timing) {
      if (a != b) return false;
      continue;
    }
    if (!(std::abs(b - a) <= floor.value)) return false;
  }
  return true;
}

}  // namespace elbowsim::report
