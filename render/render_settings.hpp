// What a scene asks of the renderer: the scenario's `render:` section as plain
// data (scenarios/README.md documents every key). No GL here: the scenario
// loader fills it, the renderer reads it.
#pragma once

#include <Eigen/Core>

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
};

struct RenderSettings {
  CameraSettings camera;
  int width = 1280;           // [px] even (H.264 with yuv420p)
  int height = 720;           // [px] even
  double fps = 30.0;          // [1/s] frames per second of simulation time
  int msaa = 4;               // samples per pixel: 1 (off), 2 or 4
  bool supersample = false;   // render 2w x 2h and average 2x2 blocks (for stills)
  double force_scale = 0.01;  // [m/N] length of a normal-force arrow per newton
};

}  // namespace elbowsim
