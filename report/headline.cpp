#include "report/headline.hpp"

#include <cmath>

#include "engine/recording/number_text.hpp"
#include "report/energy_flow.hpp"
#include "report/metrics.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;
namespace key = summary_key;

const Json* at(const RunData& run, std::string_view path) {
  if (!run.has_summary()) return nullptr;
  const Json::json_pointer p(key::json_pointer(path));
  return run.summary.contains(p) ? &run.summary[p] : nullptr;
}

double number(const RunData& run, std::string_view path) {
  const Json* v = at(run, path);
  return v && v->is_number() ? v->get<double>() : NAN;
}

bool has(const RunData& run, std::string_view path) { return at(run, path) != nullptr; }

// The metric behind a headline path: its name in the step check.
std::string checked_metric(const std::string& path) {
  if (path == key::energy_final_path(Energy::electrical_in)) return "energy_in";
  if (path == key::energy_final_path(Energy::joule)) return "joule";
  return std::string(key::metric_of(path));
}

// "below the integration floor (9.43 nm; it moves by 4.4 nm at half the step)".
std::string floor_text(const RunData& run, const Json& m, const std::string& unit) {
  const Json* how = at(run, key::step_check_refinement.path);
  return "below the integration floor (" + quantity(m.value(key::checked_value.name(), 0.0), unit) +
         "; it moves by " + quantity(m.value(key::checked_floor.name(), 0.0), unit) + " at " +
         (how && how->is_string() ? how->get<std::string>() : "half the step") + "): not a result";
}

// A list (per joint) or object (per elbow) of numbers, each with its unit.
std::string each(const Json& values, const std::string& unit) {
  std::string out;
  for (const auto& [key, v] : values.items())
    out += (out.empty() ? "" : ", ") + (v.is_number() ? quantity(v.get<double>(), unit) : "—");
  return out;
}

std::string energy_in_text(const RunData& run) {
  std::string text = quantity(number(run, key::energy_final_path(Energy::electrical_in)), "J");
  const double drawn = number(run, key::energy_final_path(Energy::drawn));
  const double regenerated = number(run, key::energy_final_path(Energy::regenerated));
  if (drawn > 0 || regenerated > 0)
    text += " (drawn " + quantity(drawn, "J") + ", regenerated " + quantity(regenerated, "J") + ")";
  return text;
}

std::string residual_text(const RunData& run) {
  const double residual = number(run, key::balance_residual.path);
  const auto flow = energy_flow(run.summary);
  std::string text = quantity(residual, "J");
  if (flow && flow->total_in > 0)
    text += " (" + percent(std::abs(residual) / flow->total_in) + " of the energy in)";
  return text;
}

bool never_rests(const RunData& run) {
  const Json* rest = at(run, key::metric_path(metric::rest_fraction));
  if (!rest || !rest->is_object()) return false;
  for (const auto& [elbow, v] : rest->items())
    if (!v.is_number() || v.get<double>() > 0) return false;
  return true;
}

std::string force_text(const RunData& run) {
  if (never_rests(run)) return "— (no elbow rests)";
  return quantity(number(run, key::metric_path(metric::elbow_force_min)), "N") + " to " +
         quantity(number(run, key::metric_path(metric::elbow_force_max)), "N") + " (mean " +
         quantity(number(run, key::metric_path(metric::elbow_force_mean)), "N") +
         ", while resting)";
}

std::string unplanned_text(const RunData& run) {
  const std::vector<std::string> rests = unplanned_rests(run);
  if (rests.empty()) return "none";
  std::string out;
  for (const std::string& r : rests) out += (out.empty() ? "" : "; ") + r;
  return out;
}

// "100 % of the run"; with several elbows "left 40 %, right 100 % of the run".
std::string rest_text(const Json& fractions) {
  std::string out;
  for (const auto& [elbow, v] : fractions.items())
    out += (out.empty() ? "" : ", ") + (fractions.size() > 1 ? elbow + " " : "") +
           (v.is_number() ? percent(v.get<double>()) : std::string("—"));
  return out + " of the run";
}

}  // namespace

