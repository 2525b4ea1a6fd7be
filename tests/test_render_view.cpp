// How a frame looks at the experiment, without GL: the orthographic and
// following cameras, the key light's shadow camera, the hand-path inset (its
// plan from the path, the window that follows the hand, its corner), the
// 1-2-5 scale numbers and the render command's --camera / --follow options.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "app/commands/camera_option.hpp"
#include "render/frame_source.hpp"
#include "render/inset.hpp"
#include "render/lighting.hpp"
#include "render/nice_scale.hpp"
#include "support/approx.hpp"
#include "test_render_fixtures.hpp"

using namespace elbowsim;
using Eigen::Vector3d;
using elbowsim::testing::approx;

namespace {

// The experiment's kind of path: a row of waves 8 cm long and 1.5 cm tall in
// the x-z plane (one point per 0.5 mm of x), starting at `start`.
std::vector<Vector3d> loops(const Vector3d& start = Vector3d(0.62, 0, -0.032)) {
  std::vector<Vector3d> out;
  for (int k = 0; k <= 160; ++k) {
    const double x = 0.0005 * k;
    out.push_back(start + Vector3d(x, 0, 0.0075 * (1 - std::cos(std::numbers::pi * x / 0.01))));
  }
  return out;
}

const Vector3d kMainBack = Vector3d(0.55, -1.0, 0.5).normalized();  // three_quarter

}  // namespace

TEST_CASE("render camera: orthographic projection and pixels per metre") {
  Camera c;
  c.eye = Vector3d(0.6, -1, 0);
  c.target = Vector3d(0.6, 0, 0);
  c.ortho_height = 0.03;
  c.aspect = 4.0 / 3.0;
  c.near = 0.5;
  c.far = 1.5;
  CHECK(approx(*c.project(c.target, 400, 300), Eigen::Vector2d(200, 150), 1e-9));
  // 1 cm up is 100 px up, at any depth; 1 cm to the right (+x seen from -y) 100 px right.
  CHECK(approx(*c.project(c.target + Vector3d(0, 0.3, 0.01), 400, 300), Eigen::Vector2d(200, 50),
               1e-9));
  CHECK(approx(*c.project(c.target + Vector3d(0.01, 0, 0), 400, 300), Eigen::Vector2d(300, 150),
               1e-9));
  CHECK(c.pixels_per_metre(c.target, 300) == doctest::Approx(10000));
  Camera p = c;
  p.ortho_height = 0;
  p.fov_deg = 90;  // tan 45 deg = 1: at 1 m, the 300 px span 2 m
  CHECK(p.pixels_per_metre(c.target, 300) == doctest::Approx(150));
  CHECK(approx(c.moved(Vector3d(0.1, 0, 0)).target, Vector3d(0.7, 0, 0), 1e-12));
}

TEST_CASE("render camera: --follow hand keeps the hand at the centre, the direction unchanged") {
  const Model model = render_fixture::arm();
  const Recording rec = render_fixture::recording();
  RenderSettings settings;
  const FrameSource fixed(model, rec, settings, "fixture");
  settings.camera.follow = CameraFollow::hand;
  settings.camera.fov_deg = 10;
  const FrameSource following(model, rec, settings, "fixture");
  for (double t : {0.0, 0.15, 0.7}) {
    CAPTURE(t);
    const Camera c = following.camera(16.0 / 9.0, t);
    const Vector3d hand = *following.playback().at(t).hand;
    CHECK(approx(c.target, hand, 1e-12));
    CHECK(approx(*c.project(hand, 1280, 720), Eigen::Vector2d(640, 360), 1e-6));
    const Camera f = fixed.camera(16.0 / 9.0, t);
    CHECK(approx((c.eye - c.target).normalized(), (f.eye - f.target).normalized(), 1e-9));
  }
  // Without follow the camera does not move.
  CHECK(approx(fixed.camera(1.5, 0.0).eye, fixed.camera(1.5, 0.7).eye, 0));
}

TEST_CASE("render lighting: a highlight shows on a box seen along its mirror direction only") {
  // A 0.7 x 0.6 x 0.1 m table top at z = 0; the key light from straight
  // above. Seen from straight above, the top mirrors the light into the
  // eye: full highlight. Seen at a grazing angle from far to the side, n.h
  // is about cos(40 deg) on the top and the light is behind the sides: none.
  Lighting l;
  l.key = Vector3d(0, 0, 1);
  l.fill = Vector3d(1, 0, 0);
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
  model.topLeftCorner<3, 3>() = Eigen::Vector3f(0.7f, 0.6f, 0.1f).asDiagonal();
  model(2, 3) = -0.05f;
  CHECK(specular_shows(l, Vector3d(0, 0, 2), model));
  CHECK_FALSE(specular_shows(l, Vector3d(0, -3, 0.2), model));
  // Off to the side of the top but still looking down on it: the highlight
  // is at the mirror point of the eye, inside the top, between grid points.
  CHECK(specular_shows(l, Vector3d(0.13, 0.07, 1.5), model));
  // No specular at all: never.
  l.specular = 0;
  CHECK_FALSE(specular_shows(l, Vector3d(0, 0, 2), model));
}

