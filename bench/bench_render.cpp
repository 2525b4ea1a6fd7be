// End-to-end frame rate of the renderer (render/render_job.cpp): scene
// building, drawing (OSMesa llvmpipe, GL 3.3 core), read-back into the
// writer's buffers, overlay, and YUV 4:2:0 frames encoded by libx264 into an
// mp4 (FFmpeg's libraries, in the writer thread), with drawing and encoding
// overlapped (drawing thread + writer thread). A plain timed program, not Google Benchmark: one
// measurement is a whole render of 150 frames (5 s at 30 fps).
//
// Prototype scene: an 8-link planar arm (8 capsules) swinging over a table,
// with 3 elbow spheres (two resting with force arrows, contact cues), the
// hand path and a desired one (so the hand-path inset is drawn), shadows and
// the ground grid: the render settings' defaults; anti-aliasing none, MSAA
// 4x and (at 1280x720) FXAA, the default. Protocol: one warm-up render, then 3 timed renders per
// configuration; reports the median and where the time went in that run.
//
// Run: build/bench/bench_render [runs] [--json FILE]
//   (renders go to /tmp/elbowsim_bench_render; --json also writes every run's
//   numbers and the medians to FILE, as bench/run.sh and bench/tables.py use them)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "render/frame_source.hpp"
#include "render/render_job.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

Model prototype_arm() {
  std::vector<testing::PlanarLinkSpec> links(8, {0.11, 0.4, 0.055, 4e-4});
  Model m = testing::planar_arm(links);
  for (Link& link : m.links) link.radius = 0.018;
  m.elbows = {Elbow{"e1", 1, Eigen::Vector3d(0.11, 0, 0), 0.025},
              Elbow{"e3", 3, Eigen::Vector3d(0.11, 0, 0), 0.025},
              Elbow{"e5", 5, Eigen::Vector3d(0.11, 0, 0), 0.025}};
  m.table = {TableBox{{0.5, 0, -0.08}, {1.3, 0.8, 0.1}, Eigen::Matrix3d::Identity()}};
  m.effects.contact = true;
  finalize(m);
  return m;
}

// 5 s at 1 kHz / 10 (like output.every: 10): the arm waves, elbows rest and lift.
Recording prototype_recording(const Model& model) {
  TrajectoryLayout::Groups groups{8, false, true, true, {}};
  for (const Elbow& e : model.elbows) groups.elbows.push_back(e.name);
  Recording rec{TrajectoryLayout(groups)};
  const TrajectoryLayout& L = rec.layout;
  for (int k = 0; k <= 500; ++k) {
    const double t = 0.01 * k;
    std::vector<double> row(static_cast<std::size_t>(L.size()), 0.0);
    row[L.time()] = t;
    for (int j = 0; j < 8; ++j)
      row[L.q(j)] = 0.35 * std::sin(2 * std::numbers::pi * 0.4 * t + 0.7 * j) - 0.05;
    row[L.hand(0)] = row[L.hand_desired(0)] = 0.7 + 0.1 * std::sin(t);
    row[L.hand(2)] = row[L.hand_desired(2)] = 0.1 + 0.05 * std::cos(2 * t);
    for (int e = 0; e < 3; ++e) {
      const bool rest = std::sin(2 * t + e) > -0.3;
      // at(): the layout gives -1 for a column it lacks (here it has them all).
      row.at(L.elbow_force(e)) = rest ? 8.0 + 3 * std::sin(3 * t + e) : 0.0;
      row.at(L.elbow_resting(e)) = rest ? 1.0 : 0.0;
    }
    row[L.energy(Energy::electrical_in)] = 2.0 * t;
    rec.values.insert(rec.values.end(), row.begin(), row.end());
  }
  return rec;
}

struct Config {
  int width, height;
  Antialiasing antialiasing;
  int msaa;  // samples with antialiasing msaa
  bool video;
  std::string label() const {  // "none", "msaa4", "fxaa"
    return antialiasing == Antialiasing::msaa ? "msaa" + std::to_string(msaa)
                                              : to_string(antialiasing);
  }
};

// Runs sorted by wall time, fastest first; the median is the middle one.
void sort_runs(std::vector<RenderStats>& runs) {
  std::sort(runs.begin(), runs.end(), [](const RenderStats& a, const RenderStats& b) {
    return a.wall_seconds < b.wall_seconds;
  });
}

void print_row(const Config& c, std::vector<RenderStats> runs) {
  sort_runs(runs);
  const RenderStats& m = runs[runs.size() / 2];
  const double per = 1000.0 / m.frames;  // ms per frame
  std::printf(
      "%5dx%-4d  %-5s  %-4s  %6.1f fps (%5.1f .. %5.1f)  ms/frame: scene %4.2f  "
      "draw %5.2f  end %5.2f  wait %5.2f | writer: compose %4.2f  output %5.2f\n",
      c.width, c.height, c.label().c_str(), c.video ? "mp4" : "none", m.frames / m.wall_seconds,
      runs.back().frames / runs.back().wall_seconds,
      runs.front().frames / runs.front().wall_seconds, m.scene_seconds * per, m.draw_seconds * per,
      m.finish_seconds * per, m.readback_seconds * per, m.compose_seconds * per,
      m.output_seconds * per);
  std::fflush(stdout);
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\')
      out += '\\', out += ch;
    else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else
      out += ch;
  }
  return out + "\"";
}

