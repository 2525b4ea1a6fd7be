// The renderer's GL-free half: playback of a recording, the abstract scene,
// the camera maths, the overlay text, the unit meshes and the render: keys.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "app/scenario/scenario.hpp"
#include "render/camera.hpp"
#include "render/frame_source.hpp"
#include "render/level_of_detail.hpp"
#include "render/meshes.hpp"
#include "render/overlay.hpp"
#include "render/playback.hpp"
#include "render/render_job.hpp"
#include "render/scene.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"
#include "test_render_fixtures.hpp"

using namespace elbowsim;
using Eigen::Vector3d;
using elbowsim::testing::approx;

namespace {

bool same(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

}  // namespace

TEST_CASE(
    "render scene: a known pose gives links, joints and an elbow where kinematics puts them") {
  const Model model = render_fixture::arm();
  const Recording rec = render_fixture::recording();
  const Playback playback(model, rec);
  // At t = 0.2 s: q = (0, pi/2), link 0 along +x, link 1 straight up.
  const PlaybackState state = playback.at(0.2);
  REQUIRE(approx(state.q, Eigen::Vector2d(0, std::numbers::pi / 2), 1e-12));
  const Scene scene = build_scene(model, state, {}, SceneOptions{});

  REQUIRE(scene.links.size() == 2);
  CHECK(approx(scene.links[0].a, Vector3d(0, 0, 0), 1e-12));
  CHECK(approx(scene.links[0].b, Vector3d(0.4, 0, 0), 1e-12));
  CHECK(approx(scene.links[1].a, Vector3d(0.4, 0, 0), 1e-12));
  CHECK(approx(scene.links[1].b, Vector3d(0.4, 0, 0.35), 1e-12));
  CHECK(scene.links[0].radius == 0.02);
  CHECK(scene.links[1].radius == 0.015);
  // Housings centred on the joint origins, along the joint axis (-y).
  REQUIRE(scene.joints.size() == 2);
  CHECK(approx(0.5 * (scene.joints[1].a + scene.joints[1].b), Vector3d(0.4, 0, 0), 1e-12));
  CHECK(approx((scene.joints[1].b - scene.joints[1].a).normalized(), Vector3d(0, -1, 0), 1e-12));
  REQUIRE(scene.elbows.size() == 1);
  CHECK(approx(scene.elbows[0].sphere.center, Vector3d(0.4, 0, 0), 1e-12));
  CHECK(scene.elbows[0].sphere.radius == 0.03);
  REQUIRE(scene.table.size() == 1);
  CHECK(approx(scene.table[0].center, model.table[0].center, 0));
  CHECK(same(scene.table[0].color, SceneStyle{}.table));
  // The base plate sits behind joint 0 (along +y, the side the axis points away from).
  CHECK(scene.base.center.y() > 0);
}

TEST_CASE("render scene: elbow colour follows its contact state; landed means within 0.1 s") {
  const Model model = render_fixture::arm();
  const Playback playback(model, render_fixture::recording());
  const SceneStyle style;
  auto elbow_at = [&](double t) { return build_scene(model, playback.at(t), {}, {}).elbows[0]; };
  // rest_elbow: 0 until t = 0.5, 1 from then on (recorded every 0.1 s).
  CHECK(elbow_at(0.3).state == ElbowState::free);
  CHECK(same(elbow_at(0.3).sphere.color, style.elbow_free));
  CHECK(elbow_at(0.55).state == ElbowState::landed);
  CHECK(same(elbow_at(0.55).sphere.color, style.elbow_landed));
  CHECK(elbow_at(0.6).state == ElbowState::landed);  // exactly 0.1 s after touchdown
  CHECK(elbow_at(0.65).state == ElbowState::resting);
  CHECK(same(elbow_at(0.65).sphere.color, style.elbow_resting));
  CHECK(playback.at(0.55).elbows[0].landed_at == doctest::Approx(0.5));
}

TEST_CASE("render scene: force arrows only at resting elbows, length = fn * force_scale") {
  const Model model = render_fixture::arm();
  const Playback playback(model, render_fixture::recording());
  SceneOptions options;
  CHECK(build_scene(model, playback.at(0.3), {}, options).forces.empty());  // free: none
  for (double scale : {0.01, 0.004}) {
    options.force_scale = scale;
    // fn: 8 N at t = 0.7, 12 N at t = 0.8 -> 10 N at t = 0.75 (linear).
    const Scene scene = build_scene(model, playback.at(0.75), {}, options);
    REQUIRE(scene.forces.size() == 1);
    const Arrow& arrow = scene.forces[0];
    CHECK(arrow.force == doctest::Approx(10.0));
    CHECK((arrow.tip - arrow.tail).norm() == doctest::Approx(10.0 * scale));
    CHECK(approx((arrow.tip - arrow.tail).normalized(), Vector3d(0, 0, 1), 1e-12));  // table up
    const Sphere& s = scene.elbows[0].sphere;
    CHECK(approx(arrow.tail, s.center + Vector3d(0, 0, s.radius), 1e-12));  // on top of the sphere
  }
  options.force_scale = 0;
  CHECK(build_scene(model, playback.at(0.75), {}, options).forces.empty());
}

TEST_CASE("render playback: linear between samples, clamped outside; the hand path up to t") {
  const Model model = render_fixture::arm();
  const Playback playback(model, render_fixture::recording());
  // q1 goes 0 -> pi/2 over 0 .. 0.2 s.
  CHECK(playback.at(0.05).q[1] == doctest::Approx(std::numbers::pi / 8));
  CHECK(playback.at(-1).q[1] == 0);
  CHECK(playback.at(99).t == doctest::Approx(1.0));
  CHECK(*playback.at(0.75).energy_in == doctest::Approx(0.75));
  const std::vector<Vector3d> path = playback.hand_path(0.15);
  REQUIRE(path.size() == 3);  // samples at 0, 0.1 and the point at 0.15
  CHECK(approx(path.back(), *playback.at(0.15).hand, 1e-12));
  CHECK_THROWS_WITH_AS(Playback(render_fixture::arm(3), render_fixture::recording()),
                       doctest::Contains("2 joints, the model 3"), std::invalid_argument);
}

TEST_CASE("render scene: the whole desired hand path in grey, only when hand_d_* is recorded") {
  const Model model = render_fixture::arm();
  const Recording plain = render_fixture::recording();
  // The fixture plus a desired hand position: a straight line from
  // (0.75, 0, 0) at t = 0 to (0.55, 0, 0.1) at t = 1 s (2 cm and 1 cm per row).
  Recording rec = render_fixture::recording(true);
  for (std::size_t r = 0; r < rec.rows(); ++r) {
    testing::set(rec, r, rec.layout.hand_desired(0), 0.75 - 0.02 * double(r));
    testing::set(rec, r, rec.layout.hand_desired(2), 0.01 * double(r));
  }
  const Playback playback(model, rec);
  const SceneOptions options;
  // Mid-run the scene already holds the whole desired path, not only up to t.
  const Scene scene = build_scene(model, playback.at(0.3), playback.hand_path(0.3), options,
                                  playback.desired_hand_path());
  const Polyline& desired = scene.desired_hand_path;
  REQUIRE(desired.points.size() == 11);
  CHECK(approx(desired.points.front(), Vector3d(0.75, 0, 0), 1e-12));
  CHECK(approx(desired.points.back(), Vector3d(0.55, 0, 0.1), 1e-12));
  CHECK(same(desired.color, SceneStyle{}.desired_hand_path));
  CHECK_FALSE(same(desired.color, SceneStyle{}.hand_path));
  CHECK(desired.radius > 0);
  CHECK(desired.radius < scene.hand_path.radius);
  CHECK(scene.hand_path.points.size() == 4);  // the traced path still stops at t
  // The frame source passes it on too.
  const FrameSource source(model, rec, RenderSettings{}, "fixture");
  CHECK(source.scene(0.0).desired_hand_path.points.size() == 11);
  CHECK(source.frame_bounds().contains(Vector3d(0.55, 0, 0.1)));

  // Without hand_d_* columns: no desired path anywhere; the rest unchanged.
  const Playback without(model, plain);
  CHECK(without.desired_hand_path().empty());
  CHECK(build_scene(model, without.at(0.3), without.hand_path(0.3), options,
                    without.desired_hand_path())
            .desired_hand_path.points.empty());
  CHECK(FrameSource(model, plain, RenderSettings{}, "fixture")
            .scene(0.3)
            .desired_hand_path.points.empty());
}

TEST_CASE("render playback: frames by simulation time, duration x fps + 1") {
  CHECK(frame_count(2.0, 30) == 61);
  CHECK(frame_count(0.5, 20) == 11);
  CHECK(frame_count(0.0, 30) == 1);
  const std::vector<double> times = frame_times(1.0, 4);
  REQUIRE(times.size() == 5);
  CHECK(times[1] == 0.25);
  CHECK(times.back() == 1.0);
}

TEST_CASE("render camera: the target projects to the centre; the auto frame fits in the image") {
  Camera c;
  c.eye = Vector3d(1, -2, 1);
  c.target = Vector3d(0.2, 0.1, -0.1);
  const Eigen::Vector2d centre = *c.project(c.target, 160, 120);
  CHECK(centre.x() == doctest::Approx(80));
  CHECK(centre.y() == doctest::Approx(60));
  CHECK_FALSE(c.project(c.eye + (c.eye - c.target), 160, 120).has_value());  // behind
  // Higher in the world is higher in the image (smaller y).
  CHECK(c.project(c.target + Vector3d(0, 0, 0.1), 160, 120)->y() < 60);

  const Eigen::AlignedBox3d frame(Vector3d(-0.2, -0.3, -0.25), Vector3d(0.8, 0.3, 0.4));
  for (CameraPreset preset :
       {CameraPreset::front, CameraPreset::side, CameraPreset::top, CameraPreset::three_quarter}) {
    const std::string name = to_string(preset);
    CAPTURE(name);
    CameraSettings settings;
    settings.preset = preset;
    const Camera cam = make_camera(settings, frame, frame, 16.0 / 9.0);
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector2d p =
          *cam.project(frame.corner(Eigen::AlignedBox3d::CornerType(k)), 1280, 720);
      min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
      min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
    }
    CHECK(min_x >= 0);
    CHECK(max_x <= 1280);
    CHECK(min_y >= 0);
    CHECK(max_y <= 720);
    CHECK(std::max(max_x - min_x, (max_y - min_y) * 16 / 9) > 0.8 * 1280);  // and fills it
    // Everything lies between the clip planes.
    for (int k = 0; k < 8; ++k) {
      const double depth = (frame.corner(Eigen::AlignedBox3d::CornerType(k)) - cam.eye)
                               .dot((cam.target - cam.eye).normalized());
      CHECK(depth > cam.near);
      CHECK(depth < cam.far);
    }
  }
}

