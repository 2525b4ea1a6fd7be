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
#include "app/scenario/start_checks.hpp"
#include "engine/control/plan.hpp"
#include "engine/run/integrator_choice.hpp"

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
void finalize_model(Model& model, const Source& source) {
  try {
    finalize(model);
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(source.file(), 0, 0, "", e.what() + source.note());
  }
}

// simulation.integrator auto (or absent): chosen for the finalized model and
// the controller's gains (run/integrator_choice.hpp); then rtol, atol and
// max_step are checked against the choice.
void choose_auto_integrator(const Value& simulation, Scenario& s) {
  if (!auto_integrator(simulation)) return;
  // Continuous feedback enters the step's stability: with a tuning rule, its
  // gains at the task's first pose (on the plant: the controller's model is
  // read later and differs from it by a belief's small offsets). A task that
  // cannot start keeps the given gains here; the run names its plan error.
  const ControllerSpec controller = s.experiment.controller.loop.sampled()
                                        ? s.experiment.controller
                                        : gains_before_run(s.model, s.experiment);
  const IntegratorChoice choice = choose_integrator(s.model, &controller);
  s.model.options.integrator = choice.kind;
  s.model.options.integrator_reason = choice.reason;
  check_error_control(simulation, s.model.options);
}

// A task without joint_limits keeps a URDF's <limit>s (continuous joints: none).
void use_urdf_limits(const Value& task, const RobotInfo& robot, HandTask& out) {
  if (!task.present() || task.get("joint_limits").present()) return;
  const bool limited = (robot.names.q_min.array().isFinite() || robot.names.q_max.array().isFinite()).any();
  if (!limited) return;
  out.q_min = robot.names.q_min;
  out.q_max = robot.names.q_max;
}

// The sections, in dependency order: effects and robot (dof) before motors,
// elbows, initial state, inputs and the task. Fills `sets` with the variants:
// and study: sections (with where each entry is written).
// The checks at the pose the run starts from are load_once's (start_checks.hpp):
// on the plant only, whose start is solved on its own table.
Scenario read(const Value& root, const Source& source, OverrideSets& sets,
              std::vector<VariantSpec::Entry>& beliefs, RobotInfo& robot_info) {
  root.allow_keys({"name", "description", "robot", "motors", "gravity", "effects", "elbows",
                   "table", "contact", "initial", "simulation", "inputs", "output", "render",
                   "task", "controller", "hand_load", "variants", "validity", "warnings",
                   "uncertainty", "joint_friction", "springs", "study"});
  Scenario s;
  s.file = source.file();
  Model& model = s.model;
  model.name = read_name(root.require("name"));
  s.description = value_or(root.get("description"), std::string(), text);
  model.effects = read_effects(root.get("effects"));
  const Value robot = root.require("robot");
  robot_info = read_robot(robot, model, source.file());
  s.chain = robot_info.names;
  model.gravity = value_or(root.get("gravity"), model.gravity, vec3);
  model.springs = read_springs(root.get("springs"), model, robot_info);
  model.motors = read_motors(root.get("motors"), model);
  const Value contact = root.get("contact");
  model.elbows = read_elbows(root.get("elbows"),
                             contact.present() ? contact.get("pad") : contact, model, robot_info);
  model.table = read_table(root.get("table"));
  model.contact = read_contact(root.get("contact"));
  model.validity = read_validity(root.get("validity"));
  model.warn = read_warnings(root.get("warnings"));
  model.joint_friction = read_joint_friction(
      root.get("joint_friction"),
      root.get("effects").present() ? root.get("effects").get("joint_friction") : root.get("effects"),
      model.dof);
  check_contact_scene(root, model);
  model.options = read_simulation(root.get("simulation"), root.get("task"));
  model.initial = read_initial(root.get("initial"), model.dof);
  model.inputs = read_inputs(root.get("inputs"), model);
  s.experiment.task = read_task(root.get("task"), model);
  use_urdf_limits(root.get("task"), robot_info, s.experiment.task);
  s.experiment.controller = read_controller(root.get("controller"), model, s.experiment.task);
  if (const Value controller = root.get("controller"); controller.present())
    beliefs = read_controller_model(controller.get("model"));
  model.hand_load = read_hand_load(root.get("hand_load"));
  s.output = read_output(root.get("output"), model.name);
  s.render = read_render(root.get("render"));
  finalize_model(model, source);
  choose_auto_integrator(root.get("simulation"), s);
  const auto texts = [](const VariantSpec& v) {
    std::vector<std::string> out;
    for (const VariantSpec::Entry& e : v.overrides) out.push_back(e.text);
    return out;
  };
  sets.variants = read_variants(root.get("variants"));
  for (const VariantSpec& v : sets.variants) s.variants.emplace_back(v.name, texts(v));
  sets.axes = read_study(root.get("study"));
  for (const StudyAxisSpec& axis : sets.axes) {
    s.study.push_back({axis.name, {}});
    for (const VariantSpec& level : axis.levels) s.study.back().levels.emplace_back(level.name, texts(level));
  }
  return s;
}

