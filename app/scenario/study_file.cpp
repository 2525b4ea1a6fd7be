#include "app/scenario/study_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "app/scenario/scenario.hpp"
#include "app/scenario/yaml_reader.hpp"

namespace elbowsim {

namespace {

using loader::Value;

bool is_name(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// A key path as --set takes it: letters, digits, '_', '.', '[', ']', '*'.
bool is_key_path(const std::string& s) {
  return !s.empty() && s.find('=') == std::string::npos && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '[' ||
           c == ']';
  });
}

// The overrides of a map {key.path: value, ...} as "key.path=value".
std::vector<std::string> overrides_of(const Value& map) {
  std::vector<std::string> out;
  if (!map.present()) return out;
  if (!map.is_map()) map.fail("expected a map of key.path: value overrides, or {}");
  for (const auto& [key, value] : map.entries()) {
    if (!is_key_path(key.text())) key.fail("not a key path (e.g. task.duration, elbows[0].at)");
    out.push_back(key.text() + "=" + value.flow_yaml());
  }
  return out;
}

// grid.<entry>: a list of values of a key, or a map of named levels.
StudyDesign::Axis read_axis(const Value& key, const Value& value) {
  StudyDesign::Axis axis{key.text(), "", {}};
  if (value.is_sequence()) {
    if (!is_key_path(axis.name)) key.fail("not a key path (e.g. task.duration, elbows[0].at)");
    axis.key = axis.name;
    std::set<std::string> seen;
    for (const Value& item : value.items()) {
      const std::string text = item.flow_yaml();
      if (text.empty()) item.fail("a value is missing");
      if (!seen.insert(text).second) item.fail("value " + text + " is given twice");
      axis.levels.push_back({text, {axis.key + "=" + text}});
    }
  } else if (value.is_map()) {
    if (!is_name(axis.name)) key.fail("an axis of named levels needs a name of letters, digits and _");
    for (const auto& [level, overrides] : value.entries()) {
      if (!is_name(level.text())) level.fail("a level's name is letters, digits and _");
      axis.levels.push_back({level.text(), overrides_of(overrides)});
    }
  } else {
    value.fail("expected a list of values ([8, 4, 2]) or a map of named levels");
  }
  if (axis.levels.empty()) value.fail("needs at least one value");
  return axis;
}

std::vector<std::pair<std::string, std::string>> read_case(const Value& item) {
  if (!item.is_map() || item.entries().empty())
    item.fail("a case is a map of key.path: value overrides, e.g. {task.duration: 4}");
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, value] : item.entries()) {
    if (!is_key_path(key.text())) key.fail("not a key path (e.g. task.duration, elbows[0].at)");
    out.emplace_back(key.text(), value.flow_yaml());
  }
  return out;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path, 0, 0, "", "cannot open the study file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

YAML::Node parse(const std::string& path) {
  try {
    YAML::Node root = YAML::Load(read_text(path));
    if (!root.IsMap()) throw ScenarioError(path, 1, 1, "", "a study file is a map (scenario, grid or cases, ...)");
    return root;
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(path, e.mark.line + 1, e.mark.column + 1, "", "invalid YAML: " + e.msg);
  }
}

}  // namespace

bool is_study_file(const std::string& path) {
  try {
    return parse(path)["scenario"].IsDefined();
  } catch (const std::exception&) {
    return false;
  }
}

StudyDesign load_study_file(const std::string& path) {
  const loader::Source source(path);
  const Value root(source, parse(path));
  root.allow_keys({"scenario", "description", "set", "grid", "cases", "draws", "seed"});
  StudyDesign d;
  d.file = path;
  d.name = std::filesystem::path(path).stem().string();
  // The scenario is named relative to the study file, like an #include.
  const Value scenario = root.require("scenario");
  const std::filesystem::path given = scenario.text();
  d.scenario = (given.is_absolute() ? given : std::filesystem::path(path).parent_path() / given)
                   .lexically_normal().string();
  if (!std::filesystem::is_regular_file(d.scenario))
    scenario.fail("no such scenario file: " + d.scenario);
  if (const Value sets = root.get("set"); sets.present())
    for (const Value& s : sets.items()) {
      const std::string text = s.text();
      if (text.find('=') == std::string::npos) s.fail("expected key.path=value (got \"" + text + "\")");
      d.sets.push_back(text);
    }
  const Value grid = root.get("grid"), cases = root.get("cases");
  if (grid.present() == cases.present())
    root.fail(grid.present() ? "give grid or cases, not both" : "needs grid (every combination) or cases (a list)");
  if (grid.present()) {
    if (!grid.is_map() || grid.entries().empty()) grid.fail("expected a map of key: [values] or axis: {levels}");
    for (const auto& [key, value] : grid.entries()) d.grid.push_back(read_axis(key, value));
  } else {
    for (const Value& item : cases.items()) d.list.push_back(read_case(item));
    if (d.list.empty()) cases.fail("needs at least one case");
  }
  if (const Value draws = root.get("draws"); draws.present()) {
    d.draws = draws.integer();
    if (d.draws < 2 || d.draws > 100000) draws.fail("must be 2 to 100000 (got " + std::to_string(d.draws) + ")");
  }
  if (const Value seed = root.get("seed"); seed.present()) {
    if (seed.integer() < 0) seed.fail("must be >= 0");
    d.seed = static_cast<std::uint64_t>(seed.integer());
  }
  return d;
}

StudyDesign::Axis grid_option(const std::string& text) {
  const auto fail = [&](const std::string& why) -> StudyDesign::Axis {
    throw ScenarioError("command line --grid " + text, 0, 0, "", why);
  };
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) return fail("expected KEY=V1,V2,... (e.g. task.duration=8,4,2)");
  StudyDesign::Axis axis{text.substr(0, eq), text.substr(0, eq), {}};
  if (!is_key_path(axis.key)) return fail("not a key path: " + axis.key);
  // Split at commas outside brackets: initial.q=[0.1, 0.2],[0.3, 0.4].
  std::string value;
  int depth = 0;
  std::set<std::string> seen;
  const auto flush = [&] {
    const auto first = value.find_first_not_of(' '), last = value.find_last_not_of(' ');
    const std::string v = first == std::string::npos ? "" : value.substr(first, last - first + 1);
    if (v.empty()) fail("a value is missing");
    if (!seen.insert(v).second) fail("value " + v + " is given twice");
    axis.levels.push_back({v, {axis.key + "=" + v}});
    value.clear();
  };
  for (const char c : text.substr(eq + 1)) {
    depth += (c == '[' || c == '{') - (c == ']' || c == '}');
    if (c == ',' && depth == 0) flush();
    else value += c;
  }
  flush();
  return axis;
}

}  // namespace elbowsim
