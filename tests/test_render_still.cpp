// Stills of the paper's experiment (scenarios/elbow_experiment.yaml, run for
// 2 s by the elbowsim binary): the inset shows the desired and traced hand
// paths where its camera projects them, and the elbow-off arm's shadow
// darkens the table under it. Drawn through the same prepare_panel /
// draw_panel as every video frame, read back before the overlay text.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "app/output/trajectory_csv.hpp"
#include "app/scenario/scenario.hpp"
#include "render/frame_source.hpp"
#include "render/gl_renderer.hpp"
#include "render/lighting.hpp"
#include "render/osmesa_context.hpp"
#include "render/render_job.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"
#include "test_render_pixels.hpp"

using namespace elbowsim;
using namespace render_pixels;
using Eigen::Vector3d;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 640, kHeight = 360;

// Both variants run once per test process, 2 s of the 4.8 s, nothing rendered. The
// folder is the process's own (ctest runs each case as a process, two at once under -j),
// removed when the process ends.
struct OwnFolder {
  fs::path path;
  ~OwnFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

const fs::path& experiment() {
  static const OwnFolder dir{[] {
    const fs::path d =
        elbowsim::testing::scratch("render", "experiment_" + std::to_string(::getpid()));
    const std::string scenario =
        std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
    const auto run = elbowsim::testing::shell(
        std::string(ELBOWSIM_BINARY) + " run " + scenario + " --out " + d.string() +
        " --no-report --no-render --set simulation.duration=2");
    if (run.exit_code != 0) throw std::runtime_error("experiment run failed: " + run.output);
    return d;
  }()};
  return dir.path;
}

struct Run {
  Scenario scenario;
  Recording recording;
};

Run load(const std::string& variant) {
  const fs::path folder = experiment() / variant;
  Run run{load_scenario((folder / "scenario.yaml").string()), {}};
  std::ifstream csv(folder / "trajectory.csv", std::ios::binary);
  run.recording = read_trajectory_csv(csv, (folder / "trajectory.csv").string());
  return run;
}

// A prepared panel drawn as every video frame is (without the overlay text,
// which the writer thread adds); boxes lit per vertex where allowed, or all
// per fragment.
Image draw(const PanelFrame& panel, bool flat_faces_per_vertex = true) {
  OsmesaContext context;
  GlRenderer renderer(kWidth, kHeight, 4);
  renderer.set_flat_faces_per_vertex(flat_faces_per_vertex);
  renderer.begin_frame(panel.scene.background);
  draw_panel(renderer, panel, 1);
  Image image{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 4)};
  renderer.end_frame(image.rgba.data());
  return image;
}

// One frame of `source` at t; `panel` gets what was drawn.
Image still(const FrameSource& source, double t, PanelFrame& panel) {
  panel = prepare_panel(source, t, {0, 0, kWidth, kHeight});
  return draw(panel);
}

RenderSettings small(RenderSettings s) {
  s.width = kWidth;
  s.height = kHeight;
  return s;
}

double distance(const Pixel& p, const Color& c) {
  return std::max(
      {std::abs(p.r - 255.0 * c.r), std::abs(p.g - 255.0 * c.g), std::abs(p.b - 255.0 * c.b)});
}

double brightness(const Pixel& p) { return p.r + p.g + p.b; }

}  // namespace

