// The picture-in-picture view of the hand's path, without GL: a magnified,
// orthographic view that follows the hand, face-on to the plane of the path,
// with the desired path (a wide grey band), the traced path (a thin line on
// it) and the hand's position drawn over a faded copy of the scene, and a
// scale bar. In the main view the path is a few millimetres wide and lies
// inside the last link's capsule; here it fills the inset.
//
// The plan (direction, window, scale bar) is fixed for a run, from the
// path's extent; each frame places the window on the hand.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/pixel_rect.hpp"
#include "render/render_settings.hpp"
#include "render/scene.hpp"

namespace elbowsim {

struct InsetPlan {
  Eigen::Vector3d back = -Eigen::Vector3d::UnitY();  // unit, from the path toward the viewer
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();     // unit, up in the inset, square to back
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // [m] centre of the path's extent
  Eigen::Vector2d extent = Eigen::Vector2d::Zero();  // [m] the path's size along right, up
  double view_height = 0.01;                         // [m] of the world window
  double aspect = 4.0 / 3.0;                         // width / height of the inset
  double scale_bar = 0.002;                          // [m]
  Eigen::Vector3d right() const { return up.cross(back); }
};

// The plan for a path (the desired hand positions): the view looks along
// the normal of the path's plane (principal axes), from the side of
// `main_back` (unit, toward the main camera); for a straight path, square to
// it and as close to main_back as can be. Window height: the whole path with
// a 10 % margin, or twice its height when that is smaller (the window then
// follows the hand along the path), at least 1/8 of its width and 5 mm. The
// scale bar: a 1-2-5 length at most 30 % of the window's width. Settings
// with a view height or scale bar > 0 override those.
InsetPlan plan_inset(const std::vector<Eigen::Vector3d>& path, const Eigen::Vector3d& main_back,
                     const InsetSettings& settings);

// The window's centre for the hand at `hand`: the path's centre, moved along
// right and up only as far as keeps the hand within the middle 60 % of the
// window (so the window does not bob with every loop).
Eigen::Vector3d inset_target(const InsetPlan& plan, const Eigen::Vector3d& hand);

// The inset's place in a panel of width x height px: a 4:3 rectangle in a
// bottom or top-right corner (of those, the one covering fewest of `avoid`,
// pixel positions of the arm in the main view; bottom right on a tie), as
// large as keeps it within 45 % of the panel's width and 42 % of its height.
PixelRect inset_rect(int width, int height, const std::vector<Eigen::Vector2d>& avoid);

// A path as drawn in the inset: only its runs through the window (grown on
// each side by a fifth of its height), so that drawing costs what is seen, not what was
// recorded.
struct InsetPath {
  std::vector<std::vector<Eigen::Vector3d>> pieces;  // [m] world, each a polyline
  double radius = 0;                                 // [m] of its tube
  Color color;
  std::size_t points() const;  // in all pieces
};

struct Inset {
  PixelRect rect;            // [px] in the panel, from its top-left corner
  Camera camera;             // orthographic, on the window
  InsetPath desired;         // the desired path, a band 6 px wide
  InsetPath traced;          // the hand's path up to now, a line 2 px wide
  Sphere hand;               // the hand now, a dot 7 px across
  double magnification = 1;  // inset pixels per metre over the main view's at the hand
  double scale_bar = 0;      // [m]
  double scale_bar_px = 0;   // its length in the inset [px]
  std::string scale_label;   // "1 cm"
  std::string title;         // "hand path ×9"
  Color background;          // of the inset
  float fade = 0;            // the scene behind the paths: its colours this far toward background
};

struct InsetStyle {
  Color background{1.0f, 1.0f, 1.0f};
  Color desired{0.62f, 0.62f, 0.65f};
  Color traced{0.60f, 0.20f, 0.70f};
  Color hand{0.10f, 0.10f, 0.12f};
  float fade = 0.72f;  // the scene behind the paths: its colours this far toward the background
};

// The inset at one instant: `rect` in a panel `panel_height` px tall whose
// view is `main`; the window on `hand`; clip planes around `depth` [m]; the
// paths given whole (world positions in order).
Inset make_inset(const InsetPlan& plan, const PixelRect& rect, const Camera& main, int panel_height,
                 const Eigen::Vector3d& hand, const std::vector<Eigen::Vector3d>& desired,
                 const std::vector<Eigen::Vector3d>& traced, const Eigen::AlignedBox3d& depth,
                 const InsetStyle& style = {});

}  // namespace elbowsim
