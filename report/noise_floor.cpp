#include "report/noise_floor.hpp"

#include <algorithm>
#include <cmath>

#include "engine/recording/number_text.hpp"
#include "report/energy_flow.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool is_energy(const std::string& path) {
  return starts_with(path, "energy_final.") || path == "balance_residual" ||
         path == "max_abs_balance_residual" || path == "metrics.energy_in" ||
         path == "metrics.joule" || path == "metrics.energy_drawn" ||
         path == "metrics.energy_regenerated" || starts_with(path, "metrics.energy_in_per_joint");
}

// The family a metric is scaled with: the path without its joint or elbow
// ("metrics.current_rms.2" -> "metrics.current_rms"); all hand-error
// measures together, all elbow-force measures together.
std::string family(const std::string& path) {
  if (starts_with(path, "metrics.hand_error_")) return "metrics.hand_error";
  if (starts_with(path, "metrics.elbow_force_")) return "metrics.elbow_force";
  const auto dot = path.rfind('.');
  if (starts_with(path, "metrics.") && dot > 8) return path.substr(0, dot);
  return path;
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
    if (run.has_summary() && run.summary.contains("settings"))
      scale = std::max(scale, run.summary["settings"].value("duration", 0.0));
  return scale;
}

// step_check's name of the quantity at `path` ("" when it does not check it).
std::string step_check_name(const std::string& path) {
  if (path == "energy_final.electrical_in") return "energy_in";
  if (path == "energy_final.joule") return "joule";
  if (path == "energy_final.drawn") return "energy_drawn";
  if (path == "energy_final.regenerated") return "energy_regenerated";
  if (starts_with(path, "metrics.") && path.find('.', 8) == std::string::npos)
    return path.substr(8);
  return "";
}

// The largest |value - at_half_step| over the runs; negative when a run did not measure it.
double step_change(const std::string& path, const std::vector<RunData>& runs) {
  const std::string name = step_check_name(path);
  if (name.empty() || runs.empty()) return -1;
  double change = 0;
  for (const RunData& run : runs) {
    const Json::json_pointer at("/step_check/metrics/" + name);
    if (!run.has_summary() || !run.summary.contains(at)) return -1;
    const Json& m = run.summary[at];
    if (!m.value("value", Json()).is_number() || !m.value("at_half_step", Json()).is_number())
      return -1;
    change = std::max(change, std::abs(m["value"].get<double>() - m["at_half_step"].get<double>()));
  }
  return change;
}

bool exact_kind(const std::string& path) {
  static const char* counts[] = {"contact.landings", "contact.releases", "contact.sticks",
                                 "contact.slips", "contact.dependent_steps"};
  for (const char* c : counts)
    if (path == c) return true;
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
  for (const char* p : {"settings.", "model.", "control_loop.", "energy_initial.",
                        "step_check.step", "step_check.half_step"})
    if (starts_with(path, p)) return MetricKind::setting;
  if (path == "contact.elbows") return MetricKind::setting;
  if (path == "wall_seconds" || path == "steps" || starts_with(path, "integrator_work.") ||
      path == "metrics.samples" || path == "contact.collision_worlds_built")
    return MetricKind::timing;
  if (starts_with(path, "step_check.") || path == "balance_residual" ||
      path == "max_abs_balance_residual" || path == "balance_residual_relative" ||
      starts_with(path, "contact.max_abs_") || path == "contact.dependent_steps" ||
      starts_with(path, "metrics.elbow_drift_max"))
    return MetricKind::numerics;
  return MetricKind::result;
}

NoiseFloor noise_floor(const std::string& path, const std::vector<RunData>& runs,
                       const std::vector<std::vector<Metric>>& per_run) {
  const MetricKind kind = metric_kind(path);
  if (kind == MetricKind::setting || kind == MetricKind::timing || exact_kind(path))
    return {0, path == "wall_seconds" ? "timing: ratios within 1.25 are noise" : "exact"};
  if (path == "contact.max_abs_C" || starts_with(path, "metrics.elbow_drift_max"))
    return {1e-9, "absolute (drift that should be 0)"};
  if (path == "contact.max_abs_Jc_qd") return {1e-9, "absolute (drift that should be 0)"};
  if (path == "balance_residual_relative") return {1e-3, "absolute (a residual that should be 0)"};
  if (starts_with(path, "metrics.rest_fraction")) return {0.01, "absolute (a share of the run)"};
  if (const double change = step_change(path, runs); change >= 0)
    return {kStepFloorFactor * change, "twice the change at half the step (--check-step)"};
  if (is_energy(path)) {
    const double scale = energy_scale(runs);
    if (scale > 0)
      return {kEnergyFloor * scale,
              "0.1 % of the energy that flowed (" + quantity(scale, "J") + ")"};
  }
  if (path == "final_time" || path == "metrics.time_in_contact") {
    const double scale = duration_scale(runs);
    return {kRelativeFloor * scale, relative_basis("the duration", scale, "s")};
  }
  const double scale = family_scale(family(path), per_run);
  const std::string unit = metric_unit(path);
  std::string name = family(path);
  if (starts_with(name, "metrics.")) name = name.substr(8);
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
    if (path == "wall_seconds") {
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
