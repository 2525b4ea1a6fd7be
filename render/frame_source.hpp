// One recorded run ready to be drawn: its playback, scene options, camera and
// overlay text, all without GL. The renderer draws one FrameSource per panel,
// so two runs can share a frame side by side (a later comparison command).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/recording/recording.hpp"
#include "render/camera.hpp"
#include "render/playback.hpp"
#include "render/render_settings.hpp"
#include "render/scene.hpp"

namespace elbowsim {

class FrameSource {
 public:
  // `model` and `recording` must outlive the source. Throws
  // std::invalid_argument if the recording lacks a column it needs (Playback).
  FrameSource(const Model& model, const Recording& recording, const RenderSettings& settings,
              std::string title);

  double end_time() const { return playback_.end_time(); }  // [s]
  const Playback& playback() const { return playback_; }
  const SceneOptions& scene_options() const { return options_; }
  // Space the arm sweeps over the recording plus the nearby table [m]: what
  // the automatic camera frames.
  const Eigen::AlignedBox3d& frame_bounds() const { return frame_; }

  Scene scene(double t) const;                       // at time t [s]
  std::vector<std::string> overlay(double t) const;  // text lines at time t
  Camera camera(double aspect) const;                // for an image of this width / height

 private:
  const Model& model_;
  mutable Data kinematics_;  // forward-kinematics scratch for scene(); one per source
  Playback playback_;
  CameraSettings camera_;
  std::string title_;
  SceneOptions options_;
  Eigen::AlignedBox3d frame_, depth_;
};

}  // namespace elbowsim
