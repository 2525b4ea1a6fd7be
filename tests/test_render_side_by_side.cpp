// The variants' side-by-side comparison and runs drawn at once (render_jobs):
// the side-by-side's frames are the runs' own frames placed side by side,
// pixel for pixel (PNG frames, and the frames given to the H.264 encoder, as
// a lossless video decodes them), and runs drawn
// on several threads give the same bytes as runs drawn on one.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "render/frame_source.hpp"
#include "render/png_writer.hpp"
#include "render/render_job.hpp"
#include "render/yuv.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"
#include "test_render_fixtures.hpp"

using namespace elbowsim;
namespace fs = std::filesystem;
using elbowsim::testing::Outcome;
using elbowsim::testing::scratch;
using elbowsim::testing::shell;

namespace {

constexpr int kWidth = 160, kHeight = 120;

const std::string kExperiment =
    std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";

// The experiment cut to 0.4 s, drawn at 160x96 and 10 fps: 5 frames per
// variant; two of its three arms (resting, held up), two panels.
std::string short_experiment(const fs::path& out, const std::string& more) {
  return std::string(ELBOWSIM_BINARY) + " run " + kExperiment + " --out " + out.string() +
         " --set simulation.duration=0.4 --set 'render.size=[160, 96]' --set render.fps=10"
         " --set 'variants={elbow_on: {}, elbow_off: {task.elbow_clearance: 0.02}}' " + more;
}

// A frame sequence's PNGs, read back.
std::vector<std::vector<std::uint8_t>> read_frames(const fs::path& folder, int& w, int& h) {
  std::vector<std::vector<std::uint8_t>> frames;
  for (int k = 0; fs::exists(folder / frame_file_name(k)); ++k)
    frames.push_back(read_png(folder / frame_file_name(k), w, h));
  return frames;
}

// Left and right RGB images (same height) placed side by side.
std::vector<std::uint8_t> side_by_side(const std::vector<std::uint8_t>& left, int lw,
                                       const std::vector<std::uint8_t>& right, int rw, int h) {
  std::vector<std::uint8_t> out;
  for (int y = 0; y < h; ++y) {
    out.insert(out.end(), left.begin() + std::ptrdiff_t(y) * lw * 3,
               left.begin() + std::ptrdiff_t(y + 1) * lw * 3);
    out.insert(out.end(), right.begin() + std::ptrdiff_t(y) * rw * 3,
               right.begin() + std::ptrdiff_t(y + 1) * rw * 3);
  }
  return out;
}

// Every file under `dir`, by path relative to it, with its bytes.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), dir).string()] = elbowsim::testing::slurp(entry.path());
  return files;
}

// The names of the files that differ between two listings (or are in one only).
std::vector<std::string> differing(const std::map<std::string, std::string>& a,
                                   const std::map<std::string, std::string>& b) {
  std::vector<std::string> names;
  for (const auto& [name, bytes] : a) {
    const auto other = b.find(name);
    if (other == b.end() || other->second != bytes) names.push_back(name);
  }
  for (const auto& [name, bytes] : b)
    if (!a.count(name)) names.push_back(name);
  return names;
}

// A lossless video's frames, decoded by the ffmpeg program: the YUV 4:2:0
// the encoder was given, frame after frame.
std::string decoded_yuv(const fs::path& video) {
  const fs::path raw = fs::path(video.string() + ".yuv");
  const Outcome decode = shell("ffmpeg -v error -y -i '" + video.string() +
                               "' -f rawvideo -pix_fmt yuv420p '" + raw.string() + "'");
  INFO(decode.output);
  REQUIRE_MESSAGE(decode.exit_code == 0, "the ffmpeg program (package ffmpeg) decodes the videos");
  std::string bytes = elbowsim::testing::slurp(raw);
  fs::remove(raw);
  return bytes;
}

// Two YUV 4:2:0 frame sequences of width w each, placed side by side: each
// plane's rows joined (the panels' widths are even, so their chroma samples
// do not straddle the seam).
std::string yuv_side_by_side(const std::string& left, const std::string& right, int w, int h) {
  const std::size_t frame = yuv420_bytes(w, h);
  std::string out;
  for (std::size_t f = 0; f + frame <= left.size(); f += frame) {
    std::size_t plane = f;
    for (const auto& [pw, ph] :
         {std::pair{w, h}, std::pair{w / 2, h / 2}, std::pair{w / 2, h / 2}}) {
      for (int y = 0; y < ph; ++y) {
        out += left.substr(plane + std::size_t(y * pw), std::size_t(pw));
        out += right.substr(plane + std::size_t(y * pw), std::size_t(pw));
      }
      plane += std::size_t(pw * ph);
    }
  }
  return out;
}

