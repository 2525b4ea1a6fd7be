#include "app/commands/camera_option.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

namespace elbowsim {

namespace {

const CameraPreset kPresets[] = {CameraPreset::front, CameraPreset::side, CameraPreset::top,
                                 CameraPreset::three_quarter};

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> out(1);
  for (char c : text)
    if (c == by)
      out.emplace_back();
    else
      out.back().push_back(c);
  return out;
}

bool parse_number(const std::string& text, double& x) {
  char* end = nullptr;
  x = std::strtod(text.c_str(), &end);
  return !text.empty() && !*end && std::isfinite(x);
}

// The items grouped by key: "eye=1,2,3,fov=20" -> {eye: [1, 2, 3], fov: [20]};
// a leading bare word is the preset. "" or the message.
std::string group(const std::string& text, std::map<std::string, std::vector<std::string>>& out) {
  std::string key;
  for (const std::string& item : split(text, ',')) {
    const std::size_t equals = item.find('=');
    if (equals != std::string::npos) {
      key = item.substr(0, equals);
      if (key == "fov_deg") key = "fov";
      if (key != "preset" && key != "eye" && key != "target" && key != "up" && key != "fov")
        return "unknown key \"" + key + "\" (keys: preset, eye, target, up, fov)";
      if (out.count(key)) return "\"" + key + "\" given twice";
      out[key].push_back(item.substr(equals + 1));
    } else if (key.empty() && out.empty()) {
      out["preset"].push_back(item);
    } else if (key.empty()) {
      return "\"" + item + "\" is not key=value";
    } else {
      out[key].push_back(item);
    }
  }
  return "";
}

std::string read_preset(const std::string& name, CameraPreset& preset) {
  for (CameraPreset p : kPresets)
    if (name == to_string(p)) return preset = p, "";
  return "preset must be one of front, side, top, three_quarter (got \"" + name + "\")";
}

std::string read_vector(const std::string& key, const std::vector<std::string>& items,
                        Eigen::Vector3d& v) {
  if (items.size() != 3)
    return key + " needs 3 numbers x,y,z [m] (got " + std::to_string(items.size()) + ")";
  for (int k = 0; k < 3; ++k)
    if (!parse_number(items[std::size_t(k)], v[k]))
      return key + ": \"" + items[std::size_t(k)] + "\" is not a number";
  return "";
}

}  // namespace

std::string apply_camera_option(const std::string& text, CameraSettings& camera) {
  auto fail = [&](const std::string& why) {
    return "--camera: " + why + " (got \"" + text + "\"; e.g. top, front,fov=25 or " +
           "eye=0.6,-0.9,0.2,target=0.6,0,0,fov=20)";
  };
  std::map<std::string, std::vector<std::string>> items;
  if (std::string error = group(text, items); !error.empty()) return fail(error);
  CameraSettings out = camera;
  const bool pose = items.count("eye") || items.count("target") || items.count("up");
  if (items.count("preset")) {
    if (pose) return fail("give a preset or eye and target, not both");
    if (items["preset"].size() != 1) return fail("preset takes one name");
    if (std::string error = read_preset(items["preset"][0], out.preset); !error.empty())
      return fail(error);
    out.explicit_pose = false;
  }
  if (pose) {
    if (!items.count("eye") || !items.count("target")) return fail("eye and target go together");
    out.up = Eigen::Vector3d::UnitZ();
    for (auto [key, v] : {std::pair{"eye", &out.eye}, {"target", &out.target}, {"up", &out.up}})
      if (items.count(key))
        if (std::string error = read_vector(key, items[key], *v); !error.empty())
          return fail(error);
    const Eigen::Vector3d view = out.target - out.eye;
    if (view.norm() < 1e-9) return fail("target must differ from eye");
    if (out.up.cross(view).norm() <= 1e-9 * out.up.norm() * view.norm())
      return fail("up must not be zero or parallel to target - eye");
    out.explicit_pose = true;
  }
  if (items.count("fov")) {
    double fov = 0;
    if (items["fov"].size() != 1 || !parse_number(items["fov"][0], fov) || fov < 1 || fov > 170)
      return fail("fov must be one number of degrees in [1, 170]");
    out.fov_deg = fov;
  }
  camera = out;
  return "";
}

std::string apply_follow_option(const std::string& text, CameraSettings& camera) {
  if (text == "hand") return camera.follow = CameraFollow::hand, "";
  if (text == "none") return camera.follow = CameraFollow::none, "";
  return "--follow: must be hand or none (got \"" + text + "\")";
}

}  // namespace elbowsim
