// render: how frames and videos of a run look (camera, size, rate,
// anti-aliasing, shadows, the hand-path inset, force arrows). Whether a run renders at all is
// output.video / output.frames (settings_section.cpp).
#include <cmath>
#include <cstdlib>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

// A whole number in [lo, hi].
long whole_in(const Value& v, long lo, long hi) {
  const long x = v.integer();
  if (x < lo || x > hi)
    v.fail("must be in " + std::to_string(lo) + " .. " + std::to_string(hi) + " (got " +
           std::to_string(x) + ")");
  return x;
}

// render.camera: {preset, fov_deg} or {eye, target, up, fov_deg}, each with follow.
CameraSettings read_camera(const Value& camera) {
  CameraSettings out;
  if (!camera.present()) return out;
  camera.allow_keys({"preset", "eye", "target", "up", "fov_deg", "follow"});
  Value follow = camera.get("follow");
  if (follow.present()) out.follow = choose(follow, {CameraFollow::none, CameraFollow::hand});
  Value fov = camera.get("fov_deg");
  if (fov.present()) {
    out.fov_deg = fov.number();
    if (!(out.fov_deg >= 1 && out.fov_deg <= 170))
      fov.fail("must be in [1, 170] degrees (got " + significant(out.fov_deg) + ")");
  }
  Value preset = camera.get("preset");
  if (preset.present()) {
    for (const char* key : {"eye", "target", "up"})
      if (camera.get(key).exists())
        camera.get(key).fail("give either preset or eye and target (with up), not both");
    out.preset = choose(preset, {CameraPreset::front, CameraPreset::side, CameraPreset::top,
                                 CameraPreset::three_quarter});
    return out;
  }
  if (!camera.get("eye").exists() && !camera.get("target").exists() && !camera.get("up").exists())
    return out;
  out.explicit_pose = true;
  out.eye = camera.require("eye").vec3();
  Value target = camera.require("target");
  out.target = target.vec3();
  const Eigen::Vector3d view = out.target - out.eye;
  if (view.norm() < 1e-9) target.fail("must differ from eye");
  Value up = camera.get("up");
  out.up = value_or(up, out.up, vec3);
  if (out.up.cross(view).norm() <= 1e-9 * out.up.norm() * view.norm())
    (up.present() ? up : target)
        .fail("up [" + listed({out.up.x(), out.up.y(), out.up.z()}) +
              "] must not be zero or parallel to target - eye");
  return out;
}

// render.size: [width, height] in pixels, even (H.264 with yuv420p halves the
// chroma resolution).
void read_size(const Value& size, RenderSettings& out) {
  if (!size.present()) return;
  const std::vector<Value> items = size.items();
  if (items.size() != 2)
    size.fail("expected [width, height] in pixels (got " + std::to_string(items.size()) +
              " values)");
  int* targets[2] = {&out.width, &out.height};
  for (int k = 0; k < 2; ++k) {
    const long x = whole_in(items[std::size_t(k)], 16, 8192);
    if (x % 2 != 0)
      items[std::size_t(k)].fail("must be even (H.264 video with yuv420p; got " +
                                 std::to_string(x) + ")");
    *targets[k] = int(x);
  }
}

// render.inset: {show, view_height, scale_bar}.
InsetSettings read_inset(const Value& inset) {
  InsetSettings out;
  if (!inset.present()) return out;
  inset.allow_keys({"show", "view_height", "scale_bar"});
  out.show = value_or(inset.get("show"), out.show, boolean);
  out.view_height = value_or(inset.get("view_height"), out.view_height, positive);
  out.scale_bar = value_or(inset.get("scale_bar"), out.scale_bar, positive);
  return out;
}

// render.force_scale: auto (unset) or a number >= 0 [m/N].
std::optional<double> read_force_scale(const Value& v) {
  if (!v.present()) return std::nullopt;
  const std::string given = v.text();
  if (given == "auto") return std::nullopt;
  char* end = nullptr;
  std::strtod(given.c_str(), &end);
  if (given.empty() || *end) v.fail("must be auto or a number >= 0 [m/N] (got \"" + given + "\")");
  return non_negative(v);
}

}  // namespace

RenderSettings read_render(const Value& render) {
  RenderSettings out;
  if (!render.present()) return out;
  render.allow_keys({"camera", "size", "fps", "antialiasing", "msaa", "supersample", "force_scale",
                     "shadows", "inset"});
  out.camera = read_camera(render.get("camera"));
  read_size(render.get("size"), out);
  Value fps = render.get("fps");
  out.fps = value_or(fps, out.fps, positive);
  if (out.fps > 240) fps.fail("must be <= 240 (got " + significant(out.fps) + ")");
  // `msaa` alone (as before there was a choice) asks for multisampling, 1 for none.
  Value msaa = render.get("msaa"), antialiasing = render.get("antialiasing");
  if (msaa.present()) {
    const long samples = msaa.integer();
    if (samples != 1 && samples != 2 && samples != 4)
      msaa.fail("must be 1 (off), 2 or 4 (got " + std::to_string(samples) + ")");
    out.msaa = int(samples);
    out.antialiasing = samples > 1 ? Antialiasing::msaa : Antialiasing::none;
  }
  if (antialiasing.present())
    out.antialiasing =
        choose(antialiasing, {Antialiasing::fxaa, Antialiasing::msaa, Antialiasing::none});
  if (out.antialiasing == Antialiasing::msaa && out.msaa == 1)
    msaa.fail("must be 2 or 4 with antialiasing msaa (got 1)");
  out.supersample = value_or(render.get("supersample"), out.supersample, boolean);
  out.force_scale = read_force_scale(render.get("force_scale"));
  out.shadows = value_or(render.get("shadows"), out.shadows, boolean);
  out.inset = read_inset(render.get("inset"));
  return out;
}

}  // namespace elbowsim::loader