// The bodies the scene does not plan to rest (contact.bodies.*.planned: a
// link's own solid, an elbow held above the table) that rested all the same:
// "link3 (a link, not a declared elbow) 99 % of the run, mean 8.7 N, peak 14.5 N".
std::vector<std::string> unplanned_rests(const RunData& run) {
  std::vector<std::string> out;
  const Json* bodies = at(run, key::contact_bodies.path);
  if (!bodies || !bodies->is_object()) return out;
  for (const auto& [name, b] : bodies->items()) {
    const double share = b.value(key::body_rest_fraction.name(), 0.0);
    if (b.value(key::body_planned.name(), "rest") == "rest" || !(share > 0)) continue;
    const bool link = b.value(key::body_kind.name(), "") == "link";
    out.push_back(name + (link ? " (a link, not a declared elbow) " : " (held above the table) ") +
                  percent(share) + " of the run, mean " +
                  quantity(b.value(key::body_force_mean.name(), 0.0), "N") + ", peak " +
                  quantity(b.value(key::body_force_peak.name(), 0.0), "N"));
  }
  return out;
}

const Json* below_floor(const RunData& run, const std::string& metric) {
  const Json* m = at(run, key::checked_metric_path(metric));
  return m && m->is_object() && m->value(key::checked_below_floor.name(), false) ? m : nullptr;
}

std::string run_title(const RunData& run) {
  const std::string scenario = run.has_summary() ? run.summary.value(key::scenario.name(), "") : "";
  if (scenario.empty()) return run.label;
  return scenario == run.label || run.label.empty() ? scenario : scenario + " · " + run.label;
}

std::string comparison_title(const std::vector<RunData>& runs) {
  std::string names;
  for (const RunData& run : runs) names += (names.empty() ? "" : " vs ") + run.label;
  const std::string scenario = !runs.empty() && runs.front().has_summary()
                                   ? runs.front().summary.value(key::scenario.name(), "")
                                   : "";
  return scenario.empty() ? names : scenario + " · " + names;
}

std::string validity(const RunData& run) {
  if (!run.has_summary()) return "unknown (no summary.json)";
  const Json& s = run.summary;
  const std::string failure = s.value(key::failure.name(), std::string("(no reason recorded)"));
  if (!s.value(key::completed.name(), false))
    return "STOPPED EARLY at t = " + quantity(s.value(key::final_time.name(), 0.0), "s") + ": " +
           failure;
  if (!s.value(key::valid.name(), true)) return "NOT VALID: " + failure;
  return "valid";
}

std::vector<HeadlineItem> headline_items(const std::vector<const RunData*>& runs) {
  // Each with the unit its path has (summary_keys.hpp; "" for a pure number).
  const auto item = [](const char* label, std::string_view path) {
    return HeadlineItem{label, std::string(path), metric_unit(std::string(path))};
  };
  const std::vector<HeadlineItem> all = {
      item("hand error, RMS", key::metric_path(metric::hand_error_rms)),
      item("hand error, max", key::metric_path(metric::hand_error_max)),
      item("electrical energy in", key::energy_final_path(Energy::electrical_in)),
      item("Joule loss", key::energy_final_path(Energy::joule)),
      item("peak electrical power", key::metric_path(metric::power_peak)),
      item("motor current, RMS per joint", key::metric_path(metric::current_rms)),
      item("motor current, peak per joint", key::metric_path(metric::current_peak)),
      item("elbow resting", key::metric_path(metric::rest_fraction)),
      item("elbow normal force", key::metric_path(metric::elbow_force_max)),
      item("other parts resting on the table", key::contact_bodies.path),
      item("energy balance residual", key::balance_residual.path),
  };
  std::vector<HeadlineItem> out;
  for (const HeadlineItem& item : all)
    for (const RunData* run : runs)
      if (has(*run, item.path)) {
        out.push_back(item);
        break;
      }
  return out;
}

std::string headline_value(const RunData& run, const HeadlineItem& item) {
  const Json* v = at(run, item.path);
  if (!v || v->is_null()) return "—";
  if (const Json* m = below_floor(run, checked_metric(item.path))) return floor_text(run, *m, item.unit);
  if (item.path == key::energy_final_path(Energy::electrical_in)) return energy_in_text(run);
  if (item.path == key::balance_residual.path) return residual_text(run);
  if (item.path == key::metric_path(metric::elbow_force_max)) return force_text(run);
  if (item.path == key::metric_path(metric::rest_fraction)) return rest_text(*v);
  if (item.path == key::contact_bodies.path) return unplanned_text(run);
  if (v->is_array() || v->is_object()) return each(*v, item.unit);
  return v->is_number() ? quantity(v->get<double>(), item.unit) : v->dump();
}