TEST_CASE("render still: the inset shows the desired path ahead of the hand, the traced behind") {
  const Run run = load("elbow_on");
  const FrameSource source(run.scenario.model, run.recording, small(run.scenario.render), "on");
  const double t = 1.2;  // the hand in the middle of its loops
  PanelFrame panel;
  const Image image = still(source, t, panel);
  image.save(fs::temp_directory_path() / "elbowsim_render_still_inset.png");
  REQUIRE(panel.inset);
  const Inset& inset = *panel.inset;
  const PixelRect& r = inset.rect;
  CHECK(inset.magnification > 5);  // the path is magnified, not just repeated

  // Every recorded desired position inside the inset (4 px from its edges),
  // projected by the inset's camera: ahead of the hand (0.15 s or more) the
  // band's colour; behind it the traced line's, drawn over the band.
  const Playback& playback = source.playback();
  const auto& desired = playback.full_desired_hand_path();
  int ahead = 0, ahead_ok = 0, behind = 0, behind_ok = 0;
  for (std::size_t row = 0; row < desired.size(); ++row) {
    const Eigen::Vector2d p = *inset.camera.project(desired[row], r.width, r.height);
    if (p.x() < 4 || p.y() < 4 || p.x() > r.width - 4 || p.y() > r.height - 4) continue;
    const Pixel px = image.at(r.x + p.x(), r.y + p.y());
    const double when = playback.time(row);
    if (when > t + 0.15) {
      ++ahead;
      ahead_ok += distance(px, inset.desired.color) <= 12;
    } else if (when < t - 0.15) {
      ++behind;
      behind_ok += distance(px, inset.traced.color) < distance(px, inset.desired.color);
    }
  }
  INFO("ahead ", ahead_ok, "/", ahead, ", behind ", behind_ok, "/", behind);
  CHECK(ahead >= 20);
  CHECK(behind >= 20);
  CHECK(ahead_ok >= 0.95 * ahead);
  CHECK(behind_ok >= 0.95 * behind);
  // The hand's dot where the hand is.
  const Eigen::Vector2d hand = *inset.camera.project(*playback.at(t).hand, r.width, r.height);
  CHECK(distance(image.at(r.x + hand.x(), r.y + hand.y()), inset.hand.color) <= 12);

  // Outside its rectangle the frame is the same as without the inset.
  RenderSettings plain = small(run.scenario.render);
  plain.inset.show = false;
  const FrameSource without(run.scenario.model, run.recording, plain, "on");
  PanelFrame bare;
  const Image reference = still(without, t, bare);
  int differ = 0, inside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool in = x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
      const Pixel a = image.at(x, y), b = reference.at(x, y);
      const bool same = a.r == b.r && a.g == b.g && a.b == b.b;
      (in ? inside : differ) += !same;
    }
  CHECK(differ == 0);
  CHECK(inside > r.width * r.height / 2);
}

TEST_CASE("render still: the inset's scene is faded toward its background by its fade") {
  const Run run = load("elbow_on");
  const FrameSource source(run.scenario.model, run.recording, small(run.scenario.render), "on");
  PanelFrame panel = prepare_panel(source, 1.2, {0, 0, kWidth, kHeight});
  REQUIRE(panel.inset);
  Inset& inset = *panel.inset;
  // Without its paths, the inset holds only its background and the faded scene.
  inset.desired.pieces.clear();
  inset.traced.pieces.clear();
  inset.hand.radius = 0;
  const Image image = draw(panel);
  image.save(fs::temp_directory_path() / "elbowsim_render_still_faded.png");
  // A lit colour c in [0, 1] mixed `fade` toward the background b is
  // (1 - fade)(c - b) from it: at most (1 - fade) 255 per channel, plus 1 for
  // rounding. The forearm above the hand fills much of the window (the
  // inset's clip planes leave the table out): it shows, 4 levels or more from
  // the background.
  const PixelRect& r = inset.rect;
  const double bound = (1.0 - inset.fade) * 255.0 + 1.0;
  int within = 0, shown = 0;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const double d = distance(image.at(x, y), inset.background);
      within += d <= bound;
      shown += d >= 4;
    }
  const int pixels = r.width * r.height;
  INFO("within ", within, ", shown ", shown, " of ", pixels, " (bound ", bound, ")");
  CHECK(inset.fade > 0.5f);
  CHECK(within == pixels);
  CHECK(shown > pixels / 4);
}