// A panel of the side-by-side tests: `width` wide, kHeight high, 5 frames per second.
RenderSettings panel_settings(int width) {
  RenderSettings settings;
  settings.width = width;
  settings.height = kHeight;
  settings.fps = 5;
  return settings;
}

}  // namespace

TEST_CASE("render side by side: its frames are the runs' own frames placed side by side") {
  // Left: the fixture's 1 s; right: its first 0.6 s (so it ends first and
  // its last frame stays), another width and title.
  const Model model = render_fixture::arm();
  const Recording full = render_fixture::recording();
  Recording cut = full;
  cut.values.resize(7 * std::size_t(cut.layout.size()));
  const RenderSettings settings = panel_settings(kWidth), narrow = panel_settings(120);
  const FrameSource left(model, full, settings, "left");
  const FrameSource right(model, cut, narrow, "right");
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    const fs::path dir = scratch("render", "side_by_side_" + std::to_string(threads));
    for (const char* sub : {"left", "right", "both"}) fs::create_directories(dir / sub);
    const RenderResults results = render_jobs({{&left, settings, {dir / "left", false, true}},
                                               {&right, narrow, {dir / "right", false, true}}},
                                              RenderRequest{dir / "both", false, true}, threads);
    REQUIRE(results.side_by_side);
    CHECK(results.jobs[0].error == "");
    CHECK(results.side_by_side->error == "");
    CHECK(results.jobs[0].frames == 6);  // 1 s at 5 fps
    CHECK(results.jobs[1].frames == 4);  // 0.6 s
    CHECK(results.side_by_side->frames == 6);
    CHECK(results.side_by_side->width == kWidth + 120);
    int lw = 0, rw = 0, bw = 0, h = 0;
    const auto l = read_frames(dir / "left" / "frames", lw, h);
    const auto r = read_frames(dir / "right" / "frames", rw, h);
    const auto b = read_frames(dir / "both" / "frames", bw, h);
    REQUIRE(l.size() == 6);
    REQUIRE(r.size() == 4);
    REQUIRE(b.size() == 6);
    REQUIRE(bw == lw + rw);
    for (std::size_t k = 0; k < b.size(); ++k) {
      CAPTURE(k);
      // Pixel for pixel; the right run's last frame stays once it has ended.
      CHECK(b[k] == side_by_side(l[k], lw, r[std::min(k, r.size() - 1)], rw, h));
    }
    CHECK(l[1] != l[3]);  // the frames do differ from each other
  }
}

TEST_CASE("run with variants: compare/frames are the variants' frames side by side") {
  const fs::path dir = scratch("render", "variants_side_by_side");
  const Outcome run =
      shell(short_experiment(dir, "--set output.frames=true --set output.video=false"));
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  int w = 0, h = 0, cw = 0;
  const auto on = read_frames(dir / "elbow_on" / "frames", w, h);
  const auto off = read_frames(dir / "elbow_off" / "frames", w, h);
  const auto both = read_frames(dir / "compare" / "frames", cw, h);
  REQUIRE(on.size() == 5);
  REQUIRE(off.size() == 5);
  REQUIRE(both.size() == 5);
  CHECK(cw == 2 * w);
  for (std::size_t k = 0; k < both.size(); ++k) {
    CAPTURE(k);
    CHECK(both[k] == side_by_side(on[k], w, off[k], w, h));
  }
  CHECK(on[4] != off[4]);
  CHECK_FALSE(fs::exists(dir / "compare" / "video.mp4"));
}

TEST_CASE(
    "run with variants: the frames compare/'s encoder is given are the variants' side by side") {
  // Lossless videos: each decodes to the YUV 4:2:0 frames its encoder was given.
  const fs::path dir = scratch("render", "variants_encoded");
  const Outcome run = shell(short_experiment(dir, "--set output.lossless_video=true"));
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const std::string on = decoded_yuv(dir / "elbow_on" / "video.mp4");
  const std::string off = decoded_yuv(dir / "elbow_off" / "video.mp4");
  const std::string both = decoded_yuv(dir / "compare" / "video.mp4");
  REQUIRE(on.size() == 5 * yuv420_bytes(160, 96));
  REQUIRE(off.size() == on.size());
  CHECK(on != off);
  REQUIRE(both.size() == 2 * on.size());
  CHECK(both == yuv_side_by_side(on, off, 160, 96));
}

