#include "render/render_job.hpp"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "render/osmesa_context.hpp"
#include "render/video_encoder.hpp"

namespace elbowsim {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Temporary outputs, removed unless committed.
struct Outputs {
  fs::path folder, video_tmp, frames_tmp;
  bool video = false, frames = false;
  ~Outputs() {
    std::error_code ignored;
    if (!frames_tmp.empty()) fs::remove_all(frames_tmp, ignored);
    if (!video_tmp.empty()) fs::remove(video_tmp, ignored);
  }
  void commit() {
    if (video) fs::rename(video_tmp, folder / "video.mp4");
    video_tmp.clear();
    if (frames) {
      fs::remove_all(folder / "frames");
      fs::rename(frames_tmp, folder / "frames");
    }
    frames_tmp.clear();
  }
};

// A render's outputs opened: a video needs FFmpeg's libraries; without them,
// PNG frames and the command that makes the video from them.
struct OpenOutputs {
  Outputs files;
  std::optional<VideoEncoder> encoder;  // before the writer that uses it, so destroyed after

  OpenOutputs(const RenderRequest& request, int width, int height, double fps, RenderStats& stats) {
    files.folder = request.folder;
    if (request.video) stats.video_unavailable = video_unavailable();
    files.video = request.video && stats.video_unavailable.empty();
    files.frames = request.frames || !stats.video_unavailable.empty();
    if (files.frames) {
      files.frames_tmp = request.folder / "frames.tmp";
      fs::remove_all(files.frames_tmp);
      fs::create_directories(files.frames_tmp);
    }
    if (files.video) {
      files.video_tmp = request.folder / "video.tmp.mp4";
      encoder.emplace(files.video_tmp, width, height, fps, request.lossless);
    }
    if (!stats.video_unavailable.empty())
      stats.video_command =
          frames_to_video_command(request.folder / "frames", request.folder / "video.mp4", fps);
  }
  FrameOutputs frame_outputs(SideBySide* side, int panel) {
    return {encoder ? &*encoder : nullptr,
            files.frames ? std::optional(files.frames_tmp) : std::nullopt, side, panel};
  }
  // Finishes the video and renames the outputs into place.
  void finish(RenderStats& stats) {
    if (encoder) encoder->finish();
    files.commit();
    stats.video_written = files.video;
    stats.frames_written = files.frames;
  }
};

// One job under way.
struct Running {
  const RenderJob* job = nullptr;
  RenderStats stats;
  std::vector<double> times;
  int scale = 1;
  std::size_t drawn = 0;  // frames drawn so far
  std::optional<OpenOutputs> outputs;
  std::unique_ptr<FrameWriter> writer;

  bool drawing() const { return writer && !writer->failed() && stats.error.empty(); }
};

// RenderControl for the drawing threads: the stop flag, and the frames drawn
// by all of them reported as a share of all the jobs' frames.
class Control {
 public:
  Control(const RenderControl& control, std::size_t total) : control_(control), total_(total) {}
  bool stopped() const { return control_.stop && control_.stop->load(std::memory_order_relaxed); }
  void frame_drawn() {
    if (!control_.progress || total_ == 0) return;
    const std::size_t n = ++drawn_;
    if (n * 100 / total_ == (n - 1) * 100 / total_ && n != total_) return;  // every whole per cent
    std::lock_guard lock(mutex_);
    if (n <= reported_) return;  // another thread said more already
    reported_ = n;
    control_.progress(double(n) / double(total_));
  }