TEST_CASE(
    "render still: boxes lit per vertex where no highlight shows, within a level of per fragment") {
  // The experiment's table and base from every preset, the table in
  // shadow: from the top the table shows a highlight (drawn per fragment
  // then), from the others it does not. A box lit per vertex under a
  // highlight differs by tens of levels.
  const Run run = load("elbow_off");
  for (const CameraPreset preset :
       {CameraPreset::three_quarter, CameraPreset::top, CameraPreset::front, CameraPreset::side}) {
    INFO("preset ", std::string(to_string(preset)));
    RenderSettings settings = small(run.scenario.render);
    settings.camera.preset = preset;
    settings.inset.show = false;
    const FrameSource source(run.scenario.model, run.recording, settings, "off");
    const PanelFrame panel = prepare_panel(source, 1.0, {0, 0, kWidth, kHeight});
    const Image fast = draw(panel), reference = draw(panel, false);
    int most = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const Pixel a = fast.at(x, y), b = reference.at(x, y);
        most = std::max({most, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
      }
    INFO("largest difference ", most);
    CHECK(most <= 1);
  }
}

TEST_CASE("render still: a shadow darkens the table under the elbow-off arm") {
  const Run run = load("elbow_off");
  RenderSettings settings = small(run.scenario.render);
  settings.inset.show = false;  // the whole table in view
  const FrameSource lit(run.scenario.model, run.recording, settings, "off");
  settings.shadows = false;
  const FrameSource flat(run.scenario.model, run.recording, settings, "off");
  const double t = 1.0;
  PanelFrame panel, flat_panel;
  const Image on = still(lit, t, panel), off = still(flat, t, flat_panel);
  on.save(fs::temp_directory_path() / "elbowsim_render_still_shadow.png");
  off.save(fs::temp_directory_path() / "elbowsim_render_still_no_shadow.png");

  // Where the key light's rays through the forearm (link 2) and through the
  // elbow sphere meet the table top, as the camera sees it.
  const Model& model = run.scenario.model;
  const double top = model.table[0].center.z() + 0.5 * model.table[0].size.z();
  const Vector3d key = view_lighting(panel.camera).key;
  auto on_table = [&](const Vector3d& p) { return Vector3d(p - key * (p.z() - top) / key.z()); };
  std::vector<Vector3d> under;
  const Capsule& forearm = panel.scene.links[2];
  for (double s : {0.3, 0.5, 0.7})
    under.push_back(on_table(forearm.a + s * (forearm.b - forearm.a)));
  // The sphere's shadow is centred where its centre's ray lands; half a
  // radius further along the light, clear of the contact cue's ring.
  const Sphere& elbow = panel.scene.elbows[0].sphere;
  REQUIRE(panel.scene.elbows[0].state == ElbowState::free);
  const Vector3d centre = on_table(elbow.center), foot = panel.scene.cues.at(0).foot;
  under.push_back(centre + 0.5 * elbow.radius * (centre - foot).normalized());
  for (const Vector3d& q : under) {
    const Eigen::Vector2d p = *panel.camera.project(q, kWidth, kHeight);
    const Pixel a = on.at(p.x(), p.y()), b = off.at(p.x(), p.y());
    INFO("at ", q.transpose(), " px ", p.transpose(), ": ", show(a), " with, ", show(b),
         " without shadows");
    CHECK(looks_like(b, SceneStyle{}.table));  // the table is what is seen there
    CHECK(brightness(a) < 0.7 * brightness(b));
  }
  // Away from the arm the table is as bright as without shadows.
  const Eigen::Vector2d far = *panel.camera.project(Vector3d(0.95, -0.25, top), kWidth, kHeight);
  CHECK(std::abs(brightness(on.at(far.x(), far.y())) - brightness(off.at(far.x(), far.y()))) <= 3);
  CHECK(looks_like(off.at(far.x(), far.y()), SceneStyle{}.table));
}

TEST_CASE("render still: the same frame twice gives the same bytes") {
  const Run run = load("elbow_off");
  const FrameSource source(run.scenario.model, run.recording, small(run.scenario.render), "off");
  PanelFrame a, b;
  CHECK(still(source, 1.5, a).rgba == still(source, 1.5, b).rgba);
}
