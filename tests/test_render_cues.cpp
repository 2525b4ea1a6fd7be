// What a frame says about contact, without GL: the ring and drop line under
// each elbow, the landed / lifted states, the elbow's height in the overlay,
// and force arrows scaled to the recording with their scale stated.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/frame_source.hpp"
#include "render/overlay.hpp"
#include "render/playback.hpp"
#include "render/scene.hpp"
#include "support/approx.hpp"
#include "test_render_fixtures.hpp"

using namespace elbowsim;
using Eigen::Vector3d;
using elbowsim::testing::approx;

namespace {

bool same(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

// The fixture's arm with link 0 raised so that the elbow sphere hangs 2 cm
// above the table top (z = -0.03) until t = 0.4 s, then lowered onto it and
// resting from 0.5 s; it lifts off again at t = 0.9 s:
//
//   t < 0.5      O          elbow centre at z = 0.02, d = 0.02
//                :          drop line
//   ======(  )=========     ring at the foot, on the table top
const double kLift = std::asin(0.02 / 0.4);

Recording hovering_recording(double peak_force = 12) {
  Recording rec = render_fixture::recording();
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t r = 0; r < rec.rows(); ++r) {
    const bool down = r >= 5 && r <= 8;
    testing::set(rec, r, L.q(0), r < 5 ? kLift : 0.0);
    testing::set(rec, r, L.elbow_distance(0), r < 5 ? 0.02 : 0.0);
    testing::set(rec, r, L.elbow_resting(0), down ? 1.0 : 0.0);
    testing::set(rec, r, L.elbow_force(0), down ? (r == 7 ? peak_force : 8.0) : 0.0);
  }
  return rec;
}

}  // namespace

TEST_CASE("render cues: a ring on the table under a free elbow and a dashed drop line to it") {
  const Model model = render_fixture::arm();
  const Playback playback(model, hovering_recording());
  const SceneStyle style;
  const Scene free = build_scene(model, playback.at(0.2), {}, SceneOptions{});
  REQUIRE(free.cues.size() == 1);
  const ContactCue& cue = free.cues[0];
  const Vector3d centre = free.elbows[0].sphere.center;
  REQUIRE(centre.z() == doctest::Approx(0.02));
  CHECK(cue.gap == doctest::Approx(0.02));
  CHECK(approx(cue.foot, Vector3d(centre.x(), 0, -0.03), 1e-12));  // on the table top, below
  CHECK(approx(cue.normal, Vector3d(0, 0, 1), 1e-12));
  CHECK(cue.radius == 0.03);
  CHECK(same(cue.color, style.cue_free));
  // Dashes: from the sphere's lowest point down to the foot, every other piece.
  REQUIRE(cue.dashes.size() >= 4);
  CHECK(cue.dashes.size() % 2 == 0);
  CHECK(approx(cue.dashes.front(), centre - Vector3d(0, 0, 0.03), 1e-12));
  CHECK(approx(cue.dashes.back(), cue.foot, 1e-12));
  CHECK(std::abs(cue.dashes[1].z() - cue.dashes[2].z()) > 1e-4);  // a space between dashes

  // Resting: the ring in the state colour, no gap, no drop line.
  const Scene resting = build_scene(model, playback.at(0.75), {}, SceneOptions{});
  REQUIRE(resting.cues.size() == 1);
  CHECK(resting.cues[0].gap == 0);
  CHECK(resting.cues[0].dashes.empty());
  CHECK(same(resting.cues[0].color, style.elbow_resting));
  CHECK(approx(resting.cues[0].foot, Vector3d(0.4, 0, -0.03), 1e-12));
  CHECK(same(build_scene(model, playback.at(0.55), {}, {}).cues[0].color, style.elbow_landed));

  // Beyond cue_range radii (3 x 3 cm) no cue; nor without a recorded distance.
  SceneOptions near;
  near.cue_range = 0.5;  // 1.5 cm < 2 cm
  CHECK(build_scene(model, playback.at(0.2), {}, near).cues.empty());
  PlaybackState unknown = playback.at(0.2);
  unknown.elbows[0].distance.reset();
  CHECK(build_scene(model, unknown, {}, SceneOptions{}).cues.empty());
}

TEST_CASE("render cues: an elbow that leaves the table is 'lifted' for landed_window") {
  const Model model = render_fixture::arm();
  const Playback playback(model, hovering_recording());
  const SceneStyle style;
  // rest_elbow: 1 from t = 0.5 to 0.8, 0 again from t = 0.9 s.
  CHECK(playback.at(0.95).elbows[0].lifted_at == doctest::Approx(0.9));
  auto elbow_at = [&](double t) { return build_scene(model, playback.at(t), {}, {}).elbows[0]; };
  CHECK(elbow_at(0.85).state == ElbowState::resting);
  CHECK(elbow_at(0.95).state == ElbowState::lifted);
  CHECK(same(elbow_at(0.95).sphere.color, style.elbow_lifted));
  CHECK(elbow_at(1.0).state == ElbowState::lifted);  // exactly 0.1 s after
  CHECK(build_scene(model, playback.at(0.95), {}, {}).forces.empty());
  const Playback later(model, hovering_recording());
  CHECK(overlay_lines("x", model, later.at(0.95))[3] == "elbow: lifted, 0.0 mm above the table");
  CHECK(overlay_lines("x", model, later.at(0.2))[3] == "elbow: free, 20.0 mm above the table");
  CHECK(overlay_lines("x", model, later.at(0.55))[3] == "elbow: 8.00 N landed");
}