TEST_CASE("render frame source: the automatic frame holds the swept arm and the table near it") {
  const Model model = render_fixture::arm();
  const Recording rec = render_fixture::recording();
  const FrameSource source(model, rec, RenderSettings{}, "fixture");
  const Eigen::AlignedBox3d& frame = source.frame_bounds();
  CHECK(frame.contains(Vector3d(0.4, 0, 0.35)));             // link 1 tip when up
  CHECK(frame.contains(Vector3d(0.75, 0, 0)));               // link 1 tip when straight
  CHECK(frame.min().z() <= model.table[0].center.z());       // the table top and some of it
  CHECK(source.scene_options().floor_z == frame.min().z());  // the table's bottom
  CHECK(source.scene(0.5).grid.points.size() > 4);
}

TEST_CASE("render overlay: time, scenario, energy so far and elbow forces") {
  const Model model = render_fixture::arm();
  const Playback playback(model, render_fixture::recording());
  const std::vector<std::string> lines = overlay_lines("elbow_rest", model, playback.at(0.75));
  REQUIRE(lines.size() == 4);
  CHECK(lines[0] == "elbow_rest");
  CHECK(lines[1] == "t = 0.750 s");
  CHECK(lines[2] == "E_in = 0.750 J");
  CHECK(lines[3] == "elbow: 10.00 N resting");
  // Free: its height over the table from the recorded distance (0 in the fixture).
  CHECK(overlay_lines("x", model, playback.at(0.3))[3] == "elbow: free, 0.0 mm above the table");
}

