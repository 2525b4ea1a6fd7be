// elbowsim render RUN_DIR: re-renders a saved run (scenario.yaml + trajectory.csv)
// without simulating; and render_outputs, which run uses after simulating.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>

#include "app/commands/camera_option.hpp"
#include "app/commands/commands.hpp"
#include "app/output/run_folder.hpp"
#include "app/output/run_manifest.hpp"
#include "app/output/trajectory_csv.hpp"
#include "app/scenario/scenario.hpp"
#include "render/render_job.hpp"

namespace elbowsim {

namespace fs = std::filesystem;

namespace {

void print_stats(const RenderStats& s, const fs::path& folder) {
  char what[160];
  std::snprintf(what, sizeof what, "%d frames, %dx%d, %g fps, MSAA %dx, %.1f s", s.frames, s.width,
                s.height, s.fps, s.samples, s.wall_seconds);
  if (s.video_written)
    std::cout << "video: " << (folder / "video.mp4").string() << " (" << what << ")\n";
  if (s.frames_written && !s.ffmpeg_missing)
    std::cout << "frames: " << (folder / "frames").string() << "/ (" << what << ")\n";
  if (s.ffmpeg_missing)
    std::cerr << "warning: ffmpeg was not found on PATH, so no video was made; wrote " << s.frames
              << " PNG frames to " << (folder / "frames").string()
              << "/ instead. Install ffmpeg (Debian: apt-get install ffmpeg) and make the video "
                 "with:\n  "
              << s.video_command << '\n';
}

// --camera, --follow, --size, --fps over the scenario's render settings; ""
// if valid, else the message.
std::string apply_options(const RenderArguments& args, RenderSettings& settings) {
  if (args.camera)
    if (std::string error = apply_camera_option(*args.camera, settings.camera); !error.empty())
      return error;
  if (args.follow)
    if (std::string error = apply_follow_option(*args.follow, settings.camera); !error.empty())
      return error;
  if (args.size) {
    std::smatch m;
    if (!std::regex_match(*args.size, m, std::regex("([0-9]{1,5})x([0-9]{1,5})")))
      return "--size: expected WIDTHxHEIGHT in pixels, e.g. 1280x720 (got \"" + *args.size + "\")";
    const int w = std::stoi(m[1]), h = std::stoi(m[2]);
    if (w < 16 || h < 16 || w > 8192 || h > 8192 || w % 2 || h % 2)
      return "--size: width and height must be even and in 16 .. 8192 (got " + *args.size + ")";
    settings.width = w;
    settings.height = h;
  }
  if (args.fps) {
    char* end = nullptr;
    const double fps = std::strtod(args.fps->c_str(), &end);
    if (end == args.fps->c_str() || *end || !(fps > 0 && fps <= 240))
      return "--fps: must be a number in (0, 240] (got \"" + *args.fps + "\")";
    settings.fps = fps;
  }
  return "";
}

// The run folder's scenario and recording; "" if readable, else the message.
std::string load_run(const fs::path& folder, Scenario& scenario, Recording& recording) {
  if (!fs::is_directory(folder)) return folder.string() + ": not a run folder (no such directory)";
  const fs::path csv = folder / "trajectory.csv", yaml = folder / "scenario.yaml";
  if (!fs::is_regular_file(csv))
    return folder.string() + ": no trajectory.csv (run the scenario with output.trajectory: true)";
  if (!fs::is_regular_file(yaml))
    return folder.string() + ": no scenario.yaml (written by elbowsim run since version 0.1.0)";
  try {
    load_run_folder(folder);  // refuses cut or mismatched files (InconsistentRunFolder)
    scenario = load_scenario(yaml.string());
    std::ifstream in(csv, std::ios::binary);
    recording = read_trajectory_csv(in, csv.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

int render_with(const Scenario& scenario, const Recording& recording, const fs::path& folder,
                const RenderSettings& settings, RenderRequest request) {
  request.folder = folder;
  std::optional<FrameSource> source;
  try {
    source.emplace(scenario.model, recording, settings, scenario.model.name);
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: cannot render " << folder.string() << ": " << e.what() << '\n';
    return exit_bad_input;
  }
  try {
    print_stats(render_panels({&*source}, settings, request), folder);
  } catch (const std::exception& e) {
    std::cerr << "error: rendering failed: " << e.what() << '\n';
    return exit_io;
  }
  return exit_ok;
}

}  // namespace

int render_side_by_side(const std::vector<fs::path>& runs, const fs::path& out) {
  std::vector<Scenario> scenarios(runs.size());
  std::vector<Recording> recordings(runs.size());
  std::vector<FrameSource> sources;
  sources.reserve(runs.size());
  try {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const std::string problem = load_run(runs[k], scenarios[k], recordings[k]);
      if (!problem.empty()) throw std::runtime_error(problem);
      // Each panel is labelled with its run folder's name (the variant).
      sources.emplace_back(scenarios[k].model, recordings[k], scenarios[0].render,
                           runs[k].filename().string());
    }
    std::vector<const FrameSource*> panels;
    for (const FrameSource& s : sources) panels.push_back(&s);
    fs::create_directories(out);
    print_stats(render_panels(panels, scenarios[0].render, {out, true, false}), out);
  } catch (const std::exception& e) {
    std::cerr << "error: side-by-side video: " << e.what() << '\n';
    return exit_io;
  }
  return exit_ok;
}

int render_outputs(const Scenario& scenario, const Recording& recording, const fs::path& folder) {
  return render_with(scenario, recording, folder, scenario.render,
                     {folder, scenario.output.video, scenario.output.frames});
}

int render_command(const RenderArguments& args) {
  Scenario scenario;
  Recording recording;
  const fs::path folder = args.folder;
  if (std::string error = load_run(folder, scenario, recording); !error.empty()) {
    std::cerr << "error: " << error << '\n';
    return exit_bad_input;
  }
  RenderSettings settings = scenario.render;
  if (std::string error = apply_options(args, settings); !error.empty()) {
    std::cerr << "error: " << error << '\n';
    return exit_bad_input;
  }
  // A scenario that asked for neither gets a video: that is what render is for.
  const bool video = scenario.output.video || !scenario.output.frames;
  const int code =
      render_with(scenario, recording, folder, settings, {folder, video, scenario.output.frames});
  if (code != exit_ok) return code;
  try {
    record_rendered(folder, video, scenario.output.frames);  // the report may now embed it
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_io;
  }
  return exit_ok;
}

}  // namespace elbowsim