// One configuration's runs (sorted) as a JSON object: the median run's numbers
// (fps, ms per frame in each stage), the fastest and slowest fps, every run's fps.
void write_json_row(std::FILE* f, const Config& c, std::vector<RenderStats> runs, bool last) {
  sort_runs(runs);
  const RenderStats& m = runs[runs.size() / 2];
  const double per = 1000.0 / m.frames;
  std::fprintf(f,
               "    {\"name\": \"%dx%d_%s_%s\", \"width\": %d, \"height\": %d, "
               "\"antialiasing\": \"%s\", \"msaa\": %d, \"samples\": %d, \"output\": \"%s\", "
               "\"frames\": %d,\n"
               "     \"video_unavailable\": %s, \"runs\": %zu,\n"
               "     \"median_fps\": %.4f, \"min_fps\": %.4f, \"max_fps\": %.4f,\n"
               "     \"median_ms_per_frame\": {\"wall\": %.4f, \"scene\": %.4f, \"draw\": %.4f, "
               "\"end\": %.4f, \"wait\": %.4f, \"compose\": %.4f, \"output\": %.4f},\n"
               "     \"fps_per_run\": [",
               c.width, c.height, c.label().c_str(), c.video ? "mp4" : "none", c.width, c.height,
               to_string(c.antialiasing), m.samples, m.samples, c.video ? "mp4" : "none", m.frames,
               !m.video_unavailable.empty() ? "true" : "false", runs.size(),
               m.frames / m.wall_seconds, runs.back().frames / runs.back().wall_seconds,
               runs.front().frames / runs.front().wall_seconds, m.wall_seconds * per,
               m.scene_seconds * per, m.draw_seconds * per, m.finish_seconds * per,
               m.readback_seconds * per, m.compose_seconds * per, m.output_seconds * per);
  for (std::size_t k = 0; k < runs.size(); ++k)
    std::fprintf(f, "%s%.4f", k ? ", " : "", runs[k].frames / runs[k].wall_seconds);
  std::fprintf(f, "]}%s\n", last ? "" : ",");
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  const char* json_path = nullptr;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--json") == 0 && k + 1 < argc)
      json_path = argv[++k];
    else if (std::strcmp(argv[k], "--help") == 0 || std::strcmp(argv[k], "-h") == 0 ||
             std::strcmp(argv[k], "--json") == 0) {
      std::fprintf(stderr, "usage: %s [runs (default 3)] [--json FILE]\n", argv[0]);
      return 2;
    } else
      runs = std::max(1, std::atoi(argv[k]));
  }
  double load[3] = {-1, -1, -1};
  getloadavg(load, 3);
  const std::time_t started = std::time(nullptr);
  const Model model = prototype_arm();
  const Recording recording = prototype_recording(model);
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "elbowsim_bench_render";
  std::filesystem::create_directories(folder);

  RenderSettings settings;
  settings.fps = 30;
  constexpr Antialiasing none = Antialiasing::none, msaa = Antialiasing::msaa,
                         fxaa = Antialiasing::fxaa;
  const std::vector<Config> configs = {{640, 480, none, 1, true},   {640, 480, msaa, 4, true},
                                       {1280, 720, none, 1, true},  {1280, 720, msaa, 4, true},
                                       {1280, 720, fxaa, 1, true},  {1280, 720, none, 1, false},
                                       {1280, 720, msaa, 4, false}, {1280, 720, fxaa, 1, false}};
  bool warmed = false;
  std::vector<std::vector<RenderStats>> all;
  std::string gl;
  for (const Config& c : configs) {
    settings.width = c.width;
    settings.height = c.height;
    settings.antialiasing = c.antialiasing;
    settings.msaa = c.msaa;
    const FrameSource source(model, recording, settings, "prototype");
    const RenderRequest request{folder, c.video, false};
    if (!warmed) render_run(source, settings, request), warmed = true;
    std::vector<RenderStats> stats;
    for (int r = 0; r < runs; ++r) stats.push_back(render_run(source, settings, request));
    if (c.width == 1280 && c.antialiasing == msaa && c.video)
      std::printf("(%s)\n", stats[0].gl.c_str());
    print_row(c, stats);
    gl = stats[0].gl;
    all.push_back(std::move(stats));
  }
  if (!json_path) return 0;
  std::FILE* f = std::fopen(json_path, "w");
  if (!f) {
    std::perror(json_path);
    return 1;
  }
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&started));
  std::fprintf(f,
               "{\n  \"context\": {\"program\": \"bench_render\", \"date\": \"%s\", "
               "\"runs_per_config\": %d, \"warmup_renders\": 1, \"frames_per_render\": %d,\n"
               "              \"load_avg\": [%.2f, %.2f, %.2f], \"gl\": %s},\n"
               "  \"configs\": [\n",
               date, runs, all.empty() ? 0 : all[0][0].frames, load[0], load[1], load[2],
               json_string(gl).c_str());
  for (std::size_t k = 0; k < all.size(); ++k)
    write_json_row(f, configs[k], all[k], k + 1 == all.size());
  std::fprintf(f, "  ]\n}\n");
  return std::fclose(f) == 0 ? 0 : 1;
}
