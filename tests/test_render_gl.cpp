// The renderer with GL (OSMesa): small frames checked pixel by pixel against
// the camera's projection, and the video / frames outputs of the command line
// (run as a process; ffprobe checks the mp4).
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "render/frame_source.hpp"
#include "render/gl_renderer.hpp"
#include "render/osmesa_context.hpp"
#include "render/png_writer.hpp"
#include "render/render_job.hpp"
#include "render/scene.hpp"
#include "render/video_encoder.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"
#include "test_render_fixtures.hpp"
#include "test_render_pixels.hpp"

using namespace elbowsim;
using namespace render_pixels;
using Eigen::Vector3d;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 160, kHeight = 120;

Camera test_camera(double aspect) {
  Camera c;
  c.eye = Vector3d(0.4, -0.9, 0.2);
  c.target = Vector3d(0.4, 0, 0.1);
  c.fov_deg = 30;
  c.aspect = aspect;
  c.near = 0.1;
  c.far = 5;
  return c;
}

using elbowsim::testing::Outcome;
using elbowsim::testing::scratch;
using elbowsim::testing::shell;

Outcome cli(const std::string& arguments) {
  return shell(std::string(ELBOWSIM_BINARY) + " " + arguments);
}

const std::string kElbowRest = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_rest.yaml";

// A short elbow_rest run, 0.5 s, rendered at 160x120 and 20 fps as asked.
std::string short_run(const fs::path& dir, const std::string& outputs) {
  return "run " + kElbowRest + " --out " + dir.string() +
         " --set simulation.duration=0.5 --set 'render.size=[160, 120]' --set render.fps=20 " +
         outputs;
}

}  // namespace

TEST_CASE("render gl: a 160x120 frame has the table, the link and the background where projected") {
  const Model model = render_fixture::arm();
  const Playback playback(model, render_fixture::recording());
  const Scene scene = build_scene(model, playback.at(0.2), {}, SceneOptions{});  // link 1 up
  const SceneStyle style;
  for (int msaa : {4, 1}) {
    CAPTURE(msaa);
    OsmesaContext context;
    GlRenderer renderer(kWidth, kHeight, msaa);
    CHECK(renderer.samples() == msaa);
    const Camera camera = test_camera(double(kWidth) / kHeight);
    renderer.begin_frame(scene.background);
    renderer.draw(scene, camera, {0, 0, kWidth, kHeight});
    Image image{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 4)};
    renderer.end_frame(image.rgba.data());
    image.save(fs::temp_directory_path() /
               ("elbowsim_render_gl_msaa" + std::to_string(msaa) + ".png"));

    const Eigen::Vector2d table = *camera.project(Vector3d(0.15, -0.15, -0.03), kWidth, kHeight);
    const Eigen::Vector2d link = *camera.project(Vector3d(0.4, 0, 0.2), kWidth, kHeight);
    const Eigen::Vector2d elbow = *camera.project(Vector3d(0.4, -0.015, -0.01), kWidth, kHeight);
    INFO("table ", show(image.at(table.x(), table.y())), " link ",
         show(image.at(link.x(), link.y())), " elbow ", show(image.at(elbow.x(), elbow.y())));
    CHECK(looks_like(image.at(table.x(), table.y()), style.table));
    CHECK(looks_like(image.at(link.x(), link.y()), style.link));
    CHECK(looks_like(image.at(elbow.x(), elbow.y()), style.elbow_free));
    CHECK_FALSE(looks_like(image.at(link.x(), link.y()), style.table));
    CHECK(is_background(image.at(3, 3), style.background));
    CHECK(is_background(image.at(kWidth - 4, 3), style.background));
  }
}

TEST_CASE("render gl: two runs side by side, one panel each") {
  const Model model = render_fixture::arm();
  const Playback playback(model, render_fixture::recording());
  const SceneStyle style;
  // Left: t = 0.3 s, the elbow free (grey); right: t = 0.8 s, resting (green).
  const Scene left = build_scene(model, playback.at(0.3), {}, SceneOptions{});
  const Scene right = build_scene(model, playback.at(0.8), {}, SceneOptions{});
  OsmesaContext context;
  GlRenderer renderer(kWidth, kHeight, 4);
  const int half = kWidth / 2;
  const Camera camera = test_camera(double(half) / kHeight);
  renderer.begin_frame(left.background);
  renderer.draw(left, camera, {0, 0, half, kHeight});
  renderer.draw(right, camera, {half, 0, half, kHeight});
  Image image{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 4)};
  renderer.end_frame(image.rgba.data());
  image.save(fs::temp_directory_path() / "elbowsim_render_gl_panels.png");
  const Eigen::Vector2d elbow = *camera.project(Vector3d(0.4, -0.015, -0.01), half, kHeight);
  const Pixel l = image.at(elbow.x(), elbow.y()), r = image.at(elbow.x() + half, elbow.y());
  INFO("left ", show(l), " right ", show(r));
  CHECK(looks_like(l, style.elbow_free));
  CHECK(looks_like(r, style.elbow_resting));
}