TEST_CASE("render side by side: panels without a video, its encoded frames are their YUV") {
  // The panels write PNG frames only, the side-by-side a lossless video and
  // PNG frames: it converts the panels itself, and what it encodes is the
  // YUV of its own PNG frames, also after the right run has ended (its last
  // frame carried over from one composed frame to the next).
  const Model model = render_fixture::arm();
  const Recording recording = render_fixture::recording();
  Recording cut = recording;
  cut.values.resize(7 * std::size_t(cut.layout.size()));
  const RenderSettings settings = panel_settings(kWidth), narrow = panel_settings(120);
  const FrameSource left(model, recording, settings, "left");
  const FrameSource right(model, cut, narrow, "right");
  const fs::path dir = scratch("render", "side_by_side_own_yuv");
  for (const char* sub : {"left", "right", "both"}) fs::create_directories(dir / sub);
  const RenderResults results = render_jobs({{&left, settings, {dir / "left", false, true}},
                                             {&right, narrow, {dir / "right", false, true}}},
                                            RenderRequest{dir / "both", true, true, true}, 2);
  REQUIRE(results.side_by_side);
  CHECK(results.side_by_side->error == "");
  CHECK(results.jobs[1].frames == 4);  // ended two frames before the left run
  int w = 0, h = 0;
  const auto frames = read_frames(dir / "both" / "frames", w, h);
  REQUIRE(frames.size() == 6);
  REQUIRE(w == kWidth + 120);
  std::string expected;
  std::vector<std::uint8_t> yuv(yuv420_bytes(w, h)), rgba(std::size_t(w) * std::size_t(h) * 4);
  for (const auto& rgb : frames) {
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i)
      std::copy_n(rgb.begin() + std::ptrdiff_t(3 * i), 3, rgba.begin() + std::ptrdiff_t(4 * i));
    rgba_to_yuv420(top_down(rgba.data(), w, h), yuv.data());
    expected.append(yuv.begin(), yuv.end());
  }
  CHECK(decoded_yuv(dir / "both" / "video.mp4") == expected);
}

TEST_CASE("render_jobs: a stop raised mid-render keeps nothing of the renders nor their side-by-side") {
  // Two runs of 6 frames each (1 s at 5 fps), videos and frames, side by
  // side. The progress callback raises the stop once a quarter of the 12
  // frames are drawn, before either run can have drawn its 6 (as a signal
  // handler would raise it).
  const Model model = render_fixture::arm();
  const Recording full = render_fixture::recording();
  const RenderSettings settings = panel_settings(kWidth);
  const FrameSource left(model, full, settings, "left"), right(model, full, settings, "right");
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    const fs::path dir = scratch("render", "stopped_" + std::to_string(threads));
    for (const char* sub : {"left", "right", "both"}) fs::create_directories(dir / sub);
    std::atomic<bool> stop{false};
    std::vector<double> shares;
    const RenderControl control{&stop, [&](double share) {
                                  shares.push_back(share);
                                  if (share >= 0.25) stop = true;
                                }};
    const RenderResults results = render_jobs({{&left, settings, {dir / "left", true, true}},
                                               {&right, settings, {dir / "right", true, true}}},
                                              RenderRequest{dir / "both", true, true}, threads,
                                              control);
    for (const RenderStats& stats : results.jobs) {
      CHECK(stats.interrupted);
      CHECK_FALSE(stats.error.empty());
      CHECK(stats.frames == 0);
      CHECK_FALSE(stats.video_written);
      CHECK_FALSE(stats.frames_written);
    }
    REQUIRE(results.side_by_side);
    CHECK(results.side_by_side->interrupted);
    CHECK(files_under(dir).empty());  // no video, no frames, no temporary left
    REQUIRE_FALSE(shares.empty());
    CHECK(shares.back() < 1.0);
    CHECK(std::is_sorted(shares.begin(), shares.end()));
  }
  // Not stopped: the progress rises to 1, every frame once.
  const fs::path dir = scratch("render", "progress");
  std::vector<double> shares;
  const RenderResults results =
      render_jobs({{&left, settings, {dir, false, true}}}, std::nullopt, 1,
                  RenderControl{nullptr, [&](double share) { shares.push_back(share); }});
  CHECK(results.jobs[0].frames == 6);
  CHECK(shares == std::vector<double>{1 / 6.0, 2 / 6.0, 3 / 6.0, 4 / 6.0, 5 / 6.0, 1.0});
}

