#include "render/inset.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "engine/recording/number_text.hpp"
#include "render/nice_scale.hpp"

namespace elbowsim {

namespace {

constexpr double kMargin = 1.2;       // whole-path window: path size times this
constexpr double kFollow = 2.0;       // following window: path height times this
constexpr double kMinWindow = 0.005;  // [m]
constexpr double kKeep = 0.3;         // the hand stays within +-kKeep window sizes of the centre

// Principal axes of the points, largest spread first (columns), and the
// spread (standard deviation) along each.
void principal_axes(const std::vector<Eigen::Vector3d>& points, Eigen::Matrix3d& axes,
                    Eigen::Vector3d& spread) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) covariance += (p - mean) * (p - mean).transpose();
  covariance /= double(points.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);  // ascending
  for (int k = 0; k < 3; ++k) {
    axes.col(k) = solver.eigenvectors().col(2 - k);
    spread[k] = std::sqrt(std::max(solver.eigenvalues()[2 - k], 0.0));
  }
}

// The view direction: the path plane's normal toward main_back; for a
// straight path (or a point) main_back made square to its line.
Eigen::Vector3d view_back(const std::vector<Eigen::Vector3d>& path,
                          const Eigen::Vector3d& main_back) {
  if (path.size() < 2) return main_back;
  Eigen::Matrix3d axes;
  Eigen::Vector3d spread;
  principal_axes(path, axes, spread);
  if (spread[0] < 1e-6) return main_back;  // a point
  Eigen::Vector3d back;
  if (spread[1] > 0.05 * spread[0]) {
    back = axes.col(2);
  } else {
    const Eigen::Vector3d line = axes.col(0);
    back = main_back - main_back.dot(line) * line;
    if (back.norm() < 1e-6) back = axes.col(1);
  }
  back.normalize();
  return back.dot(main_back) < 0 ? Eigen::Vector3d(-back) : back;
}

// Up in the inset: world z made square to back; for a view along z, y.
Eigen::Vector3d view_up(const Eigen::Vector3d& back) {
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ() - back.z() * back;
  if (up.norm() < 0.1) up = Eigen::Vector3d::UnitY() - back.y() * back;
  return up.normalized();
}

// The runs of `path` through the camera's window grown on each side by a
// fifth of its height: every point inside it, with the points just before and after a run
// (so that its segments reach the edge).
std::vector<std::vector<Eigen::Vector3d>> in_window(const std::vector<Eigen::Vector3d>& path,
                                                    const Camera& c) {
  const CameraBasis basis = c.basis();
  const Eigen::Vector3d &right = basis.right, &up = basis.up;
  const double half_h = 0.7 * c.ortho_height, half_w = half_h * c.aspect;
  auto inside = [&](std::size_t k) {
    const Eigen::Vector3d d = path[k] - c.target;
    return std::abs(d.dot(right)) <= half_w && std::abs(d.dot(up)) <= half_h;
  };
  std::vector<std::vector<Eigen::Vector3d>> pieces;
  bool open = false;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const bool keep =
        inside(k) || (k > 0 && inside(k - 1)) || (k + 1 < path.size() && inside(k + 1));
    if (keep && !open) pieces.emplace_back();
    if (keep) pieces.back().push_back(path[k]);
    open = keep;
  }
  return pieces;
}

}  // namespace

std::size_t InsetPath::points() const {
  std::size_t n = 0;
  for (const auto& piece : pieces) n += piece.size();
  return n;
}