 private:
  const RenderControl& control_;
  const std::size_t total_;
  std::atomic<std::size_t> drawn_{0};
  std::mutex mutex_;
  std::size_t reported_ = 0;
};

// Panel i of n across the frame, in pixels: one panel, the whole frame.
PixelRect whole(const RenderSettings& s) { return {0, 0, s.width, s.height}; }

// Frame k of `r` drawn, read into one of its writer's buffers and handed over.
void draw_frame(Running& r, GlRenderer& renderer, int k) {
  Clock::time_point t0 = Clock::now();
  ReadFrame frame{k, {}, {}};
  PanelFrame f = prepare_panel(*r.job->source, r.times[std::size_t(k)], whole(r.job->settings));
  r.stats.scene_seconds += seconds_since(t0);
  t0 = Clock::now();
  renderer.begin_frame(f.scene.background);
  draw_panel(renderer, f, r.scale);
  frame.text = std::move(f.text);
  r.stats.draw_seconds += seconds_since(t0);
  t0 = Clock::now();
  frame.rgba = r.writer->buffer();
  r.stats.readback_seconds += seconds_since(t0);
  t0 = Clock::now();
  renderer.end_frame(frame.rgba.data());
  r.stats.finish_seconds += seconds_since(t0);
  r.writer->push(std::move(frame));
  ++r.drawn;
}

// Stopped from outside: the jobs not fully drawn keep nothing (finish() does
// not commit a job with an error), and a side-by-side stops waiting for them.
void interrupt(const std::vector<Running*>& jobs, SideBySide* side) {
  for (Running* r : jobs)
    if (r->drawing() && r->drawn < r->times.size()) {
      r->stats.interrupted = true;
      r->stats.error = "interrupted by a signal before its last frame";
    }
  if (side) side->abort();
}

// Draws `jobs` in turns, frame by frame, in a context of this thread. A GL
// failure stops them all (they share the context).
void draw_jobs(const std::vector<Running*>& jobs, SideBySide* side, Control& control) {
  try {
    OsmesaContext context;
    std::vector<std::unique_ptr<GlRenderer>> renderers;  // destroyed before the context
    std::size_t frames = 0;
    for (Running* r : jobs) {
      const RenderSettings& s = r->job->settings;
      renderers.push_back(
          std::make_unique<GlRenderer>(s.width * r->scale, s.height * r->scale, s.samples()));
      r->stats.samples = renderers.back()->samples();
      r->stats.gl = context.description();
      frames = std::max(frames, r->times.size());
    }
    for (std::size_t k = 0; k < frames; ++k)
      for (std::size_t j = 0; j < jobs.size(); ++j) {
        Running& r = *jobs[j];
        if (k >= r.times.size() || !r.drawing()) continue;
        if (control.stopped()) return interrupt(jobs, side);
        draw_frame(r, *renderers[j], int(k));
        control.frame_drawn();
        // A job that has ended is closed at once: a side-by-side's longer
        // panels wait for its frames until it is.
        if (k + 1 == r.times.size()) r.writer->close();
      }
  } catch (const std::exception& e) {
    for (Running* r : jobs) r->stats.error = e.what();
    if (side) side->abort();  // its other panels must not wait for these
  }
}

// The jobs split among `threads` drawing threads (job i to thread i mod threads).
std::vector<std::vector<Running*>> groups(std::vector<Running>& running, int threads) {
  const std::size_t n = std::size_t(std::clamp(threads, 1, int(running.size())));
  std::vector<std::vector<Running*>> out(n);
  for (std::size_t i = 0; i < running.size(); ++i) out[i % n].push_back(&running[i]);
  return out;
}

void start(Running& r, const RenderJob& job, SideBySide* side, int panel) {
  r.job = &job;
  const RenderSettings& s = job.settings;
  r.stats.width = s.width;
  r.stats.height = s.height;
  r.stats.fps = s.fps;
  r.scale = s.supersample ? 2 : 1;
  r.stats.fxaa = s.antialiasing == Antialiasing::fxaa;
  r.times = frame_times(job.source->end_time(), s.fps);
  try {
    r.outputs.emplace(job.request, s.width, s.height, s.fps, r.stats);
    r.writer = std::make_unique<FrameWriter>(s.width, s.height, r.scale, r.stats.fxaa,
                                             r.outputs->frame_outputs(side, panel));
  } catch (const std::exception& e) {
    r.stats.error = e.what();
    if (side) side->abort();
  }
}

// After drawing: the writer's last frames, the video's end, the outputs renamed into place.
void finish(Running& r, Clock::time_point started) {
  try {
    if (r.writer) r.writer->finish();
    if (r.stats.error.empty() && r.outputs) r.outputs->finish(r.stats);
  } catch (const std::exception& e) {
    if (r.stats.error.empty()) r.stats.error = e.what();
  }
  if (r.writer) {
    r.stats.compose_seconds = r.writer->compose_seconds;
    r.stats.output_seconds = r.writer->output_seconds;
  }
  r.writer.reset();
  if (r.stats.error.empty()) r.stats.frames = int(r.times.size());
  r.outputs.reset();  // what a failed render wrote goes
  r.stats.wall_seconds = seconds_since(started);
}

}  // namespace

PanelFrame prepare_panel(const FrameSource& source, double t, const PixelRect& panel) {
  PanelFrame f{panel,
               source.camera(double(panel.width) / panel.height, t),
               source.scene(t),
               std::nullopt,
               {source.overlay(t), std::nullopt}};
  f.inset = source.inset(t, f.camera, panel.width, panel.height);
  if (f.inset) {
    const Inset& inset = *f.inset;
    const PixelRect r{panel.x + inset.rect.x, panel.y + inset.rect.y, inset.rect.width,
                      inset.rect.height};
    f.text.inset = InsetOverlay{r,
                                inset.title,
                                inset.scale_label,
                                inset.scale_bar_px,
                                inset.desired.color,
                                inset.traced.color};
  }
  return f;
}

void draw_panel(GlRenderer& renderer, const PanelFrame& f, int scale) {
  auto scaled = [scale](const PixelRect& r) {
    return Viewport{r.x * scale, r.y * scale, r.width * scale, r.height * scale};
  };
  if (!f.inset) return renderer.draw(f.scene, f.camera, scaled(f.panel));
  const GlRenderer::InsetView inset{*f.inset, scaled(f.text.inset->rect)};
  renderer.draw(f.scene, f.camera, scaled(f.panel), &inset);
}

