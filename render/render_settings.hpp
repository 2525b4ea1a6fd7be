// What a scene asks of the renderer: the scenario's `render:` section as plain
// data (scenarios/README.md documents every key). No GL here: the scenario
// loader fills it, the renderer reads it.
#pragma once

#include <Eigen/Core>
#include <optional>

namespace elbowsim {

// Named view directions; each is framed automatically (camera.hpp).
enum class CameraPreset { front, side, top, three_quarter };

inline const char* to_string(CameraPreset preset) {
  switch (preset) {
    case CameraPreset::front:
      return "front";
    case CameraPreset::side:
      return "side";
    case CameraPreset::top:
      return "top";
    case CameraPreset::three_quarter:
      return "three_quarter";
  }
  return "?";
}

// What the camera keeps in view as the run plays: nothing (a fixed camera) or
// the hand (the target moves with the recorded hand, the view direction and
// distance stay).
enum class CameraFollow { none, hand };

inline const char* to_string(CameraFollow follow) {
  return follow == CameraFollow::hand ? "hand" : "none";
}

struct CameraSettings {
  // With `explicit_pose` false the camera looks along the preset's direction
  // and frames the space the arm sweeps plus the table; with it true, eye,
  // target and up are used as given.
  CameraPreset preset = CameraPreset::three_quarter;
  bool explicit_pose = false;
  Eigen::Vector3d eye = Eigen::Vector3d(0.5, -1.5, 0.5);  // [m] world
  Eigen::Vector3d target = Eigen::Vector3d::Zero();       // [m] world
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();          // world, not parallel to target - eye
  double fov_deg = 40.0;                                  // vertical field of view [deg]
  CameraFollow follow = CameraFollow::none;
};

// The picture-in-picture view of the hand's path (render/inset.hpp): shown
// when the recording has a desired hand path (a task) and `show` is true. Zero
// lengths are chosen from the path's extent.
struct InsetSettings {
  bool show = true;
  double view_height = 0;  // [m] height of the world window the inset shows; 0: automatic
  double scale_bar = 0;    // [m] length of its scale bar; 0: a 1-2-5 length, at most 0.3 x width
};

// How frames are anti-aliased: FXAA (one sample per pixel, edges smoothed
// after drawing, render/fxaa.hpp; grid lines drawn smooth), multisampling
// (`msaa` samples per pixel, resolved by GL) or not at all.
enum class Antialiasing { fxaa, msaa, none };

inline const char* to_string(Antialiasing a) {
  switch (a) {
    case Antialiasing::fxaa:
      return "fxaa";
    case Antialiasing::msaa:
      return "msaa";
    case Antialiasing::none:
      return "none";
  }
  return "?";
}

struct RenderSettings {
  CameraSettings camera;
  int width = 1280;   // [px] even (H.264 with yuv420p)
  int height = 720;   // [px] even
  double fps = 30.0;  // [1/s] frames per second of simulation time
  Antialiasing antialiasing = Antialiasing::fxaa;
  int msaa = 4;              // samples per pixel with antialiasing msaa: 2 or 4
  bool supersample = false;  // render 2w x 2h and average 2x2 blocks (for stills)
  // [m/N] length of a normal-force arrow per newton (0: no arrows); unset: a
  // 1-2-5 scale at which the largest recorded force fits in the frame.
  std::optional<double> force_scale;
  bool shadows = true;  // shadow mapping from the key light
  InsetSettings inset;

  // Samples per pixel GL draws with.
  int samples() const { return antialiasing == Antialiasing::msaa ? msaa : 1; }
};

}  // namespace elbowsim