InsetPlan plan_inset(const std::vector<Eigen::Vector3d>& path, const Eigen::Vector3d& main_back,
                     const InsetSettings& settings) {
  InsetPlan plan;
  plan.back = view_back(path, main_back.normalized());
  plan.up = view_up(plan.back);
  const Eigen::Vector3d right = plan.right();
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector3d& p : path) box.extend(Eigen::Vector2d(p.dot(right), p.dot(plan.up)));
  if (box.isEmpty()) box.extend(Eigen::Vector2d::Zero());
  plan.extent = box.sizes();
  const double depth = path.empty() ? 0.0 : path.front().dot(plan.back);
  plan.centre = box.center().x() * right + box.center().y() * plan.up + depth * plan.back;
  const double whole = kMargin * std::max(plan.extent.y(), plan.extent.x() / plan.aspect);
  plan.view_height =
      std::max({std::min(whole, kFollow * plan.extent.y()), plan.extent.x() / 8, kMinWindow});
  if (settings.view_height > 0) plan.view_height = settings.view_height;
  plan.scale_bar = settings.scale_bar > 0 ? settings.scale_bar
                                          : nice_floor(0.3 * plan.view_height * plan.aspect);
  return plan;
}

Eigen::Vector3d inset_target(const InsetPlan& plan, const Eigen::Vector3d& hand) {
  const Eigen::Vector3d right = plan.right();
  const double size[2] = {plan.view_height * plan.aspect, plan.view_height};
  const Eigen::Vector3d axis[2] = {right, plan.up};
  Eigen::Vector3d target = hand;  // keeps the hand's depth along back
  for (int k = 0; k < 2; ++k) {
    const double h = hand.dot(axis[k]), c = plan.centre.dot(axis[k]);
    target += (std::clamp(c, h - kKeep * size[k], h + kKeep * size[k]) - h) * axis[k];
  }
  return target;
}

PixelRect inset_rect(int width, int height, const std::vector<Eigen::Vector2d>& avoid) {
  int h = int(std::min(0.45 * width * 3 / 4, 0.42 * height)) / 2 * 2;
  int w = (h * 4 / 3) / 2 * 2;
  const int margin = std::max(2, height / 60);
  const std::array<PixelRect, 3> corners = {
      PixelRect{width - w - margin, height - h - margin, w, h},  // bottom right
      PixelRect{margin, height - h - margin, w, h},              // bottom left
      PixelRect{width - w - margin, margin, w, h}};              // top right
  auto covered = [&](const PixelRect& r) {
    int n = 0;
    for (const Eigen::Vector2d& p : avoid)
      n += p.x() >= r.x && p.x() < r.x + r.width && p.y() >= r.y && p.y() < r.y + r.height;
    return n;
  };
  PixelRect best = corners[0];
  for (const PixelRect& r : corners)
    if (covered(r) < covered(best)) best = r;
  return best;
}

Inset make_inset(const InsetPlan& plan, const PixelRect& rect, const Camera& main, int panel_height,
                 const Eigen::Vector3d& hand, const std::vector<Eigen::Vector3d>& desired,
                 const std::vector<Eigen::Vector3d>& traced, const Eigen::AlignedBox3d& depth,
                 const InsetStyle& style) {
  Inset inset;
  inset.rect = rect;
  inset.background = style.background;
  inset.fade = style.fade;
  Camera& c = inset.camera;
  c.ortho_height = plan.view_height;
  c.aspect = double(rect.width) / std::max(rect.height, 1);
  c.up = plan.up;
  c.target = inset_target(plan, hand);
  // The eye outside everything drawn, looking along -back.
  Eigen::AlignedBox3d all = depth;
  all.extend(hand);
  c.eye = c.target + (all.diagonal().norm() + (all.center() - c.target).norm() + 0.1) * plan.back;
  fit_clip(c, all);

  const double per_metre = rect.height / plan.view_height;  // [px/m] in the inset
  inset.desired = {in_window(desired, c), 3.0 / per_metre, style.desired};
  inset.traced = {in_window(traced, c), 1.0 / per_metre, style.traced};
  inset.hand = {hand, 3.5 / per_metre, style.hand};
  inset.magnification = per_metre / main.pixels_per_metre(hand, panel_height);
  inset.scale_bar = plan.scale_bar;
  inset.scale_bar_px = plan.scale_bar * per_metre;
  inset.scale_label = length_label(plan.scale_bar);
  const double m = inset.magnification;
  inset.title =
      "hand path \u00d7" + significant(m >= 10 ? std::round(m) : std::round(10 * m) / 10, 3);
  return inset;
}

}  // namespace elbowsim
