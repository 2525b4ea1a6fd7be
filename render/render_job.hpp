// Renders recorded runs into videos and/or PNG frames: frames sampled by
// simulation time at settings.fps, the overlay text on each; and, for a
// scenario's variants, the runs' frames placed side by side (side_by_side.hpp:
// copied from the runs' own frames, not drawn again). The only place that
// creates GL contexts, so a run that does not ask for frames never pays for one.
//
// Pipeline of one render: a drawing thread builds scenes, draws and reads
// frame k back into one of the writer's buffers while the render's writer
// thread (frame_writer.hpp) finishes frame k-1 and encodes it (H.264 by
// libx264, in-process) or writes it as PNG. Several
// renders are drawn by up to `threads` drawing threads, each with its own
// OSMesa context; a thread with several renders draws them in turns, frame
// by frame. llvmpipe rasterises with threads of its own while there are
// fewer drawing threads than cores, else in the drawing threads.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/frame_source.hpp"
#include "render/frame_writer.hpp"
#include "render/gl_renderer.hpp"
#include "render/render_settings.hpp"

namespace elbowsim {

struct RenderRequest {
  std::filesystem::path folder;  // video.mp4 and frames/ go here (it must exist)
  bool video = true;             // folder/video.mp4 (render/video_encoder.hpp)
  bool frames = false;           // folder/frames/frame_00001.png ...
  bool lossless = false;         // the video lossless (x264 quantiser 0)
};

struct RenderStats {
  int frames = 0;             // frames written
  int width = 0, height = 0;  // [px] of the output
  int samples = 1;            // MSAA samples per pixel in use
  bool fxaa = false;          // frames anti-aliased by FXAA after drawing
  double fps = 0;
  bool video_written = false;   // folder/video.mp4
  bool frames_written = false;  // folder/frames/
  // Video asked but none could be made here (FFmpeg's libraries missing):
  // why; PNG frames were written instead, and video_command makes the video
  // from them.
  std::string video_unavailable;
  std::string video_command;
  std::string gl;     // GL renderer and version used
  std::string error;  // why this render failed ("" if it did not): nothing of it was kept
  bool interrupted = false;  // stopped by RenderControl::stop (error says so): nothing kept
  // Where the time went [s]. Drawing thread: building scenes, issuing the
  // draws (llvmpipe transforms and bins the triangles), waiting for a free
  // buffer when the writer is behind ("readback"), end of frame (llvmpipe
  // rasterizes and shades there, then the MSAA resolve blit and
  // glReadPixels into the buffer). Writer thread:
  // RGBA -> RGB (and 2x2 averaging) plus overlay, then output (YUV
  // conversion and H.264 encoding; PNG
  // encoding; handing the frame to a side-by-side composition). A
  // side-by-side's own time is all output (copies wait for the panels).
  double wall_seconds = 0, scene_seconds = 0, draw_seconds = 0, finish_seconds = 0,
         readback_seconds = 0, compose_seconds = 0, output_seconds = 0;
};

// One recorded run to render; `source` must outlive the call.
struct RenderJob {
  const FrameSource* source = nullptr;
  RenderSettings settings;
  RenderRequest request;
};

struct RenderResults {
  std::vector<RenderStats> jobs;            // in the order of the jobs
  std::optional<RenderStats> side_by_side;  // when asked
  int threads = 0;                          // drawing threads used: min(threads, jobs)
};

// What may stop renders early and what hears how far they are; both optional.
struct RenderControl {
  // Read before each frame is drawn: once true, the renders not fully drawn
  // stop and keep nothing (RenderStats::interrupted), nor does a side-by-side
  // they are panels of. Set by a signal handler (SIGINT, SIGTERM).
  const std::atomic<bool>* stop = nullptr;
  // The share of all the jobs' frames drawn so far (0 .. 1), at every whole
  // per cent and at the end; called from the drawing threads, one call at a time.
  std::function<void(double)> progress;
};

// Renders every job for its recording's duration, drawing up to `threads`
// jobs at once, and with `side_by_side` the jobs' frames side by side, left
// to right in job order, into side_by_side->folder. Outputs appear only when
// complete (written under temporary names, then renamed; frames/ is replaced
// as a whole). A job that fails (GL, the video, files) leaves nothing behind
// and its error in its stats; the side-by-side then fails too. Throws
// std::invalid_argument for no jobs, or when the side-by-side's jobs differ
// in height or fps (side_by_side_problem).
RenderResults render_jobs(const std::vector<RenderJob>& jobs,
                          const std::optional<RenderRequest>& side_by_side, int threads,
                          const RenderControl& control = {});

// The cores this process may run on (its CPU affinity, so `taskset -c 0`
// gives 1): render_jobs' usual number of drawing threads.
int available_cores();

// Why `jobs` cannot be placed side by side ("" when they can): their frames
// must have one height and one rate.
std::string side_by_side_problem(const std::vector<RenderJob>& jobs);

// One job in the calling thread; throws std::runtime_error with its error
// (not when interrupted: the stats say so).
RenderStats render_run(const FrameSource& source, const RenderSettings& settings,
                       const RenderRequest& request, const RenderControl& control = {});

// One panel of one frame, without GL: `source` at time t [s] in `panel`
// (output pixels of the frame): its camera, scene, inset (rectangle within
// the panel) and text (the inset's marks placed in the frame).
struct PanelFrame {
  PixelRect panel;
  Camera camera;
  Scene scene;
  std::optional<Inset> inset;
  PanelText text;
};
PanelFrame prepare_panel(const FrameSource& source, double t, const PixelRect& panel);

// Draws a prepared panel, scene then inset, into a renderer whose frame is
// `scale` times the output size.
void draw_panel(GlRenderer& renderer, const PanelFrame& frame, int scale);

// Frame times [s]: k / fps for k = 0 .. frame_count(end, fps) - 1, the last
// clamped to `end`.
std::vector<double> frame_times(double end, double fps);

}  // namespace elbowsim