// The controller's model: the scenario (as loaded so far) with controller.model's
// entries applied, read like the plant, so every key is checked the same way.
// Its structure must be the plant's: it may believe other numbers only.
Model read_believed(const YAML::Node& root, Source source,
                    const std::vector<VariantSpec::Entry>& beliefs, const Model& plant) {
  YAML::Node copy = YAML::Clone(root);
  YAML::Node controller = copy["controller"];
  controller.remove("model");
  copy.remove("variants");
  copy.remove("study");
  source.set_note(source.note() + " (in the controller's model, controller.model)");
  for (const VariantSpec::Entry& e : beliefs) apply_override(copy, e.text, source, e.origin);
  OverrideSets none;
  std::vector<VariantSpec::Entry> no_beliefs;
  RobotInfo robot;
  Model believed = read(Value(source, copy), source, none, no_beliefs, robot).model;
  auto differs = [&](const char* what, std::size_t a, std::size_t b) {
    if (a == b) return;
    const VariantSpec::Entry& e = beliefs.front();
    throw ScenarioError(e.origin.file, e.origin.line, e.origin.column, "controller.model",
                        std::string("the controller's model must have the plant's ") + what +
                            " (" + std::to_string(b) + "), got " + std::to_string(a) +
                            ": it may believe other values, not another structure");
  };
  differs("number of joints", static_cast<std::size_t>(believed.dof),
          static_cast<std::size_t>(plant.dof));
  differs("number of motors", believed.motors.size(), plant.motors.size());
  differs("number of elbows", believed.elbows.size(), plant.elbows.size());
  differs("number of table boxes", believed.table.size(), plant.table.size());
  return believed;
}

// What one load applies before the command line's overrides: a study case's
// levels (one per axis, or none), then a variant (or none).
struct Applied {
  std::vector<const VariantSpec*> levels;
  const VariantSpec* variant = nullptr;
};

// " (in study case loops-fast, variant elbow_on)": where an error came from.
std::string applied_note(const Applied& applied) {
  std::string note;
  if (!applied.levels.empty()) {
    note = "study case ";
    for (std::size_t i = 0; i < applied.levels.size(); ++i)
      note.append(i ? "-" : "").append(applied.levels[i]->name);
  }
  if (applied.variant) note.append(note.empty() ? "" : ", ").append("variant ").append(applied.variant->name);
  return note.empty() ? note : " (in " + note + ")";
}

