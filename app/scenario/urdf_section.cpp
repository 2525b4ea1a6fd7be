// robot.urdf: the arm from a URDF file (urdf_file.cpp parses it with urdfdom,
// urdf_chain.cpp makes the serial chain). The path is relative to the scenario
// file; a value that starts with '<' is the URDF itself (a run folder's
// scenario.yaml carries it so, to stand alone). Every error names the
// scenario's robot.urdf key, the URDF and the element.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "app/scenario/urdf_chain.hpp"

namespace elbowsim::loader {

namespace {

constexpr std::uintmax_t kMaxUrdfBytes = 16u << 20;  // a URDF of 256 links is ~1 MB

bool is_inline(const std::string& value) {
  const std::size_t first = value.find_first_not_of(" \t\r\n");
  return first != std::string::npos && value[first] == '<';
}

// The URDF's text, and how messages name it (the path as written, or "the
// inline URDF").
std::string read_urdf_text(const Value& urdf, const std::string& scenario_file, std::string& shown) {
  const std::string value = urdf.text();
  if (is_inline(value)) {
    shown = "the inline URDF";
    return value;
  }
  if (value.empty()) urdf.fail("must be a URDF file's path (relative to the scenario file)");
  shown = value;
  namespace fs = std::filesystem;
  const fs::path path = fs::path(value).is_absolute() ? fs::path(value)
                                                      : fs::path(scenario_file).parent_path() / value;
  std::error_code error;
  if (!fs::is_regular_file(path, error))
    urdf.fail("cannot read " + path.string() + ": " +
              (fs::exists(path, error) ? "not a regular file" : "no such file") +
              " (the path is relative to the scenario file)");
  if (fs::file_size(path, error) > kMaxUrdfBytes)
    urdf.fail(path.string() + " is larger than 16 MiB: not a URDF of an arm");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) urdf.fail("cannot read " + path.string());
  return text.str();
}

// base_link / tip_link: a link of the file (checked here to fail at the key).
std::string read_link_name(const Value& v, const urdf::Tree& tree, const std::string& shown) {
  if (!v.present()) return "";
  const std::string name = v.text();
  if (tree.links.count(name)) return name;
  std::vector<std::string_view> names;
  for (const auto& [link, _] : tree.links) names.push_back(link);
  const std::string guess = closest(name, names);
  v.fail(shown + " has no link named \"" + name + "\"" +
         (guess.empty() ? "" : " (did you mean \"" + guess + "\"?)"));
}

void fill(const urdf::Chain& chain, const std::string& shown, Model& model, RobotInfo& info) {
  model.joints.insert(model.joints.end(), chain.joints.begin(), chain.joints.end());
  model.links.insert(model.links.end(), chain.links.begin(), chain.links.end());
  model.damping = chain.damping;
  ChainNames& names = info.names;
  names.urdf = shown;
  names.base_link = chain.base;
  names.tip_link = chain.tip;
  names.joints = chain.joint_names;
  names.links = chain.link_names;
  names.merged = chain.merged;
  names.q_min = chain.q_min;
  names.q_max = chain.q_max;
  for (Eigen::Index i = 0; i < chain.friction.size(); ++i)
    if (chain.friction[i] != 0)
      names.notes.push_back("joint \"" + chain.joint_names[std::size_t(i)] +
                            "\": <dynamics friction> is not simulated (give joint_friction:)");
  for (const auto& [name, frame] : chain.frames) info.frames[name] = {frame.link, frame.to_link};
}

}  // namespace

RobotInfo read_urdf_chain(const Value& robot, Model& model, const std::string& scenario_file) {
  const Value urdf = robot.get("urdf");
  RobotInfo info;
  info.form = RobotInfo::Form::urdf;
  std::string shown;
  info.urdf_text = read_urdf_text(urdf, scenario_file, shown);
  urdf::Tree tree;
  try {
    tree = urdf::parse(info.urdf_text);
  } catch (const urdf::UrdfError& e) {
    urdf.fail(shown + ": " + e.what());
  }
  const std::string base = read_link_name(robot.get("base_link"), tree, shown);
  const std::string tip = read_link_name(robot.get("tip_link"), tree, shown);
  try {
    fill(urdf::build_chain(tree, base, tip), shown, model, info);
  } catch (const urdf::UrdfError& e) {
    urdf.fail(shown + ": " + e.what());
  }
  return info;
}

}  // namespace elbowsim::loader