TEST_CASE("render_jobs: runs drawn on 2 threads write the same bytes as on 1, mp4s included") {
  const Model model = render_fixture::arm();
  const Recording full = render_fixture::recording();
  Recording cut = full;
  cut.values.resize(7 * std::size_t(cut.layout.size()));
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.fps = 10;
  const FrameSource left(model, full, settings, "left");
  const FrameSource right(model, cut, settings, "right");
  std::map<int, std::map<std::string, std::string>> outputs;  // by threads
  for (int threads : {1, 2, 8}) {
    CAPTURE(threads);
    const fs::path dir = scratch("render", "threads_" + std::to_string(threads));
    for (const char* sub : {"left", "right", "both"}) fs::create_directories(dir / sub);
    const RenderResults results = render_jobs({{&left, settings, {dir / "left", true, true}},
                                               {&right, settings, {dir / "right", true, true}}},
                                              RenderRequest{dir / "both", true, true}, threads);
    CHECK(results.threads == std::min(threads, 2));  // at most one thread per run
    CHECK(results.jobs[0].error == "");
    CHECK(results.jobs[1].error == "");
    REQUIRE(results.side_by_side);
    CHECK(results.side_by_side->error == "");
    CHECK(results.jobs[0].frames == 11);
    outputs[threads] = files_under(dir);
    CHECK(outputs[threads].size() == 12 + 8 + 12);  // video.mp4 and 11, 7, 11 frames
  }
  CHECK(differing(outputs[1], outputs[2]).empty());
  CHECK(differing(outputs[1], outputs[8]).empty());
}

TEST_CASE("run with variants: drawn on the cores available; --jobs 1 writes the same bytes") {
  const int cores = available_cores();
  if (cores < 2) MESSAGE("one core available: both runs are drawn on one thread either way");
  const std::string outputs = "--set output.frames=true";
  const fs::path all = scratch("render", "variants_all_cores");
  const Outcome parallel = shell(short_experiment(all, outputs));
  INFO(parallel.output);
  REQUIRE(parallel.exit_code == 0);
  const int threads = std::min(cores, 2);
  CHECK(parallel.output.find("render: 2 runs drawn at once on " + std::to_string(threads) +
                             (threads == 1 ? " thread (" : " threads (") + std::to_string(cores)) !=
        std::string::npos);
  const fs::path one = scratch("render", "variants_one_thread");
  const Outcome serial = shell(short_experiment(one, outputs + " --jobs 1"));
  INFO(serial.output);
  REQUIRE(serial.exit_code == 0);
  CHECK(serial.output.find("render: 2 runs drawn at once on 1 thread (") != std::string::npos);
  // What was drawn: the videos and frames (summary.json and the reports hold
  // the simulation's wall time, which differs from run to run).
  auto drawn = [](const fs::path& dir) {
    std::map<std::string, std::string> files = files_under(dir);
    std::erase_if(files, [](const auto& f) {
      return f.first.find("video.mp4") == std::string::npos &&
             f.first.find("frames/") == std::string::npos;
    });
    return files;
  };
  const auto a = drawn(one), b = drawn(all);
  CHECK(a.size() == 3 * (1 + 5));
  CHECK(a.count("compare/video.mp4") == 1);
  const std::vector<std::string> names = differing(a, b);
  std::string listed;
  for (const std::string& n : names) listed += n + " ";
  INFO("differing: ", listed);
  CHECK(names.empty());
  // Bounded by the cores: pinned to one, one drawing thread; and the same
  // bytes (x264's thread count is fixed, not taken from the cores).
  if (shell("taskset -c 0 true").exit_code == 0) {
    const fs::path pinned_dir = scratch("render", "variants_pinned");
    const Outcome pinned = shell("taskset -c 0 " + short_experiment(pinned_dir, outputs));
    CHECK(pinned.output.find("render: 2 runs drawn at once on 1 thread (1 core available)") !=
          std::string::npos);
    const std::vector<std::string> pinned_names = differing(drawn(pinned_dir), b);
    std::string pinned_listed;
    for (const std::string& n : pinned_names) pinned_listed += n + " ";
    INFO("differing when pinned to one core: ", pinned_listed);
    CHECK(pinned_names.empty());
  }
  CHECK(shell(short_experiment(one, "--jobs 0")).exit_code == 2);
}