TEST_CASE("render lighting: a key light from above-left; its shadow view holds the bounds") {
  Camera c;
  c.eye = Vector3d(1, -2, 1);
  c.target = Vector3d(0.5, 0, 0);
  const Lighting l = view_lighting(c);
  const Vector3d right = c.up.cross((c.eye - c.target).normalized()).normalized();
  CHECK(l.key.norm() == doctest::Approx(1));
  CHECK(l.key.z() > 0.8);       // mostly from above
  CHECK(l.key.dot(right) < 0);  // from the left: shadows fall to the right
  const Eigen::AlignedBox3d bounds(Vector3d(-0.1, -0.3, -0.15), Vector3d(1.0, 0.3, 0.6));
  const ShadowView v = shadow_view(l.key, bounds, 1024);
  const Camera& s = v.camera;
  CHECK(approx((s.eye - s.target).normalized(), l.key, 1e-12));
  // Texels of the bounds' diagonal over 1024, square (the projection's pixels
  // per metre agree both ways), and no more of them than hold the bounds: a
  // corner on each side of the map, within one texel of its edge.
  CHECK(v.texel == doctest::Approx(bounds.diagonal().norm() / 1024));
  CHECK(s.ortho_height * s.aspect / v.width == doctest::Approx(v.texel));
  CHECK(s.ortho_height / v.height == doctest::Approx(v.texel));
  CHECK(v.width <= 1024);
  CHECK(v.height <= 1024);
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (int k = 0; k < 8; ++k) {
    const Vector3d p = bounds.corner(Eigen::AlignedBox3d::CornerType(k));
    const Eigen::Vector2d px = *s.project(p, v.width, v.height);
    min_x = std::min(min_x, px.x()), max_x = std::max(max_x, px.x());
    min_y = std::min(min_y, px.y()), max_y = std::max(max_y, px.y());
    const double depth = (p - s.eye).dot((s.target - s.eye).normalized());
    CHECK(depth > s.near);
    CHECK(depth < s.far);
  }
  CHECK(min_x >= 0);
  CHECK(min_y >= 0);
  CHECK(max_x <= v.width);
  CHECK(max_y <= v.height);
  CHECK(min_x + (v.width - max_x) <= 1.0 + 1e-9);
  CHECK(min_y + (v.height - max_y) <= 1.0 + 1e-9);
  // A wide, flat box seen from above takes far fewer texels than the square
  // around its sphere did (the experiment's bounds: half).
  CHECK(double(v.width) * v.height < 0.75 * 1024 * 1024);
}

TEST_CASE("render inset: the plan faces the path's plane; window and scale bar from its extent") {
  const InsetPlan wave = plan_inset(loops(), kMainBack, {});
  CHECK(approx(wave.back, Vector3d(0, -1, 0), 1e-9));  // face-on, from the main camera's side
  CHECK(approx(wave.up, Vector3d(0, 0, 1), 1e-9));
  CHECK(approx(wave.right(), Vector3d(1, 0, 0), 1e-9));
  CHECK(wave.extent.x() == doctest::Approx(0.08));
  CHECK(wave.extent.y() == doctest::Approx(0.015));
  CHECK(wave.view_height == doctest::Approx(0.03));  // twice its height: it follows the hand
  CHECK(wave.scale_bar == doctest::Approx(0.01));    // 30 % of the 4 cm width, 1-2-5 below
  // A 3 cm circle: the whole of it with a 10 % margin.
  std::vector<Vector3d> circle;
  for (int k = 0; k < 100; ++k) {
    const double a = 2 * std::numbers::pi * k / 100;
    circle.push_back(Vector3d(0.6 + 0.015 * std::cos(a), 0, 0.015 * std::sin(a)));
  }
  CHECK(plan_inset(circle, kMainBack, {}).view_height == doctest::Approx(0.036));
  // A straight stroke: seen square to it, from as near the main view as can be.
  const std::vector<Vector3d> line = {Vector3d(0.6, 0, 0), Vector3d(0.64, 0, 0),
                                      Vector3d(0.68, 0, 0)};
  const InsetPlan stroke = plan_inset(line, kMainBack, {});
  CHECK(approx(stroke.back, Vector3d(0, -1, 0.5).normalized(), 1e-9));  // kMainBack without x
  CHECK(stroke.view_height == doctest::Approx(0.01));                   // 1/8 of its length
  // A point (holding still): the main view's direction, the smallest window.
  const InsetPlan hold = plan_inset({Vector3d(0.6, 0, 0)}, kMainBack, {});
  CHECK(approx(hold.back, kMainBack, 1e-12));
  CHECK(hold.view_height == 0.005);
  // The scene's own numbers win.
  InsetSettings given;
  given.view_height = 0.05;
  given.scale_bar = 0.002;
  const InsetPlan own = plan_inset(loops(), kMainBack, given);
  CHECK(own.view_height == 0.05);
  CHECK(own.scale_bar == 0.002);
}

