// Renders recorded runs into a video and/or PNG frames: frames sampled by
// simulation time at settings.fps, one panel per FrameSource side by side,
// overlay text on each panel. The only place that creates a GL context, so a
// run that does not ask for frames never pays for one.
//
// Pipeline: the calling thread builds scenes, draws and reads frame k back
// (pixel-buffer objects, one frame in flight) while a writer thread converts
// frame k-1, draws its overlay and pipes it to ffmpeg (another process, which
// encodes in parallel) or writes it as PNG.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/frame_source.hpp"
#include "render/gl_renderer.hpp"
#include "render/overlay.hpp"
#include "render/render_settings.hpp"

namespace elbowsim {

struct RenderRequest {
  std::filesystem::path folder;  // video.mp4 and frames/ go here (it must exist)
  bool video = true;             // folder/video.mp4 through ffmpeg
  bool frames = false;           // folder/frames/frame_00001.png ...
};

struct RenderStats {
  int frames = 0;             // frames rendered
  int width = 0, height = 0;  // [px] of the output
  int samples = 1;            // MSAA samples per pixel in use
  double fps = 0;
  bool video_written = false;   // folder/video.mp4
  bool frames_written = false;  // folder/frames/
  // Video asked but no ffmpeg on PATH: PNG frames were written instead, and
  // video_command makes the video from them.
  bool ffmpeg_missing = false;
  std::string video_command;
  std::string gl;  // GL renderer and version used
  // Where the time went [s]. Calling thread: building scenes, issuing the
  // draws (llvmpipe transforms and bins the triangles), end of frame (llvmpipe
  // rasterizes and shades there, then the MSAA resolve blit and glReadPixels
  // into a pixel-buffer object), fetch (mapping it, copying the pixels out,
  // waiting for a free buffer when the writer is behind). Writer thread:
  // RGBA -> RGB (and 2x2 averaging) plus overlay, then output (pipe writes
  // wait for ffmpeg's encoder; or PNG encoding).
  double wall_seconds = 0, scene_seconds = 0, draw_seconds = 0, finish_seconds = 0,
         readback_seconds = 0, compose_seconds = 0, output_seconds = 0;
};

// Renders `panels` (at least one; each must outlive the call) for the longest
// panel's recorded duration. Outputs appear only when complete (written under
// temporary names, then renamed; frames/ is replaced as a whole). Throws
// std::runtime_error on GL, ffmpeg or file failures, leaving nothing behind.
RenderStats render_panels(const std::vector<const FrameSource*>& panels,
                          const RenderSettings& settings, const RenderRequest& request);

// What the writer thread draws over a panel: the text box and the inset's marks.
struct PanelText {
  std::vector<std::string> lines;
  std::optional<InsetOverlay> inset;  // output pixels of the whole frame
};

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