TEST_CASE("render video: run writes an H.264 yuv420p mp4 of duration x fps frames") {
  REQUIRE_MESSAGE(shell("command -v ffprobe").exit_code == 0,
                  "ffprobe (package ffmpeg) is needed on PATH");
  const fs::path dir = scratch("render", "video");
  const Outcome run = cli(short_run(dir, "--set output.video=true"));
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(run.output.find("video: " + (dir / "video.mp4").string()) != std::string::npos);
  // The line gives the video's length (11 frames at 20 fps play 0.55 s), and
  // the time rendering took labelled apart.
  CHECK(run.output.find("video: " + (dir / "video.mp4").string() +
                        " (0.55 s long: 11 frames at 20 fps, 160x120, FXAA; rendered in ") !=
        std::string::npos);
  REQUIRE(fs::exists(dir / "video.mp4"));
  CHECK_FALSE(fs::exists(dir / "frames"));
  for (const auto& entry : fs::directory_iterator(dir))
    CHECK(entry.path().filename().string().find("tmp") == std::string::npos);
  const Outcome probe = shell(
      "ffprobe"
      " -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,pix_fmt,width,height,nb_read_frames -of csv=p=0 " +
      (dir / "video.mp4").string());
  REQUIRE(probe.exit_code == 0);
  // 0.5 s x 20 fps: frames at 0, 0.05, ..., 0.5 s.
  CHECK(probe.output == "h264,160,120,yuv420p,11\n");

  SUBCASE("render re-renders a run folder at another size and rate without simulating") {
    const Outcome again = cli("render " + dir.string() + " --size 96x64 --fps 10 --camera top");
    INFO(again.output);
    REQUIRE(again.exit_code == 0);
    const Outcome reprobe = shell(std::string("ffprobe") +
                                  " -v error -select_streams v:0 -count_frames -show_entries "
                                  "stream=codec_name,pix_fmt,width,height,nb_read_frames -of "
                                  "csv=p=0 " +
                                  (dir / "video.mp4").string());
    CHECK(reprobe.output == "h264,96,64,yuv420p,6\n");
    CHECK(again.output.find(" (0.6 s long: 6 frames at 10 fps, 96x64, ") != std::string::npos);
  }
  SUBCASE("render --camera with a pose and a field of view, --follow hand") {
    const Outcome close =
        cli("render " + dir.string() +
            " --size 96x64 --fps 10 --camera eye=0.2,-0.6,0.1,target=0.2,0,0,fov=15"
            " --follow hand");
    INFO(close.output);
    REQUIRE(close.exit_code == 0);
    CHECK(close.output.find("video: " + (dir / "video.mp4").string()) != std::string::npos);
  }
}

TEST_CASE("render frames: output.frames writes numbered PNGs; --no-render writes none") {
  const fs::path dir = scratch("render", "frames");
  // Supersampled: drawn at 320x240, averaged down to 160x120.
  const Outcome run = cli(short_run(dir, "--set output.frames=true --set render.supersample=true"));
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "video.mp4"));
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir / "frames")) {
    (void)entry;
    ++count;
  }
  CHECK(count == 11);
  int w = 0, h = 0;
  read_png(dir / "frames" / "frame_00011.png", w, h);
  CHECK(w == 160);
  CHECK(h == 120);

  const fs::path none = scratch("render", "no_render");
  const Outcome skipped =
      cli(short_run(none, "--set output.video=true --set output.frames=true --no-render"));
  CHECK(skipped.exit_code == 0);
  CHECK(fs::exists(none / "trajectory.csv"));
  CHECK_FALSE(fs::exists(none / "video.mp4"));
  CHECK_FALSE(fs::exists(none / "frames"));
}

// Whether `elbowsim ARGUMENTS` loads `library`: the dynamic loader names
// every library it loads under LD_DEBUG=libs.
bool loads(const std::string& arguments, const std::string& library) {
  const Outcome out = shell("LD_DEBUG=libs " + std::string(ELBOWSIM_BINARY) + " " + arguments);
  INFO(arguments, "\n", out.output.substr(0, 2000));
  REQUIRE(out.exit_code == 0);
  return out.output.find(library) != std::string::npos;
}

TEST_CASE("FFmpeg's libraries are loaded only by a render that makes a video") {
  CHECK_FALSE(loads("--version", "libavformat"));
  const fs::path dir = scratch("render", "lazy_libav");
  CHECK_FALSE(loads(short_run(dir, "--set output.frames=true --no-report"), "libavformat"));
  CHECK(loads(short_run(dir, "--set output.video=true --no-report"), "libavformat"));
}

TEST_CASE("OSMesa (and the LLVM it loads) is loaded only by a run that renders") {
  auto loads_osmesa = [](const std::string& arguments) { return loads(arguments, "libOSMesa"); };
  CHECK_FALSE(loads_osmesa("--version"));
  CHECK_FALSE(loads_osmesa("validate " + kElbowRest));
  const fs::path dir = scratch("render", "lazy_osmesa");
  CHECK_FALSE(loads_osmesa(short_run(dir, "--no-render --no-report")));
  CHECK(loads_osmesa(short_run(dir, "--set output.frames=true --no-report")));  // it does render
}

