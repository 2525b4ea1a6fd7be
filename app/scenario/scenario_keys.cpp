#include "app/scenario/scenario_keys.hpp"

#include <yaml-cpp/yaml.h>

#include <map>

namespace elbowsim {

namespace {

using Leaves = std::vector<std::pair<std::string, std::string>>;

std::string flow(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

bool all_scalars(const YAML::Node& node) {
  for (const YAML::Node& item : node)
    if (!item.IsScalar() && !(item.IsSequence() && all_scalars(item))) return false;
  return true;
}

void walk(const YAML::Node& node, const std::string& path, Leaves& out) {
  if (node.IsMap()) {
    for (const auto& entry : node)
      walk(entry.second, path.empty() ? entry.first.as<std::string>() : path + "." + entry.first.as<std::string>(), out);
  } else if (node.IsSequence() && !all_scalars(node)) {
    for (std::size_t k = 0; k < node.size(); ++k) walk(node[k], path + "[" + std::to_string(k) + "]", out);
  } else {
    out.emplace_back(path, node.IsNull() ? std::string("null") : flow(node));
  }
}

}  // namespace

Leaves scenario_keys(const std::string& yaml_text) {
  Leaves out;
  try {
    walk(YAML::Load(yaml_text), "", out);
  } catch (const YAML::Exception&) {
    return {};
  }
  return out;
}

std::vector<KeyDifference> differing_keys(const std::vector<std::string>& texts) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::string>> values;
  std::map<std::string, std::vector<bool>> present;
  for (std::size_t t = 0; t < texts.size(); ++t)
    for (const auto& [key, value] : scenario_keys(texts[t])) {
      if (!values.count(key)) {
        order.push_back(key);
        values[key].assign(texts.size(), "");
        present[key].assign(texts.size(), false);
      }
      values[key][t] = value;
      present[key][t] = true;
    }
  std::vector<KeyDifference> out;
  for (const std::string& key : order) {
    bool same = true;
    for (std::size_t t = 1; t < texts.size(); ++t)
      same &= values[key][t] == values[key][0] && present[key][t] == present[key][0];
    if (!same) out.push_back({key, values[key]});
  }
  return out;
}

}  // namespace elbowsim
