// Scenario file -> YAML tree -> overrides -> section readers -> finalize().
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "app/scenario/checks.hpp"
#include "app/scenario/overrides.hpp"
#include "app/scenario/scenario.hpp"
#include "app/scenario/sections.hpp"

namespace elbowsim {

namespace {

std::string locate(const std::string& file, int line, int column) {
  std::string out = file;
  // Appended piece by piece: `":" + std::to_string(...)` trips GCC 12's -Wrestrict.
  if (line > 0) out.append(":").append(std::to_string(line));
  if (line > 0 && column > 0) out.append(":").append(std::to_string(column));
  return out;
}

}  // namespace

ScenarioError::ScenarioError(std::string file_, int line_, int column_, std::string key_,
                             const std::string& message)
    : std::runtime_error(locate(file_, line_, column_) + ": " + (key_.empty() ? "" : key_ + ": ") +
                         message),
      file(std::move(file_)),
      key(std::move(key_)),
      line(line_),
      column(column_) {}

namespace loader {

namespace {

// The document must be a map of sections (an empty one becomes an empty map,
// so that overrides alone can still be reported key by key).
YAML::Node parse(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root.reset(YAML::Load(text));
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(file, e.mark.line + 1, e.mark.column + 1, "", "invalid YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull()) return YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) {
    YAML::Mark m = root.Mark();
    throw ScenarioError(file, m.line + 1, m.column + 1, "",
                        "expected a map of sections (name, robot, simulation, ...)");
  }
  return root;
}

// name: [A-Za-z0-9_-]+, also the default output folder.
std::string read_name(const Value& v) {
  std::string name = v.text();
  auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  };
  if (name.empty() || !std::all_of(name.begin(), name.end(), allowed))
    v.fail("must be letters, digits, _ or - only (got \"" + name + "\")");
  return name;
}

// finalize() re-checks the model; the readers above should have caught
// everything, so a failure here has no line to point at.
void finalize_model(Model& model, const std::string& file) {
  try {
    finalize(model);
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(file, 0, 0, "", e.what());
  }
}

// The sections, in dependency order: effects and robot (dof) before motors,
// elbows, initial state and inputs.
Scenario read(const Value& root, const std::string& file) {
  root.allow_keys({"name", "description", "robot", "motors", "gravity", "effects", "elbows",
                   "table", "contact", "initial", "simulation", "inputs", "output"});
  Scenario s;
  s.file = file;
  Model& model = s.model;
  model.name = read_name(root.require("name"));
  s.description = value_or(root.get("description"), std::string(), text);
  model.effects = read_effects(root.get("effects"));
  const Value robot = root.require("robot");
  read_robot(robot, model);
  model.gravity = value_or(root.get("gravity"), model.gravity, vec3);
  model.motors = read_motors(root.get("motors"), model);
  model.elbows = read_elbows(root.get("elbows"), model, robot.get("planar").exists());
  model.table = read_table(root.get("table"));
  model.contact = read_contact(root.get("contact"));
  check_contact_scene(root, model);
  model.options = read_simulation(root.require("simulation"));
  model.initial = read_initial(root.get("initial"), model.dof);
  model.inputs = read_inputs(root.get("inputs"), model);
  s.output = read_output(root.get("output"), model.name);
  finalize_model(model, file);
  check_initial_penetration(root, model);
  return s;
}

}  // namespace

}  // namespace loader

Scenario load_scenario_text(const std::string& text, const std::string& file_name,
                            const std::vector<std::string>& overrides) {
  loader::Source source(file_name);
  YAML::Node root = loader::parse(text, file_name);
  for (const std::string& o : overrides) loader::apply_override(root, o, source);
  Scenario scenario = loader::read(loader::Value(source, root), file_name);
  YAML::Emitter resolved;
  resolved << root;
  scenario.resolved_yaml = std::string(resolved.c_str()) + "\n";
  return scenario;
}

Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path, 0, 0, "", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return load_scenario_text(text.str(), path, overrides);
}

}  // namespace elbowsim