TEST_CASE("render without FFmpeg's libraries: PNG frames and the command that makes the video") {
  const fs::path dir = scratch("render", "no_libav");
  REQUIRE(cli(short_run(dir, "")).exit_code == 0);
  const fs::path missing = scratch("render", "no_libav_here") / "libavformat.so.59";
  const Outcome out = shell("ELBOWSIM_LIBAVFORMAT=" + missing.string() + " " + ELBOWSIM_BINARY +
                            " render " + dir.string() + " --fps 10");
  INFO(out.output);
  CHECK(out.exit_code == 0);
  CHECK(out.output.find("warning: no video was made: cannot load FFmpeg's " + missing.string()) !=
        std::string::npos);
  CHECK(out.output.find("apt-get install libavformat") != std::string::npos);
  CHECK(out.output.find("wrote 6 PNG frames to " + (dir / "frames").string()) != std::string::npos);
  CHECK(out.output.find("`elbowsim render " + dir.string() + "` makes the video") !=
        std::string::npos);
  CHECK(out.output.find("ffmpeg -framerate 10 -i '" + (dir / "frames" / "frame_%05d.png").string() +
                        "' -c:v libx264") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "video.mp4"));
  CHECK(fs::exists(dir / "frames" / "frame_00001.png"));
  CHECK(fs::exists(dir / "frames" / "frame_00006.png"));
  CHECK_FALSE(fs::exists(dir / "frames" / "frame_00007.png"));
}

TEST_CASE("render with a libavformat of another major version: refused by name, PNG frames") {
  const fs::path dir = scratch("render", "libav_version");
  REQUIRE(cli(short_run(dir, "")).exit_code == 0);
  const Outcome out = shell(std::string("ELBOWSIM_LIBAVFORMAT=") + ELBOWSIM_FAKE_LIBAVFORMAT + " " +
                            ELBOWSIM_BINARY + " render " + dir.string() + " --fps 10");
  INFO(out.output);
  CHECK(out.exit_code == 0);
  CHECK(out.output.find("avformat_version gives major version 1, elbowsim was built for ") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(dir / "video.mp4"));
  CHECK(fs::exists(dir / "frames" / "frame_00006.png"));
}

TEST_CASE("render: a bad run folder is exit 2 with a clear message, and nothing is written") {
  const Outcome missing = cli("render /nonexistent/run");
  CHECK(missing.exit_code == 2);
  CHECK(missing.output.find("error: /nonexistent/run: not a run folder") != std::string::npos);

  const fs::path dir = scratch("render", "bad_dir");
  std::ofstream(dir / "scenario.yaml") << render_fixture::scenario_yaml();
  const Outcome no_csv = cli("render " + dir.string());
  CHECK(no_csv.exit_code == 2);
  CHECK(no_csv.output.find("no trajectory.csv") != std::string::npos);
  std::ofstream(dir / "trajectory.csv") << "time [s],q0 [rad]\n0,0\n";
  const Outcome short_csv = cli("render " + dir.string());
  CHECK(short_csv.exit_code == 2);
  CHECK(short_csv.output.find(
            "trajectory.csv:1: trajectory column 3 is missing: expected 'qd0 [rad/s]'") !=
        std::string::npos);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) (void)entry, ++files;
  CHECK(files == 2);

  const fs::path ok = scratch("render", "bad_option");
  REQUIRE(cli(short_run(ok, "")).exit_code == 0);
  const Outcome size = cli("render " + ok.string() + " --size 161x120");
  CHECK(size.exit_code == 2);
  CHECK(size.output.find("--size: width and height must be even") != std::string::npos);
  CHECK(cli("render " + ok.string() + " --camera diagonal").exit_code == 2);
  const Outcome pose = cli("render " + ok.string() + " --camera eye=1,1,target=0,0,0");
  CHECK(pose.exit_code == 2);
  CHECK(pose.output.find("error: --camera: eye needs 3 numbers x,y,z [m] (got 2)") !=
        std::string::npos);
  const Outcome follow = cli("render " + ok.string() + " --follow elbow");
  CHECK(follow.exit_code == 2);
  CHECK(follow.output.find("error: --follow: must be hand or none (got \"elbow\")") !=
        std::string::npos);
  CHECK(cli("render " + ok.string() + " --fps 0").exit_code == 2);
  CHECK_FALSE(fs::exists(ok / "video.mp4"));
}

TEST_CASE(
    "render with a video that cannot be written: exit 1 with the reason, nothing left behind") {
  const fs::path dir = scratch("render", "unwritable_video");
  REQUIRE(cli(short_run(dir, "")).exit_code == 0);
  auto listing = [&] {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
    return names;
  };
  // The video's temporary file cannot be made: an (empty) folder holds its
  // name, as a stale temporary of ours; it goes with the failed render.
  const std::set<std::string> before = listing();
  fs::create_directory(dir / "video.tmp.mp4");
  const Outcome out = cli("render " + dir.string());
  INFO(out.output);
  CHECK(out.exit_code == 1);
  CHECK(out.output.find("cannot write " + (dir / "video.tmp.mp4").string() + ": Is a directory") !=
        std::string::npos);
  CHECK(listing() == before);
}