std::string headline_sentence(const RunData& run) {
  if (!run.has_summary()) return "This run folder has no summary.json: its numbers are unknown.";
  const Json& s = run.summary;
  const std::string status = validity(run);
  std::string text = status == "valid" ? "A valid run" : "A run that is " + status + ";";
  text += " of " + quantity(s.value(key::final_time.name(), 0.0), "s") + " simulated";
  if (status != "valid") return text + ". Its numbers below cover what it computed.";
  std::vector<std::string> parts;
  if (below_floor(run, metric::hand_error_rms))
    parts.push_back("the hand error is below the integration floor (it measures the integrator, "
                    "not the arm; the report's accuracy check gives the numbers)");
  else if (has(run, key::metric_path(metric::hand_error_rms)))
    parts.push_back(
        "the hand kept to its path within " +
        quantity(number(run, key::metric_path(metric::hand_error_rms)), "m") + " RMS (" +
        quantity(number(run, key::metric_path(metric::hand_error_max)), "m") + " at most)");
  if (has(run, key::energy_final_path(Energy::electrical_in)) &&
      number(run, key::energy_final_path(Energy::drawn)) > 0)
    parts.push_back("the motors took " +
                    quantity(number(run, key::energy_final_path(Energy::electrical_in)), "J") +
                    " of electrical energy and lost " +
                    quantity(number(run, key::energy_final_path(Energy::joule)), "J") +
                    " as heat in their windings");
  if (never_rests(run))
    parts.push_back("no elbow rested on the table");
  else if (const Json* rest = at(run, key::metric_path(metric::rest_fraction));
           rest && rest->is_object())
    parts.push_back(std::string(rest->size() > 1 ? "the elbows rested " : "the elbow rested ") +
                    rest_text(*rest));
  for (std::size_t k = 0; k < parts.size(); ++k)
    text += (k == 0 ? ": " : k + 1 == parts.size() ? " and " : ", ") + parts[k];
  text += ".";
  // What else carried the arm: never left out of a run's first sentence.
  for (const std::string& rest : unplanned_rests(run))
    text += " The table also carried " + rest + ".";
  return text;
}

std::string accuracy_check(const RunData& run) {
  const Json* check = at(run, key::step_check.path);
  if (!check || !check->is_object())
    return "not measured (the run was made with --no-check-step; without it each run is "
           "repeated refined and its numbers' integration floor stated)";
  if (check->contains(key::step_check_error.name()))
    return "failed: " + (*check)[key::step_check_error.name()].get<std::string>();
  std::string text =
      check->contains(key::step_check_half_step.name())
          ? "at half the step (" +
                quantity(check->value(key::step_check_half_step.name(), 0.0), "s") + ")"
          : "at " +
                check->value(key::step_check_refinement.name(), std::string("a refined setting"));
  if (!check->value(key::step_check_valid_at_half_step.name(), true))
    return text + " the run is NOT VALID";
  const Json& m = check->value(key::step_check_metrics.name(), Json::object());
  const std::string_view change = key::checked_relative_change.name();
  std::vector<std::string> changes;
  for (const auto& [name, label] :
       {std::pair<const char*, const char*>{metric::hand_error_rms, "the RMS hand error"},
        {metric::energy_in, "the electrical energy in"},
        {metric::joule, "the Joule loss"}})
    if (m.contains(name) && m[name].contains(change))
      changes.push_back(std::string(label) + (changes.empty() ? " changes by " : " by ") +
                        percent(m[name][change].get<double>()));
  if (changes.empty()) return text + " no metric was compared";
  for (std::size_t k = 0; k < changes.size(); ++k)
    text += (k == 0 ? " " : k + 1 == changes.size() ? " and " : ", ") + changes[k];
  std::string below;
  for (const auto& name : check->value(key::step_check_below_floor.name(), Json::array()))
    below += (below.empty() ? "" : ", ") + name.get<std::string>();
  if (!below.empty())
    text += "; below the integration floor (under 10 times their change, so not results): " + below;
  return text;
}

}  // namespace elbowsim::report
