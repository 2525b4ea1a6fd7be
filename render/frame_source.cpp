#include "render/frame_source.hpp"

#include <algorithm>
#include <cmath>

#include "render/overlay.hpp"

namespace elbowsim {

namespace {

// Rough reach of the arm from its base [m]: joint offsets plus the last tip.
double reach(const Model& model) {
  double r = 0;
  for (const Joint& j : model.joints) r += j.origin_position.norm();
  if (!model.links.empty()) r += model.links.back().tip.norm() + model.links.back().radius;
  return std::max(r, 0.1);
}

// The arm at up to 240 recorded samples, plus the hand path and desired path.
Eigen::AlignedBox3d swept_bounds(const Model& model, const Playback& playback,
                                 const SceneOptions& options) {
  Eigen::AlignedBox3d out;
  Data kinematics(model);
  const std::size_t rows = playback.samples();
  const std::size_t stride = std::max<std::size_t>(1, rows / 240);
  for (std::size_t r = 0; r < rows; r += stride)
    out.extend(
        arm_bounds(build_scene(model, kinematics, playback.at(playback.time(r)), {}, options)));
  out.extend(arm_bounds(build_scene(model, kinematics, playback.at(playback.end_time()), {}, options)));
  for (const Eigen::Vector3d& p : playback.hand_path(playback.end_time())) out.extend(p);
  for (const Eigen::Vector3d& p : playback.desired_hand_path()) out.extend(p);
  return out;
}

// The table where it is near the arm: each box clipped to the swept space
// grown by half the reach sideways (a huge table does not shrink the arm to a
// dot), and to its own extent downwards.
Eigen::AlignedBox3d nearby_table(const Model& model, const Eigen::AlignedBox3d& swept) {
  Eigen::AlignedBox3d near = swept;
  const double grow = reach(model) / 2;
  near.min() -= Eigen::Vector3d(grow, grow, 1e3);
  near.max() += Eigen::Vector3d(grow, grow, grow);
  Eigen::AlignedBox3d out;
  for (const TableBox& b : model.table) {
    const Eigen::AlignedBox3d box = box_bounds({b.center, b.rotation, b.size, {}});
    const Eigen::AlignedBox3d clipped = box.intersection(near);
    if (!clipped.isEmpty()) out.extend(clipped);
  }
  return out;
}

// The ground grid lies under everything framed (the table stands on it; an
// arm without a table swings 5 cm above it), over the frame's x-y extent
// grown by 10 cm, 0.1 m apart (coarser for big scenes: at most ~40 lines).
void place_grid(SceneOptions& options, const Eigen::AlignedBox3d& frame, bool table) {
  options.floor_z = frame.min().z() - (table ? 0.0 : 0.05);
  options.grid_area = Eigen::AlignedBox2d(frame.min().head<2>() - Eigen::Vector2d::Constant(0.1),
                                          frame.max().head<2>() + Eigen::Vector2d::Constant(0.1));
  const double extent = options.grid_area.sizes().maxCoeff();
  options.grid_spacing = 0.1;
  for (double s : {0.25, 0.5, 1.0, 2.5, 5.0})
    if (extent / options.grid_spacing > 40) options.grid_spacing = s;
}

}  // namespace

FrameSource::FrameSource(const Model& model, const Recording& recording,
                         const RenderSettings& settings, std::string title)
    : model_(model),
      kinematics_(model),
      playback_(model, recording),
      camera_(settings.camera),
      title_(std::move(title)) {
  options_.force_scale = settings.force_scale;
  frame_ = swept_bounds(model, playback_, options_);
  frame_.extend(nearby_table(model, frame_));
  place_grid(options_, frame_, !model.table.empty());
  depth_ = frame_;
  depth_.extend(Eigen::Vector3d(options_.grid_area.min().x(), options_.grid_area.min().y(),
                                options_.floor_z));
  depth_.extend(Eigen::Vector3d(options_.grid_area.max().x(), options_.grid_area.max().y(),
                                options_.floor_z));
}

Scene FrameSource::scene(double t) const {
  return build_scene(model_, kinematics_, playback_.at(t), playback_.hand_path(t), options_,
                     playback_.desired_hand_path());
}

std::vector<std::string> FrameSource::overlay(double t) const {
  return overlay_lines(title_, model_, playback_.at(t), options_.landed_window);
}

Camera FrameSource::camera(double aspect) const {
  return make_camera(camera_, frame_, depth_, aspect);
}

}  // namespace elbowsim
