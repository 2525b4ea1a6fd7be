// uncertainty: which plant parameters a Monte Carlo study draws, and how.
//
//   uncertainty:
//     seed: 1
//     parameters:
//       robot.planar.links[*].mass: {uniform: 0.10}   # each link's own draw
//       motors.default.resistance: {normal: 0.05}
//       hand_load.mass: {range: [0, 0.2]}
//
// Keys are checked against the scenario as loaded (after variants and --set):
// a relative law needs the number to be there; "[*]" expands over a list.
#include <cmath>
#include <set>

#include "app/scenario/checks.hpp"
#include "app/scenario/overrides.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

// Every concrete key path the steps name in `node`, with its node (undefined
// when the last map key is missing). Fails at `where` when a list is missing
// or an index is out of range.
void expand(const YAML::Node& node, const std::vector<KeyStep>& steps, std::size_t k,
            const std::string& prefix, const Value& where, bool absent_ok,
            std::vector<std::pair<std::string, YAML::Node>>& out) {
  if (k == steps.size()) {
    out.emplace_back(prefix, node);
    return;
  }
  const KeyStep& s = steps[k];
  if (s.index == kMapKey) {
    const std::string path = prefix.empty() ? s.key : prefix + "." + s.key;
    if (node.IsDefined() && node.IsMap() && node[s.key]) {
      expand(node[s.key], steps, k + 1, path, where, absent_ok, out);
    } else if (k + 1 == steps.size()) {
      out.emplace_back(path, YAML::Node(YAML::NodeType::Undefined));
    } else if (absent_ok) {  // an absolute law: the draw creates the missing maps
      std::string rest = path;
      for (std::size_t i = k + 1; i < steps.size(); ++i) {
        if (steps[i].index != kMapKey) where.fail("the scenario has no " + path + " (a list to index)");
        rest += "." + steps[i].key;
      }
      out.emplace_back(rest, YAML::Node(YAML::NodeType::Undefined));
    } else {
      where.fail("the scenario has no " + path + " (give it in the file to draw around it)");
    }
    return;
  }
  if (!node.IsDefined() || !node.IsSequence())
    where.fail(prefix + " is not a list in the scenario");
  const long first = s.index == kEveryItem ? 0 : s.index;
  const long last = s.index == kEveryItem ? static_cast<long>(node.size()) - 1 : s.index;
  if (last >= static_cast<long>(node.size()))
    where.fail(prefix + "[" + std::to_string(last) + "] is out of range (the list has " +
               counted(static_cast<long long>(node.size()), "item") + ")");
  for (long i = first; i <= last; ++i)
    expand(node[static_cast<std::size_t>(i)], steps, k + 1,
           prefix + "[" + std::to_string(i) + "]", where, absent_ok, out);
}

UncertainParameter read_law(const Value& key, const Value& law) {
  UncertainParameter p;
  p.given = key.text();
  law.allow_keys({"uniform", "normal", "range"});
  const auto entries = law.entries();
  if (entries.size() != 1) law.fail("give one law: {uniform: fraction}, {normal: fraction} or {range: [low, high]}");
  const Value& value = entries.front().second;
  const std::string name = entries.front().first.text();
  if (name == "range") {
    p.law = UncertainParameter::Law::range;
    const Eigen::VectorXd r = value.numbers(2, "low, high");
    if (!(r[0] <= r[1])) value.fail("needs low <= high");
    p.low = r[0];
    p.high = r[1];
    return p;
  }
  p.law = name == "uniform" ? UncertainParameter::Law::uniform : UncertainParameter::Law::normal;
  p.spread = non_negative(value);
  if (p.law == UncertainParameter::Law::uniform && p.spread >= 1)
    value.fail("a relative spread of 1 or more can make the value 0 or change its sign");
  if (p.law == UncertainParameter::Law::normal && p.spread >= 1.0 / 3)
    value.fail("sigma must be below 1/3 (the draw is truncated at 3 sigma and must keep its sign)");
  return p;
}

}  // namespace

Uncertainty read_uncertainty(const Value& uncertainty, const YAML::Node& root) {
  Uncertainty out;
  if (!uncertainty.present()) return out;
  uncertainty.allow_keys({"seed", "parameters"});
  if (const Value seed = uncertainty.get("seed"); seed.present()) {
    const long s = seed.integer();
    if (s < 0) seed.fail("must be >= 0");
    out.seed = static_cast<std::uint64_t>(s);
  }
  const Value parameters = uncertainty.require("parameters");
  if (!parameters.is_map())
    parameters.fail("expected a map of key.path: {uniform: f} | {normal: f} | {range: [a, b]}");
  std::set<std::string> seen;
  for (const auto& [key, law] : parameters.entries()) {
    const UncertainParameter p = read_law(key, law);
    std::vector<KeyStep> steps;
    if (!parse_key_path(p.given, true, steps).empty()) key.fail("expected a key path (e.g. robot.planar.links[*].mass)");
    if (steps.front().key == "uncertainty" || steps.front().key == "variants" ||
        steps.front().key == "simulation" || steps.front().key == "output" ||
        steps.front().key == "render" || steps.front().key == "controller" ||
        steps.front().key == "validity")
      key.fail("only plant parameters can be uncertain (robot, motors, gravity, hand_load, "
               "elbows, table, contact, initial, ...), not " + steps.front().key);
    std::vector<std::pair<std::string, YAML::Node>> found;
    expand(root, steps, 0, "", key, p.law == UncertainParameter::Law::range, found);
    for (const auto& [path, node] : found) {
      UncertainParameter q = p;
      q.key = path;
      q.nominal = std::nan("");
      if (node.IsDefined() && node.IsScalar()) {
        double x = 0;
        try {
          x = node.as<double>();
        } catch (const YAML::Exception&) {
          key.fail(path + " is not a number in the scenario (got \"" + node.Scalar() + "\")");
        }
        q.nominal = x;
      } else if (node.IsDefined() && !node.IsNull()) {
        key.fail(path + " is not a single number in the scenario");
      }
      if (q.law != UncertainParameter::Law::range && !std::isfinite(q.nominal))
        key.fail(path + " is not given in the scenario: a relative law needs its nominal value "
                 "there (write it out, or use {range: [low, high]})");
      if (!seen.insert(path).second) key.fail(path + " is drawn twice");
      out.parameters.push_back(q);
    }
  }
  return out;
}

}  // namespace elbowsim::loader
