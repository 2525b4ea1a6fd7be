// The unit of every number summary.json holds, from its schema
// (report/summary_keys.hpp: each key once, with its unit; the metrics' units
// from engine/recording/metrics.hpp). summary.json carries the units of its own
// numbers (its "units" object, made by units_json); the reports label their
// values from the same rows.
//
// Units are SI symbols ("m", "J", "N", "s", "A", "W", "kg", "Hz", "rad", "m/s");
// "1" is a pure number: a count, an index, a ratio or a share; "state" is the
// integrated state's own units (rad, rad/s, A, J: an absolute tolerance).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace elbowsim::report {

// The unit of the number at `path` ("metrics.hand_error_rms", "contact.bodies.elbow.force_mean",
// "metrics.current_peak.0": a list's element by its index); "" when no key of the
// schema covers it or it is not a number.
std::string summary_unit(std::string_view path);

// {path: unit} for every number in `summary`, in the order they appear; a list of
// numbers is one entry, under the list's path. Throws std::logic_error naming the
// first number the schema gives no unit (a key added without its unit).
nlohmann::ordered_json units_json(const nlohmann::ordered_json& summary);

// `summary` with its "units" object placed second, after "provenance" (or first
// without one): what summary.json holds.
nlohmann::ordered_json with_units(const nlohmann::ordered_json& summary);

}  // namespace elbowsim::report