TEST_CASE(
    "render forces: the automatic scale keeps the largest force within a quarter of the arm") {
  // 1-2-5 newtons per centimetre: max force / (25 cm per m of arm) rounded up.
  CHECK(automatic_force_scale(82, 1.0) == doctest::Approx(0.01 / 5));    // 3.28 N/cm -> 5
  CHECK(automatic_force_scale(22.6, 0.8) == doctest::Approx(0.01 / 2));  // 1.13 -> 2
  CHECK(automatic_force_scale(2, 0.8) == doctest::Approx(0.01 / 0.1));   // 0.1 N/cm
  CHECK(automatic_force_scale(0, 0.8) == 0.01);
  for (double f : {0.3, 7.0, 82.0, 640.0})
    for (double size : {0.3, 0.8, 2.0}) {
      CAPTURE(f);
      CAPTURE(size);
      const double length = f * automatic_force_scale(f, size);
      CHECK(length <= 0.25 * size * (1 + 1e-12));
      CHECK(length > 0.1 * size);  // and not tiny: at most 2.5 x below the quarter
    }

  // An 82 N peak on the fixture's arm (0.75 m across): in the frame, the scale stated.
  const Model model = render_fixture::arm();
  const Recording rec = hovering_recording(82);
  const FrameSource source(model, rec, RenderSettings{}, "fixture");
  CHECK(source.force_scale() == doctest::Approx(0.002));  // 82 N: 16.4 cm
  CHECK(source.overlay(0.7).back() == "force arrows: 5 N per cm");
  const Scene peak = source.scene(0.7);
  REQUIRE(peak.forces.size() == 1);
  CHECK(peak.forces[0].force == doctest::Approx(82));
  const Camera camera = source.camera(16.0 / 9.0);
  const Eigen::Vector2d tip = *camera.project(peak.forces[0].tip, 1280, 720);
  CHECK(tip.x() > 0);
  CHECK(tip.x() < 1280);
  CHECK(tip.y() > 0);
  CHECK(tip.y() < 720);
  // A scene's own scale is kept and stated too.
  RenderSettings fixed;
  fixed.force_scale = 0.004;
  const FrameSource given(model, rec, fixed, "fixture");
  CHECK(given.force_scale() == 0.004);
  CHECK(given.overlay(0.7).back() == "force arrows: 2.5 N per cm");
}

TEST_CASE("render playback: a link without a solid (d_link = +inf by design) keeps every row; "
          "a non-finite angle ends the playback there") {
  const Model model = render_fixture::arm();
  Recording rec = hovering_recording();
  const TrajectoryLayout& L = rec.layout;
  REQUIRE(L.link_distance(1) >= 0);
  for (std::size_t r = 0; r < rec.rows(); ++r)
    testing::set(rec, r, L.link_distance(1), std::numeric_limits<double>::infinity());
  const double end = rec.at(rec.rows() - 1, std::size_t(L.time()));
  CHECK(Playback(model, rec).end_time() == doctest::Approx(end));
  testing::set(rec, 3, L.q(0), std::numeric_limits<double>::quiet_NaN());
  CHECK(Playback(model, rec).end_time() == doctest::Approx(rec.at(2, std::size_t(L.time()))));
}

TEST_CASE("render cues: a resting link's own solid gets a force arrow and an overlay line") {
  // Link 1 (a capsule along +x from (0.4, 0, 0) to (0.75, 0, 0) while q1 = 0, radius
  // 0.015) rests from t = 0.5 to 0.8 s pushed by 5 N: both ends are equally low, so the
  // arrow starts above their middle, on the capsule's top, and points up 5 N long.
  const Model model = render_fixture::arm();
  Recording rec = hovering_recording();
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t r = 0; r < rec.rows(); ++r) {
    testing::set(rec, r, L.link_resting(1), r >= 5 && r <= 8 ? 1.0 : 0.0);
    testing::set(rec, r, L.link_force(1), r >= 5 && r <= 8 ? 5.0 : 0.0);
  }
  const Playback playback(model, rec);
  SceneOptions options;
  options.force_scale = 0.01;
  const Scene resting = build_scene(model, playback.at(0.6), {}, options);
  const Arrow* arrow = nullptr;
  for (const Arrow& a : resting.forces)
    if (a.link == 1) arrow = &a;
  REQUIRE(arrow != nullptr);
  CHECK(arrow->elbow == -1);
  CHECK(arrow->force == 5.0);
  CHECK(approx(arrow->tail, Vector3d(0.575, 0, 0.015), 1e-12));
  CHECK(approx(arrow->tip, Vector3d(0.575, 0, 0.065), 1e-12));
  const std::vector<std::string> lines = overlay_lines("t", model, playback.at(0.6), 0.1);
  CHECK(std::find(lines.begin(), lines.end(), "link1 (not an elbow): 5.00 N resting") != lines.end());
  // Free again at 0.9 s: no arrow for it, no line.
  const Scene free = build_scene(model, playback.at(0.95), {}, options);
  for (const Arrow& a : free.forces) CHECK(a.link != 1);
  for (const std::string& line : overlay_lines("t", model, playback.at(0.95), 0.1))
    CHECK(line.find("link1") == std::string::npos);
  // The arrows' scale counts the link's force too.
  CHECK(playback.max_force() == 12.0);
  testing::set(rec, 6, L.link_force(1), 20.0);
  CHECK(Playback(model, rec).max_force() == 20.0);
}