TEST_CASE("render meshes: closed, outward-facing (signed volume) unit shapes") {
  auto volume = [](const Mesh& m) {
    double v = 0;
    auto p = [&](std::uint32_t i) {
      return Vector3d(m.vertices[6 * i], m.vertices[6 * i + 1], m.vertices[6 * i + 2]);
    };
    for (std::size_t k = 0; k < m.indices.size(); k += 3)
      v += p(m.indices[k]).dot(p(m.indices[k + 1]).cross(p(m.indices[k + 2]))) / 6;
    return v;
  };
  // Edges by their ends' positions: in a closed mesh each is used once in
  // each direction; `open` counts those used once (a boundary), `bad` the
  // rest (a hole at a sphere's poles showed here, not in the volume).
  auto edges = [](const Mesh& m, int& open, int& bad) {
    std::map<std::pair<std::array<long, 3>, std::array<long, 3>>, int> uses;
    auto key = [&](std::uint32_t i) {
      std::array<long, 3> k;
      for (int c = 0; c < 3; ++c) k[std::size_t(c)] = std::lround(1e6 * m.vertices[6 * i + c]);
      return k;
    };
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
      for (int e = 0; e < 3; ++e) {
        const auto a = key(m.indices[t + std::size_t(e)]);
        const auto b = key(m.indices[t + std::size_t((e + 1) % 3)]);
        if (a != b) ++uses[{a, b}];
      }
    open = bad = 0;
    for (const auto& [edge, n] : uses) {
      const auto back = uses.find({edge.second, edge.first});
      const int m_back = back == uses.end() ? 0 : back->second;
      if (n == 1 && m_back == 0)
        ++open;
      else if (n != 1 || m_back != 1)
        ++bad;
    }
  };
  int open = 0, bad = 0;
  edges(unit_sphere(24, 12), open, bad);
  CHECK(open == 0);
  CHECK(bad == 0);
  // The dome (a capsule's end): open along its rim only, the 24 edges at z = 0.
  const Mesh dome = unit_dome(24, 6);
  edges(dome, open, bad);
  CHECK(open == 24);
  CHECK(bad == 0);
  for (std::size_t i = 0; i < dome.vertices.size(); i += 6) CHECK(dome.vertices[i + 2] >= -1e-6f);
  const double pi = std::numbers::pi;
  CHECK(volume(unit_box()) == doctest::Approx(1.0));
  CHECK(volume(unit_sphere(64, 32)) == doctest::Approx(4 * pi / 3).epsilon(0.01));
  CHECK(volume(unit_cylinder(64)) == doctest::Approx(pi).epsilon(0.01));
  CHECK(volume(unit_cone(64)) == doctest::Approx(pi / 3).epsilon(0.01));
  CHECK(volume(unit_torus(96, 32, 0.1)) == doctest::Approx(2 * pi * pi * 0.01).epsilon(0.01));
  // The open tube (paths): the cylinder's side only, every vertex on the
  // unit circle at z 0 or 1 with a radial normal; the cylinder adds two caps.
  const Mesh tube = unit_tube(6);
  CHECK(tube.indices.size() == 3 * 2 * 6);
  CHECK(unit_cylinder(6).indices.size() == tube.indices.size() + 3 * 2 * 6);
  for (std::size_t i = 0; i < tube.vertices.size(); i += 6) {
    const float* v = &tube.vertices[i];
    CHECK(std::hypot(v[0], v[1]) == doctest::Approx(1.0));
    CHECK((v[2] == 0.0f || v[2] == 1.0f));
    CHECK(v[3] == doctest::Approx(v[0]));
    CHECK(v[4] == doctest::Approx(v[1]));
    CHECK(v[5] == 0.0f);
  }
  // The square (the inset's ribbons): two faces, each wound counter-clockwise
  // seen from the side its normal points to, so one is drawn from either side.
  const Mesh square = unit_square();
  REQUIRE(square.indices.size() == 3 * 4);
  int up = 0, down = 0;
  for (std::size_t k = 0; k < square.indices.size(); k += 3) {
    auto p = [&](int j) {
      const float* v = &square.vertices[6 * square.indices[k + std::size_t(j)]];
      return Vector3d(v[0], v[1], v[2]);
    };
    const Vector3d n = (p(1) - p(0)).cross(p(2) - p(0));
    const float ny = square.vertices[6 * square.indices[k] + 4];
    CHECK(n.y() * ny > 0);
    (ny > 0 ? up : down) += 1;
    for (int j = 0; j < 3; ++j) CHECK(p(j).cwiseAbs().maxCoeff() == doctest::Approx(0.5));
  }
  CHECK(up == 2);
  CHECK(down == 2);
}