// One load: the file, then what `applied` names (errors they cause name the
// level or variant), then `overrides`. A case has no study, a variant's
// scenario no variants.
Scenario load_once(const std::string& text, const std::string& file, const Applied& applied,
                   const std::vector<std::string>& overrides, OverrideSets& sets) {
  Source source(file);
  YAML::Node root = parse(text, file);
  source.set_note(applied_note(applied));
  for (const VariantSpec* level : applied.levels)
    for (const VariantSpec::Entry& e : level->overrides) apply_override(root, e.text, source, e.origin);
  if (applied.variant)
    for (const VariantSpec::Entry& e : applied.variant->overrides)
      apply_override(root, e.text, source, e.origin);
  for (const std::string& o : overrides) apply_override(root, o, source);
  if (!applied.levels.empty()) root.remove("study");
  if (applied.variant) root.remove("variants");
  std::vector<VariantSpec::Entry> beliefs;
  RobotInfo robot;
  Scenario scenario = read(Value(source, root), source, sets, beliefs, robot);
  scenario.variant = applied.variant ? applied.variant->name : "";
  for (const VariantSpec* level : applied.levels) scenario.study_case.push_back(level->name);
  scenario.uncertainty = read_uncertainty(Value(source, root).get("uncertainty"), root);
  if (!beliefs.empty()) {
    scenario.experiment.controller_model =
        std::make_shared<const Model>(read_believed(root, source, beliefs, scenario.model));
    for (const VariantSpec::Entry& e : beliefs) scenario.controller_model_overrides.push_back(e.text);
  }
  check_start(Value(source, root), scenario);
  // The scenario as run stands alone: a URDF read from a file goes in as its text.
  if (robot.form == RobotInfo::Form::urdf) root["robot"]["urdf"] = robot.urdf_text;
  YAML::Emitter resolved;
  resolved << root;
  scenario.resolved_yaml = std::string(resolved.c_str()) + "\n";
  return scenario;
}

const VariantSpec& find_set(const std::vector<VariantSpec>& sets, const std::string& name,
                            const std::string& file, const std::string& key, const std::string& what) {
  std::vector<std::string_view> names;
  for (const VariantSpec& v : sets) {
    if (v.name == name) return v;
    names.push_back(v.name);
  }
  throw ScenarioError(file, 0, 0, key,
                      "no " + what + " named \"" + name + "\"" +
                          (names.empty() ? " (the scenario has none)" : "; it has " + join(names)));
}

// The levels `names` of the study's axes, in axis order.
std::vector<const VariantSpec*> find_levels(const std::vector<StudyAxisSpec>& axes,
                                            const std::vector<std::string>& names,
                                            const std::string& file) {
  if (names.empty()) return {};
  if (names.size() != axes.size())
    throw ScenarioError(file, 0, 0, "study",
                        "a study case names one level per axis: the study has " +
                            std::to_string(axes.size()) + " axes, the case " +
                            std::to_string(names.size()) + " levels");
  std::vector<const VariantSpec*> out;
  for (std::size_t a = 0; a < axes.size(); ++a)
    out.push_back(&find_set(axes[a].levels, names[a], file, "study.axes." + axes[a].name, "level"));
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path, 0, 0, "", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

}  // namespace loader

// The scenario itself, then each variant loaded once to check it. Study
// levels are checked where cases are loaded (montecarlo, validate): a --set
// for one run may well contradict a level (task.path against a circle's keys).
Scenario load_scenario_text(const std::string& text, const std::string& file_name,
                            const std::vector<std::string>& overrides) {
  loader::OverrideSets sets, none;
  Scenario scenario = loader::load_once(text, file_name, {}, overrides, sets);
  for (const loader::VariantSpec& v : sets.variants)
    loader::load_once(text, file_name, {{}, &v}, overrides, none);
  return scenario;
}

Scenario load_scenario_case_text(const std::string& text, const std::string& file_name,
                                 const std::vector<std::string>& levels, const std::string& variant,
                                 const std::vector<std::string>& overrides) {
  loader::OverrideSets sets, none;
  loader::load_once(text, file_name, {}, overrides, sets);
  loader::Applied applied{loader::find_levels(sets.axes, levels, file_name), nullptr};
  if (!variant.empty())
    applied.variant = &loader::find_set(sets.variants, variant, file_name, "variants", "variant");
  return loader::load_once(text, file_name, applied, overrides, none);
}

Scenario load_scenario_case(const std::string& path, const std::vector<std::string>& levels,
                            const std::string& variant, const std::vector<std::string>& overrides) {
  return load_scenario_case_text(loader::read_file(path), path, levels, variant, overrides);
}

Scenario load_scenario_variant_text(const std::string& text, const std::string& file_name,
                                    const std::string& name,
                                    const std::vector<std::string>& overrides) {
  return load_scenario_case_text(text, file_name, {}, name, overrides);
}

Scenario load_scenario_variant(const std::string& path, const std::string& name,
                               const std::vector<std::string>& overrides) {
  return load_scenario_variant_text(loader::read_file(path), path, name, overrides);
}

Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  return load_scenario_text(loader::read_file(path), path, overrides);
}

}  // namespace elbowsim