std::vector<double> frame_times(double end, double fps) {
  std::vector<double> times;
  const int n = frame_count(end, fps);
  for (int k = 0; k < n; ++k) times.push_back(std::min(k / fps, end));
  return times;
}

int available_cores() {
  cpu_set_t set;
  if (::sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

std::string side_by_side_problem(const std::vector<RenderJob>& jobs) {
  for (const RenderJob& j : jobs) {
    const RenderSettings &a = jobs.front().settings, &b = j.settings;
    if (b.height != a.height)
      return "the runs' frames differ in height (" + std::to_string(a.height) + " and " +
             std::to_string(b.height) + " px)";
    if (b.fps != a.fps) return "the runs' frame rates differ";
  }
  return "";
}

RenderResults render_jobs(const std::vector<RenderJob>& jobs,
                          const std::optional<RenderRequest>& side_by_side, int threads,
                          const RenderControl& control) {
  if (jobs.empty()) throw std::invalid_argument("render_jobs: no jobs");
  // With a drawing thread on every core, llvmpipe's own rasteriser threads
  // only add hand-offs (0.4 s of the main job's 10 s of CPU, wall time the
  // same): each drawing thread then rasterises its own frames. llvmpipe reads
  // this when the process's first context is made; the user's value stays.
  if (std::min(threads, int(jobs.size())) >= available_cores())
    ::setenv("LP_NUM_THREADS", "0", /*overwrite=*/0);
  if (side_by_side)
    if (const std::string problem = side_by_side_problem(jobs); !problem.empty())
      throw std::invalid_argument("no side-by-side video: " + problem);
  const Clock::time_point started = Clock::now();
  RenderResults results;

  // The side-by-side's outputs and composition, fed by the jobs' writers.
  std::optional<RenderStats> side_stats;
  std::optional<OpenOutputs> side_outputs;
  std::optional<SideBySide> side;
  if (side_by_side) {
    const RenderSettings& first = jobs.front().settings;
    std::vector<int> widths;
    for (const RenderJob& j : jobs) widths.push_back(j.settings.width);
    side_stats.emplace();
    side_stats->width = 0;
    for (int w : widths) side_stats->width += w;
    side_stats->height = first.height;
    side_stats->fps = first.fps;
    side_stats->samples = first.samples();
    side_stats->fxaa = first.antialiasing == Antialiasing::fxaa;
    try {
      side_outputs.emplace(*side_by_side, side_stats->width, first.height, first.fps, *side_stats);
      const FrameOutputs o = side_outputs->frame_outputs(nullptr, 0);
      side.emplace(widths, first.height, o.encoder, o.frames);
    } catch (const std::exception& e) {
      side_stats->error = e.what();
    }
  }
  SideBySide* composer = side ? &*side : nullptr;

  std::vector<Running> running(jobs.size());
  std::size_t total = 0;  // frames to draw
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    start(running[i], jobs[i], composer, int(i));
    if (running[i].stats.error.empty()) total += running[i].times.size();
  }
  Control drawing(control, total);
  const std::vector<std::vector<Running*>> by_thread = groups(running, threads);
  results.threads = int(by_thread.size());
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < by_thread.size(); ++t)
    helpers.emplace_back([&, t] { draw_jobs(by_thread[t], composer, drawing); });
  draw_jobs(by_thread[0], composer, drawing);
  for (std::thread& h : helpers) h.join();
  for (Running& r : running) finish(r, started);
  for (Running& r : running) results.jobs.push_back(r.stats);

  if (side_stats) {
    for (const Running& r : running) {
      side_stats->interrupted |= r.stats.interrupted;
      if (side_stats->error.empty() && !r.stats.error.empty())
        side_stats->error = "a panel failed: " + r.stats.error;
    }
    if (side_stats->error.empty() && side) side_stats->error = side->error();
    try {
      if (side_stats->error.empty()) side_outputs->finish(*side_stats);
    } catch (const std::exception& e) {
      side_stats->error = e.what();
    }
    if (side) {
      side_stats->frames = side_stats->error.empty() ? side->frames() : 0;
      side_stats->output_seconds = side->output_seconds();
    }
    for (const Running& r : running) side_stats->gl = r.stats.gl;
    side_outputs.reset();
    side_stats->wall_seconds = seconds_since(started);
    results.side_by_side = side_stats;
  }
  return results;
}

RenderStats render_run(const FrameSource& source, const RenderSettings& settings,
                       const RenderRequest& request, const RenderControl& control) {
  RenderStats stats =
      render_jobs({{&source, settings, request}}, std::nullopt, 1, control).jobs.front();
  if (!stats.error.empty() && !stats.interrupted) throw std::runtime_error(stats.error);
  return stats;
}

}  // namespace elbowsim
