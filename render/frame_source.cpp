#include "render/frame_source.hpp"

#include <algorithm>
#include <cmath>

#include "engine/recording/number_text.hpp"
#include "render/nice_scale.hpp"
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

// The arm at up to 240 recorded samples, plus the hand path and desired
// path; `points` gets the link ends and elbow centres of those samples.
Eigen::AlignedBox3d swept_bounds(const Model& model, const Playback& playback,
                                 const SceneOptions& options,
                                 std::vector<Eigen::Vector3d>& points) {
  Eigen::AlignedBox3d out;
  Data kinematics(model);
  const std::size_t rows = playback.samples();
  const std::size_t stride = std::max<std::size_t>(1, rows / 240);
  auto add = [&](double t) {
    const Scene scene = build_scene(model, kinematics, playback.at(t), {}, options);
    out.extend(arm_bounds(scene));
    for (const Capsule& c : scene.links) points.insert(points.end(), {c.a, c.b});
    for (const ElbowMarker& e : scene.elbows) points.push_back(e.sphere.center);
  };
  for (std::size_t r = 0; r < rows; r += stride) add(playback.time(r));
  add(playback.end_time());
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

double automatic_force_scale(double max_force, double arm_size) {
  if (!(max_force > 0) || !(arm_size > 0)) return 0.01;
  const double newtons_per_cm = nice_ceil(max_force / (100 * 0.25 * arm_size));
  return 0.01 / newtons_per_cm;
}

FrameSource::FrameSource(const Model& model, const Recording& recording,
                         const RenderSettings& settings, std::string title)
    : model_(model),
      kinematics_(model),
      playback_(model, recording),
      camera_(settings.camera),
      title_(std::move(title)),
      shadows_(settings.shadows) {
  // The arm alone first (no arrows), to size the arrows; then with them.
  options_.force_scale = 0;
  const Eigen::AlignedBox3d arm = swept_bounds(model, playback_, options_, swept_points_);
  options_.force_scale = settings.force_scale.value_or(
      automatic_force_scale(playback_.max_force(), arm.sizes().maxCoeff()));
  swept_points_.clear();
  frame_ = swept_bounds(model, playback_, options_, swept_points_);
  frame_.extend(nearby_table(model, frame_));
  place_grid(options_, frame_, !model.table.empty());
  depth_ = frame_;
  depth_.extend(Eigen::Vector3d(options_.grid_area.min().x(), options_.grid_area.min().y(),
                                options_.floor_z));
  depth_.extend(Eigen::Vector3d(options_.grid_area.max().x(), options_.grid_area.max().y(),
                                options_.floor_z));
  // With a task, the inset looks at its desired path from the side the main
  // camera looks from. (Without one there is no path the hand is to write.)
  const auto& desired = playback_.full_desired_hand_path();
  if (settings.inset.show && !desired.empty() && !playback_.full_hand_path(0).empty()) {
    const Camera main = make_camera(camera_, frame_, depth_, 16.0 / 9.0);
    inset_ = plan_inset(desired, main.eye - main.target, settings.inset);
  }
}

Scene FrameSource::scene(double t) const {
  Scene scene = build_scene(model_, kinematics_, playback_.at(t), playback_.hand_path(t), options_,
                            playback_.desired_hand_path());
  scene.shadows = {shadows_, frame_};
  return scene;
}

std::vector<std::string> FrameSource::overlay(double t) const {
  std::vector<std::string> lines =
      overlay_lines(title_, model_, playback_.at(t), options_.landed_window);
  if (model_.effects.contact && options_.force_scale > 0 && playback_.max_force() > 0)
    lines.push_back("force arrows: " + significant(0.01 / options_.force_scale, 3) + " N per cm");
  return lines;
}

Camera FrameSource::camera(double aspect, double t) const {
  Camera camera = make_camera(camera_, frame_, depth_, aspect);
  const std::optional<Eigen::Vector3d> hand = playback_.at(t).hand;
  if (camera_.follow == CameraFollow::none || !hand) return camera;
  camera = camera.moved(*hand - camera.target);
  Eigen::AlignedBox3d everything = depth_;
  everything.extend(frame_);
  fit_clip(camera, everything);
  return camera;
}

std::optional<Inset> FrameSource::inset(double t, const Camera& main, int width, int height) const {
  const PlaybackState state = playback_.at(t);
  if (!inset_ || !state.hand) return std::nullopt;
  const Camera start = camera(double(width) / height, playback_.start_time());
  std::vector<Eigen::Vector2d> avoid;
  for (const Eigen::Vector3d& p : swept_points_)
    if (const auto pixel = start.project(p, width, height)) avoid.push_back(*pixel);
  return make_inset(*inset_, inset_rect(width, height, avoid), main, height, *state.hand,
                    playback_.full_desired_hand_path(), playback_.full_hand_path(t), depth_);
}

}  // namespace elbowsim