TEST_CASE("render inset: the window follows the hand without bobbing with every loop") {
  const std::vector<Vector3d> path = loops();
  const InsetPlan plan = plan_inset(path, kMainBack, {});
  const double width = plan.view_height * plan.aspect;
  double up_min = 1e9, up_max = -1e9;
  for (const Vector3d& hand : path) {
    const Vector3d target = inset_target(plan, hand);
    CHECK(std::abs((target - hand).dot(plan.right())) <= 0.3 * width + 1e-12);
    CHECK(std::abs((target - hand).dot(plan.up)) <= 0.3 * plan.view_height + 1e-12);
    CHECK((target - hand).dot(plan.back) == doctest::Approx(0).epsilon(1e-12));
    up_min = std::min(up_min, target.z()), up_max = std::max(up_max, target.z());
  }
  CHECK(up_max - up_min < 1e-12);  // 1.5 cm tall waves in a 3 cm window: it stays put
  CHECK(inset_target(plan, path.front()).x() > path.front().x() + 0.01);  // ahead at the start
  CHECK(inset_target(plan, path.back()).x() < path.back().x() - 0.01);    // behind at the end
}

TEST_CASE("render inset: a 4:3 corner away from the arm; the hand and the path where projected") {
  const PixelRect r = inset_rect(1280, 720, {});
  CHECK(r.height == 302);
  CHECK(r.width == 402);
  CHECK(r.x + r.width == 1280 - 12);  // bottom right
  CHECK(r.y + r.height == 720 - 12);
  const PixelRect left = inset_rect(1280, 720, {Eigen::Vector2d(1200, 600)});
  CHECK(left.x == 12);  // bottom left: the arm is in the bottom right
  const PixelRect panel = inset_rect(640, 720, {});
  CHECK(panel.width <= 0.45 * 640 + 1);

  const std::vector<Vector3d> path = loops();
  const InsetPlan plan = plan_inset(path, kMainBack, {});
  Camera main;
  main.eye = Vector3d(1.2, -1.0, 0.5);
  main.target = Vector3d(0.6, 0, 0);
  const Vector3d hand = path[70];
  const Inset inset = make_inset(plan, r, main, 720, hand, path, {path.begin(), path.begin() + 71},
                                 Eigen::AlignedBox3d(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)));
  CHECK(inset.camera.ortho_height == plan.view_height);
  const Eigen::Vector2d h = *inset.camera.project(hand, r.width, r.height);
  CHECK(h.x() > 0.2 * r.width);
  CHECK(h.x() < 0.8 * r.width);
  CHECK(h.y() > 0.2 * r.height);
  CHECK(h.y() < 0.8 * r.height);
  // 1 cm of path is view_height / 1 cm of the inset's height.
  const Eigen::Vector2d ahead =
      *inset.camera.project(hand + Vector3d(0.01, 0, 0), r.width, r.height);
  CHECK(ahead.x() - h.x() == doctest::Approx(0.01 / plan.view_height * r.height));
  CHECK(inset.scale_bar_px == doctest::Approx(0.01 / plan.view_height * r.height));
  CHECK(inset.scale_label == "1 cm");
  CHECK(inset.magnification ==
        doctest::Approx(r.height / plan.view_height / main.pixels_per_metre(hand, 720)));
  CHECK(inset.title.find("hand path \u00d7") == 0);
  // Only the runs of the paths through the window (grown by a fifth): here
  // one run each, the traced one ending at the hand.
  REQUIRE(inset.desired.pieces.size() == 1);
  REQUIRE(inset.traced.pieces.size() == 1);
  CHECK(inset.desired.points() < path.size());
  CHECK(inset.desired.points() > 40);
  CHECK(approx(inset.traced.pieces[0].back(), hand, 0));
  for (const Vector3d& p : inset.desired.pieces[0]) {
    const Eigen::Vector2d px = *inset.camera.project(p, r.width, r.height);
    CHECK(std::abs(px.x() - 0.5 * r.width) < 0.72 * r.width);  // inside, or the next point out
  }
  CHECK(inset.desired.radius > inset.traced.radius);  // the band under the line
}

