// One recorded run ready to be drawn: its playback, scene options, camera and
// overlay text, all without GL. The renderer draws one FrameSource per panel,
// so two runs can share a frame side by side (a later comparison command).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/recording/recording.hpp"
#include "render/camera.hpp"
#include "render/inset.hpp"
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
  // For an image of this width / height at time t [s] (a following camera
  // moves; the others do not).
  Camera camera(double aspect, double t = 0) const;
  // The inset of a panel width x height px whose view at t is `main`; none
  // when the recording has no desired hand path (no task) or the settings
  // turn it off. The
  // corner is chosen once for the panel's shape (the view at the start).
  std::optional<Inset> inset(double t, const Camera& main, int width, int height) const;
  // [m/N] length of a force arrow per newton in use (settings, or automatic).
  double force_scale() const { return options_.force_scale; }

 private:
  const Model& model_;
  mutable Data kinematics_;  // forward-kinematics scratch for scene(); one per source
  Playback playback_;
  CameraSettings camera_;
  std::string title_;
  SceneOptions options_;
  bool shadows_;
  Eigen::AlignedBox3d frame_, depth_;
  std::vector<Eigen::Vector3d> swept_points_;  // [m] link ends and elbows over the run
  std::optional<InsetPlan> inset_;
};

// [m/N] the force-arrow scale for a recording whose largest force is
// `max_force` [N] on an arm that sweeps `arm_size` [m] (its largest extent):
// a 1-2-5 number of newtons per centimetre at which that force is at most a
// quarter of arm_size long. 0.01 (1 N per cm) when there is no force.
double automatic_force_scale(double max_force, double arm_size);

}  // namespace elbowsim
