// elbowsim render RUN_DIR: re-renders a saved run (scenario.yaml + trajectory.csv)
// without simulating; and render_runs, which run uses after simulating.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>

#include "app/commands/camera_option.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt.hpp"
#include "app/commands/progress.hpp"
#include "app/output/run_folder.hpp"
#include "app/output/run_manifest.hpp"
#include "app/output/trajectory_csv.hpp"
#include "app/scenario/scenario.hpp"
#include "engine/recording/number_text.hpp"
#include "render/playback.hpp"
#include "render/render_job.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim {

namespace fs = std::filesystem;

namespace {

std::string antialiasing(const RenderStats& s) {
  if (s.samples > 1) return "MSAA " + std::to_string(s.samples) + "x" + (s.fxaa ? " + FXAA" : "");
  return s.fxaa ? "FXAA" : "no anti-aliasing";
}

std::string rerun_command(const fs::path& run_folder) {
  return "`elbowsim render " + run_folder.string() + "`";
}

// What a render made, as the video: and frames: lines say it: the length a
// player shows (frames / fps), frames, rate, size and anti-aliasing, then,
// labelled apart, the time rendering took.
std::string render_stats_text(const RenderStats& s) {
  const double length = s.fps > 0 ? s.frames / s.fps : 0.0;
  char what[200];
  std::snprintf(what, sizeof what, length < 100 ? "%.3g" : "%.0f", length);  // 4.83, 20, 1200
  std::snprintf(what + std::strlen(what), sizeof what - std::strlen(what),
                " s long: %d frames at %g fps, %dx%d, %s; rendered in %.1f s", s.frames, s.fps,
                s.width, s.height, antialiasing(s).c_str(), s.wall_seconds);
  return what;
}

// `rerun`: how to make the video again once the library is there.
void print_stats(const RenderStats& s, const fs::path& folder, const std::string& rerun) {
  const std::string what = render_stats_text(s);
  if (s.video_written)
    std::cout << "video: " << (folder / "video.mp4").string() << " (" << what << ")\n";
  if (s.frames_written && s.video_unavailable.empty())
    std::cout << "frames: " << (folder / "frames").string() << "/ (" << what << ")\n";
  if (!s.video_unavailable.empty())
    std::cerr << "warning: no video was made: " << s.video_unavailable << "\nwrote " << s.frames
              << " PNG frames to " << (folder / "frames").string()
              << "/ instead; with the library installed, " << rerun
              << " makes the video, or the ffmpeg program from the frames:\n  " << s.video_command
              << '\n';
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
    const report::RunData run = load_run_folder(folder);  // refuses cut or mismatched files
    scenario = load_scenario(yaml.string());
    // scenario.yaml is the variant as run, without its name: summary.json keeps it.
    const std::string_view variant = summary_key::variant.name();
    if (run.summary.is_object() && run.summary.contains(variant))
      scenario.variant = run.summary[variant].get<std::string>();
    std::ifstream in(csv, std::ios::binary);
    recording = read_trajectory_csv(in, csv.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// The title over a run's frames: the scene's name, and the variant's.
std::string title(const Scenario& scenario) {
  return scenario.variant.empty() ? scenario.model.name
                                  : scenario.model.name + ": " + scenario.variant;
}

// Stopped by SIGINT or SIGTERM; progress on a terminal, else a line saying
// it starts (how many frames: the video lines say when it ended).
RenderControl render_control() { return {&interrupt_flag(), terminal_progress("rendering ")}; }

void say_started(std::size_t runs, std::size_t frames, bool side_by_side) {
  if (progress_on_terminal()) return;
  std::cerr << "rendering " << counted(static_cast<long long>(frames), "frame") << " of "
            << counted(static_cast<long long>(runs), "run")
            << (side_by_side ? ", and their side-by-side" : "") << '\n';
}

int render_with(const Scenario& scenario, const Recording& recording, const fs::path& folder,
                const RenderSettings& settings, RenderRequest request) {
  request.folder = folder;
  std::optional<FrameSource> source;
  try {
    source.emplace(scenario.model, recording, settings, title(scenario));
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: cannot render " << folder.string() << ": " << e.what() << '\n';
    return exit_bad_input;
  }
  say_started(1, std::size_t(frame_count(source->end_time(), settings.fps)), false);
  try {
    const RenderStats stats = render_run(*source, settings, request, render_control());
    if (stats.interrupted) {
      end_progress_line();
      std::cerr << "interrupted: no video or frames made; " << folder.string()
                << " holds what it held before\n";
      return interrupt_exit_code();
    }
    print_stats(stats, folder, rerun_command(folder));
  } catch (const std::exception& e) {
    std::cerr << "error: rendering failed: " << e.what() << '\n';
    return exit_io;
  }
  return exit_ok;
}

}  // namespace

std::vector<int> render_runs(const std::vector<RunToRender>& runs,
                             const std::optional<fs::path>& side_by_side, int& side_by_side_code,
                             int threads) {
  side_by_side_code = exit_ok;
  std::vector<int> codes(runs.size(), exit_ok);
  std::vector<std::optional<FrameSource>> sources(runs.size());
  std::vector<RenderJob> jobs;
  std::vector<std::size_t> job_run;  // the run of each job
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Scenario& s = *runs[k].scenario;
    if (!s.output.video && !s.output.frames) continue;
    try {
      sources[k].emplace(s.model, *runs[k].recording, s.render, title(s));
    } catch (const std::invalid_argument& e) {
      std::cerr << "error: cannot render " << runs[k].folder.string() << ": " << e.what() << '\n';
      codes[k] = exit_bad_input;
      continue;
    }
    jobs.push_back({&*sources[k],
                    s.render,
                    {runs[k].folder, s.output.video, s.output.frames, s.output.lossless_video}});
    job_run.push_back(k);
  }
  if (jobs.empty()) return codes;
  // The side-by-side needs every run's frames, of one height and rate.
  std::optional<RenderRequest> side;
  if (side_by_side && jobs.size() == runs.size()) {
    if (const std::string problem = side_by_side_problem(jobs); !problem.empty()) {
      std::cerr << "warning: no side-by-side video: " << problem << '\n';
    } else {
      fs::create_directories(*side_by_side);
      const Scenario& first = *runs.front().scenario;
      side = RenderRequest{*side_by_side, first.output.video, first.output.frames,
                           first.output.lossless_video};
    }
  }
  const int cores = available_cores();
  std::size_t frames = 0;
  for (const RenderJob& j : jobs)
    frames += std::size_t(frame_count(j.source->end_time(), j.settings.fps));
  say_started(jobs.size(), frames, side.has_value());
  const RenderResults results =
      render_jobs(jobs, side, threads > 0 ? threads : cores, render_control());
  // Interrupted: the runs not fully drawn keep nothing and say nothing here
  // (the caller says what was kept); those drawn to the end are kept.
  bool interrupted = false;
  for (const RenderStats& stats : results.jobs) interrupted |= stats.interrupted;
  if (interrupted) end_progress_line();
  if (jobs.size() > 1 && !interrupted)
    std::cout << "render: " << jobs.size() << " runs drawn at once on " << results.threads
              << (results.threads == 1 ? " thread" : " threads") << " (" << cores
              << (cores == 1 ? " core" : " cores") << " available)\n";
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const RenderStats& stats = results.jobs[j];
    const fs::path& folder = runs[job_run[j]].folder;
    if (stats.interrupted) {
      codes[job_run[j]] = interrupt_exit_code();
    } else if (!stats.error.empty()) {
      std::cerr << "error: rendering " << folder.string() << " failed: " << stats.error << '\n';
      codes[job_run[j]] = exit_io;
    } else {
      print_stats(stats, folder, rerun_command(folder));
    }
  }
  if (results.side_by_side) {
    if (results.side_by_side->interrupted) {
      side_by_side_code = interrupt_exit_code();
    } else if (!results.side_by_side->error.empty()) {
      std::cerr << "error: side-by-side video: " << results.side_by_side->error << '\n';
      side_by_side_code = exit_io;
    } else {
      print_stats(*results.side_by_side, *side_by_side, "`elbowsim run` of the scenario again");
    }
  }
  return codes;
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
  install_interrupt_handlers();
  const int code =
      render_with(scenario, recording, folder, settings,
                  {folder, video, scenario.output.frames, scenario.output.lossless_video});
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