TEST_CASE("render settings: defaults, every key, and errors at file:line:col") {
  const std::string base = render_fixture::scenario_yaml();
  const Scenario plain = load_scenario_text(base, "x.yaml");
  CHECK(plain.render.width == 1280);
  CHECK(plain.render.height == 720);
  CHECK(plain.render.fps == 30);
  CHECK(plain.render.antialiasing == Antialiasing::fxaa);
  CHECK(plain.render.samples() == 1);
  CHECK_FALSE(plain.render.supersample);
  CHECK_FALSE(plain.render.force_scale.has_value());  // automatic
  CHECK(plain.render.shadows);
  CHECK(plain.render.inset.show);
  CHECK(plain.render.inset.view_height == 0);
  CHECK(plain.render.inset.scale_bar == 0);
  CHECK(plain.render.camera.follow == CameraFollow::none);
  CHECK_FALSE(plain.render.camera.explicit_pose);
  CHECK_FALSE(plain.output.video);
  CHECK_FALSE(plain.output.frames);

  const Scenario s = load_scenario_text(base + R"(render:
  camera: {eye: [1, -2, 1], target: [0.3, 0, 0], fov_deg: 30, follow: hand}
  size: [640, 480]
  fps: 25
  msaa: 2
  supersample: true
  force_scale: 0.02
  shadows: false
  inset: {show: false, view_height: 0.04, scale_bar: 0.005}
)",
                                        "x.yaml", {"output.video=true", "output.frames=true"});
  CHECK(s.render.camera.explicit_pose);
  CHECK(s.render.camera.eye == Vector3d(1, -2, 1));
  CHECK(s.render.camera.fov_deg == 30);
  CHECK(s.render.width == 640);
  CHECK(s.render.fps == 25);
  CHECK(s.render.msaa == 2);
  CHECK(s.render.antialiasing == Antialiasing::msaa);  // msaa alone asks for it
  CHECK(s.render.samples() == 2);
  CHECK(s.render.supersample);
  CHECK(s.render.force_scale == 0.02);
  CHECK(s.render.camera.follow == CameraFollow::hand);
  CHECK_FALSE(s.render.shadows);
  CHECK_FALSE(s.render.inset.show);
  CHECK(s.render.inset.view_height == 0.04);
  CHECK(s.render.inset.scale_bar == 0.005);
  CHECK(s.output.video);
  CHECK(s.output.frames);
  CHECK(load_scenario_text(base + "render: {camera: {preset: top}}\n", "x.yaml")
            .render.camera.preset == CameraPreset::top);
  auto aa = [&](const std::string& keys) {
    return load_scenario_text(base + "render: {" + keys + "}\n", "x.yaml").render;
  };
  CHECK(aa("msaa: 1").antialiasing == Antialiasing::none);
  CHECK(aa("antialiasing: msaa").samples() == 4);
  CHECK(aa("antialiasing: fxaa, msaa: 4").samples() == 1);
  CHECK(aa("antialiasing: none").antialiasing == Antialiasing::none);
  CHECK_FALSE(load_scenario_text(base + "render: {force_scale: auto}\n", "x.yaml")
                  .render.force_scale.has_value());

  const int line = render_fixture::scenario_lines() + 1;  // the line of "render:"
  auto error = [&](const std::string& render) {
    try {
      load_scenario_text(base + render, "x.yaml");
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string l = "x.yaml:" + std::to_string(line);
  CHECK(error("render: {msaa: 3}\n") == l + ":16: render.msaa: must be 1 (off), 2 or 4 (got 3)");
  CHECK(error("render: {antialiasing: msaa, msaa: 1}\n") ==
        l + ":36: render.msaa: must be 2 or 4 with antialiasing msaa (got 1)");
  CHECK(error("render: {antialiasing: smaa}\n")
            .find(l + ":24: render.antialiasing: must be one of fxaa, msaa, none") == 0);
  CHECK(error("render: {size: [641, 480]}\n").find(l + ":17: render.size[0]: must be even") == 0);
  CHECK(error("render: {camera: {preset: diagonal}}\n")
            .find("render.camera.preset: must be one of front, side, top, three_quarter") !=
        std::string::npos);
  CHECK(error("render: {camera: {preset: top, eye: [1, 1, 1]}}\n")
            .find("render.camera.eye: give either preset or eye and target") != std::string::npos);
  CHECK(error("render: {camera: {eye: [1, 1, 1]}}\n")
            .find("render.camera.target: required key is missing") != std::string::npos);
  CHECK(error("render: {camera: {eye: [0, 0, 1], target: [0, 0, 0]}}\n")
            .find("render.camera.target: up [0, 0, 1] must not be zero or parallel") !=
        std::string::npos);
  CHECK(error("render: {fps: 0}\n").find("render.fps: must be > 0") != std::string::npos);
  CHECK(error("render: {force_scale: -1}\n").find("render.force_scale: must be >= 0") !=
        std::string::npos);
  CHECK(error("render: {force_scale: big}\n") ==
        l + ":23: render.force_scale: must be auto or a number >= 0 [m/N] (got \"big\")");
  CHECK(error("render: {camera: {follow: elbow}}\n")
            .find("render.camera.follow: must be one of none, hand") != std::string::npos);
  CHECK(
      error("render: {inset: {view_height: 0}}\n").find("render.inset.view_height: must be > 0") !=
      std::string::npos);
  CHECK(error("render: {inset: {shown: true}}\n").find("did you mean \"show\"") !=
        std::string::npos);
  CHECK(error("render: {shadows: 2}\n").find("render.shadows:") != std::string::npos);
  CHECK(error("render: {fsp: 3}\n").find("did you mean \"fps\"") != std::string::npos);
}

TEST_CASE("render level of detail: the fewest slices within half a pixel of round") {
  auto error = [](double radius_px, int level) {
    return radius_px * (1 - std::cos(std::numbers::pi / kSlices[std::size_t(level)]));
  };
  int previous = 0;
  for (double r = 0.5; r < 400; r *= 1.1) {
    CAPTURE(r);
    const int level = detail_level(r);
    CHECK(level >= previous);  // larger on screen: never fewer slices
    previous = level;
    if (level + 1 < int(kSlices.size())) CHECK(error(r, level) <= kOutlineError);
    if (level > 0) CHECK(error(r, level - 1) > kOutlineError);  // and no more than needed
  }
  CHECK(kSlices[std::size_t(detail_level(3))] == 8);     // the inset's hand dot
  CHECK(kSlices[std::size_t(detail_level(17))] == 16);   // a link in the main view
  CHECK(kSlices[std::size_t(detail_level(1e6))] == 48);  // beyond the finest: the finest
  CHECK(kSlices[std::size_t(detail_level(std::nan("")))] == 48);
}