TEST_CASE("render inset: only with a task's desired path, unless turned off") {
  const Model model = render_fixture::arm();
  Recording with = render_fixture::recording(true);  // hand_d_*: a 20 cm line
  for (std::size_t r = 0; r < with.rows(); ++r)
    testing::set(with, r, with.layout.hand_desired(0), 0.75 - 0.02 * double(r));
  const Recording without = render_fixture::recording();
  RenderSettings settings;
  const FrameSource task(model, with, settings, "task");
  const Camera main = task.camera(16.0 / 9.0);
  const std::optional<Inset> inset = task.inset(0.5, main, 1280, 720);
  REQUIRE(inset);
  CHECK(inset->desired.points() > 0);
  CHECK(inset->traced.points() > 0);
  CHECK_FALSE(FrameSource(model, without, settings, "free").inset(0.5, main, 1280, 720));
  settings.inset.show = false;
  CHECK_FALSE(FrameSource(model, with, settings, "off").inset(0.5, main, 1280, 720));
}

TEST_CASE("render scale numbers: 1-2-5 rounding and length labels") {
  CHECK(nice_ceil(3.28) == doctest::Approx(5));
  CHECK(nice_ceil(0.011) == doctest::Approx(0.02));
  CHECK(nice_ceil(2) == doctest::Approx(2));
  CHECK(nice_floor(0.012) == doctest::Approx(0.01));
  CHECK(nice_floor(0.0499) == doctest::Approx(0.02));
  CHECK(nice_floor(7) == doctest::Approx(5));
  CHECK(length_label(0.01) == "1 cm");
  CHECK(length_label(0.005) == "5 mm");
  CHECK(length_label(0.2) == "20 cm");
  CHECK(length_label(2) == "2 m");
  CHECK(length_label(5e-4) == "500 \u00b5m");
}

TEST_CASE("render --camera and --follow: presets, eye/target/fov, and clear errors") {
  CameraSettings c;
  CHECK(apply_camera_option("top", c) == "");
  CHECK(c.preset == CameraPreset::top);
  CHECK_FALSE(c.explicit_pose);
  CHECK(apply_camera_option("front,fov=25", c) == "");
  CHECK(c.preset == CameraPreset::front);
  CHECK(c.fov_deg == 25);
  CHECK(apply_camera_option("eye=0.6,-0.9,0.2,target=0.6,0,-0.03,fov=12", c) == "");
  CHECK(c.explicit_pose);
  CHECK(c.eye == Vector3d(0.6, -0.9, 0.2));
  CHECK(c.target == Vector3d(0.6, 0, -0.03));
  CHECK(c.up == Vector3d(0, 0, 1));
  CHECK(c.fov_deg == 12);
  CHECK(apply_camera_option("fov=30", c) == "");  // only the field of view changes
  CHECK(c.explicit_pose);
  CHECK(c.fov_deg == 30);
  CHECK(apply_camera_option("eye=0,0,1,target=0,0,0,up=0,1,0", c) == "");
  CHECK(c.up == Vector3d(0, 1, 0));

  const CameraSettings before = c;
  auto error = [&](const std::string& text) {
    CameraSettings copy = before;
    const std::string e = apply_camera_option(text, copy);
    CHECK(copy.eye == before.eye);  // unchanged on an error
    CHECK(copy.fov_deg == before.fov_deg);
    return e;
  };
  CHECK(error("diagonal").find("--camera: preset must be one of front, side, top") == 0);
  CHECK(error("eye=1,2,target=0,0,0").find("eye needs 3 numbers x,y,z [m] (got 2)") !=
        std::string::npos);
  CHECK(error("eye=1,2,3").find("eye and target go together") != std::string::npos);
  CHECK(error("top,eye=1,2,3,target=0,0,0").find("a preset or eye and target, not both") !=
        std::string::npos);
  CHECK(error("fov=200").find("fov must be one number of degrees in [1, 170]") !=
        std::string::npos);
  CHECK(error("eye=1,1,1,target=1,1,1").find("target must differ from eye") != std::string::npos);
  CHECK(error("eye=0,0,1,target=0,0,0").find("up must not be zero or parallel") !=
        std::string::npos);
  CHECK(error("zoom=2").find("unknown key \"zoom\"") != std::string::npos);
  CHECK(error("eye=a,0,0,target=0,0,0").find("eye: \"a\" is not a number") != std::string::npos);

  CHECK(apply_follow_option("hand", c) == "");
  CHECK(c.follow == CameraFollow::hand);
  CHECK(apply_follow_option("none", c) == "");
  CHECK(c.follow == CameraFollow::none);
  CHECK(apply_follow_option("elbow", c) == "--follow: must be hand or none (got \"elbow\")");
}
