#include "render/render_job.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <optional>
#include <queue>
#include <stdexcept>
#include <thread>

#include "render/gl_renderer.hpp"
#include "render/osmesa_context.hpp"
#include "render/overlay.hpp"
#include "render/png_writer.hpp"
#include "render/video_encoder.hpp"

namespace elbowsim {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A frame read back, on its way to the writer thread.
struct Frame {
  int index = 0;
  std::vector<std::uint8_t> rgba;  // render size, rows bottom-up
  std::vector<PanelText> overlay;  // per panel
};

// A small blocking queue; close() wakes every waiter and makes pop() return
// nothing once empty.
template <class T>
class Channel {
 public:
  void push(T item) {
    std::lock_guard lock(mutex_);
    items_.push(std::move(item));
    ready_.notify_one();
  }
  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return !items_.empty() || closed_; });
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop();
    return item;
  }
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    ready_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::queue<T> items_;
  bool closed_ = false;
};

// Panel i of n across the frame, in pixels; the last one takes the remainder.
PixelRect panel_rect(int i, int n, int width, int height) {
  const int w = width / n;
  return {i * w, 0, i == n - 1 ? width - i * w : w, height};
}

// RGBA rows bottom-up at `scale` times the output size -> RGB rows top-down,
// averaging scale x scale blocks (scale 1 or 2).
void to_rgb(const std::uint8_t* rgba, int width, int height, int scale, std::uint8_t* rgb) {
  const std::size_t in_width = std::size_t(width) * std::size_t(scale);
  const int in_height = height * scale;
  for (int y = 0; y < height; ++y) {
    std::uint8_t* out = rgb + std::size_t(y) * std::size_t(width) * 3;
    const std::uint8_t* row = rgba + std::size_t(in_height - 1 - y * scale) * in_width * 4;
    if (scale == 1) {
      for (int x = 0; x < width; ++x, row += 4, out += 3)
        out[0] = row[0], out[1] = row[1], out[2] = row[2];
      continue;
    }
    const std::uint8_t* below = row - in_width * 4;  // the next row up in the image
    for (int x = 0; x < width; ++x, row += 8, below += 8, out += 3)
      for (int c = 0; c < 3; ++c)
        out[c] = std::uint8_t((row[c] + row[c + 4] + below[c] + below[c + 4] + 2) / 4);
  }
}

std::string frame_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index + 1);
  return name;
}

// The writer thread: takes read-back frames, converts them, draws the
// overlay and outputs them; hands the pixel buffers back for reuse. Joined
// (after the frames queued so far) when it goes out of scope.
class Writer {
 public:
  Writer(int width, int height, int scale, int panels, VideoEncoder* encoder,
         std::optional<fs::path> frames, std::size_t buffer_bytes)
      : width_(width),
        height_(height),
        scale_(scale),
        panels_(panels),
        encoder_(encoder),
        frames_(std::move(frames)),
        box_widths_(std::size_t(panels), 0) {
    for (int k = 0; k < 3; ++k) free_.push(std::vector<std::uint8_t>(buffer_bytes));
    thread_ = std::thread([this] { run(); });
  }
  ~Writer() { join(); }

  std::vector<std::uint8_t> buffer() { return *free_.pop(); }  // waits for a free one
  void push(Frame frame) { queue_.push(std::move(frame)); }
  bool failed() const { return failed_; }
  // Waits for the queued frames; rethrows what failed in the thread.
  void finish() {
    join();
    if (error_) std::rethrow_exception(error_);
  }
  double compose_seconds = 0, output_seconds = 0;  // read after finish()

 private:
  void join() {
    queue_.close();
    if (thread_.joinable()) thread_.join();
  }

  void run() {
    std::vector<std::uint8_t> rgb(std::size_t(width_) * std::size_t(height_) * 3);
    while (std::optional<Frame> frame = queue_.pop()) {
      if (!failed_) {
        try {
          write(*frame, rgb);
        } catch (...) {
          error_ = std::current_exception();
          failed_ = true;
        }
      }
      free_.push(std::move(frame->rgba));
    }
  }

  void write(const Frame& frame, std::vector<std::uint8_t>& rgb) {
    Clock::time_point start = Clock::now();
    to_rgb(frame.rgba.data(), width_, height_, scale_, rgb.data());
    for (int p = 0; p < panels_; ++p) {
      int& box = box_widths_[std::size_t(p)];  // overlay boxes only grow during a render
      const PanelText& text = frame.overlay[std::size_t(p)];
      if (text.inset) draw_inset_overlay(rgb.data(), width_, height_, *text.inset);
      box = draw_overlay(rgb.data(), width_, height_, panel_rect(p, panels_, width_, height_),
                         text.lines, box);
    }
    compose_seconds += seconds_since(start);
    start = Clock::now();
    if (encoder_) encoder_->write(rgb.data());
    if (frames_) write_png(*frames_ / frame_name(frame.index), width_, height_, rgb.data());
    output_seconds += seconds_since(start);
  }

  int width_, height_, scale_, panels_;
  VideoEncoder* encoder_;           // null: no video
  std::optional<fs::path> frames_;  // PNG folder, if any
  std::vector<int> box_widths_;     // per panel
  Channel<Frame> queue_;
  Channel<std::vector<std::uint8_t>> free_;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
  std::thread thread_;
};

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

RenderStats render_panels(const std::vector<const FrameSource*>& panels,
                          const RenderSettings& settings, const RenderRequest& request) {
  if (panels.empty()) throw std::invalid_argument("render_panels: no panels");
  const Clock::time_point start = Clock::now();
  RenderStats stats;
  stats.width = settings.width;
  stats.height = settings.height;
  stats.fps = settings.fps;

  // Outputs: a video needs ffmpeg; without it, PNG frames and the command.
  Outputs out;
  out.folder = request.folder;
  const fs::path ffmpeg = request.video ? find_on_path("ffmpeg") : fs::path();
  out.video = request.video && !ffmpeg.empty();
  stats.ffmpeg_missing = request.video && ffmpeg.empty();
  out.frames = request.frames || stats.ffmpeg_missing;
  if (out.frames) {
    out.frames_tmp = request.folder / "frames.tmp";
    fs::remove_all(out.frames_tmp);
    fs::create_directories(out.frames_tmp);
  }

  const int scale = settings.supersample ? 2 : 1;
  const int rw = settings.width * scale, rh = settings.height * scale;
  const int n = int(panels.size());
  OsmesaContext context;
  stats.gl = context.description();
  GlRenderer renderer(rw, rh, settings.msaa);
  stats.samples = renderer.samples();

  std::optional<VideoEncoder> encoder;
  if (out.video) {
    out.video_tmp = request.folder / "video.tmp.mp4";
    encoder.emplace(ffmpeg, out.video_tmp, settings.width, settings.height, settings.fps);
  }
  Writer writer(settings.width, settings.height, scale, n, encoder ? &*encoder : nullptr,
                out.frames ? std::optional(out.frames_tmp) : std::nullopt,
                std::size_t(rw) * std::size_t(rh) * 4);

  double end = 0;
  for (const FrameSource* p : panels) end = std::max(end, p->end_time());
  const std::vector<double> times = frame_times(end, settings.fps);
  std::queue<Frame> in_flight;  // drawn, read-back started, not yet fetched
  auto fetch_one = [&] {
    Clock::time_point t0 = Clock::now();
    Frame frame = std::move(in_flight.front());
    in_flight.pop();
    frame.rgba = writer.buffer();
    renderer.fetch(frame.rgba.data());
    stats.readback_seconds += seconds_since(t0);
    writer.push(std::move(frame));
  };
  // Frame k is drawn and its read-back started before frame k-1 is fetched
  // and handed to the writer.
  for (int k = 0; k < int(times.size()) && !writer.failed(); ++k) {
    const double t = times[std::size_t(k)];
    Clock::time_point t0 = Clock::now();
    Frame frame{k, {}, {}};
    std::vector<PanelFrame> prepared;
    for (int p = 0; p < n; ++p)
      prepared.push_back(prepare_panel(*panels[std::size_t(p)], t,
                                       panel_rect(p, n, settings.width, settings.height)));
    stats.scene_seconds += seconds_since(t0);
    t0 = Clock::now();
    renderer.begin_frame(prepared.front().scene.background);
    for (PanelFrame& f : prepared) {
      draw_panel(renderer, f, scale);
      frame.overlay.push_back(std::move(f.text));
    }
    stats.draw_seconds += seconds_since(t0);
    t0 = Clock::now();
    renderer.end_frame();
    stats.finish_seconds += seconds_since(t0);
    in_flight.push(std::move(frame));
    if (in_flight.size() > 1) fetch_one();
  }
  while (!in_flight.empty() && !writer.failed()) fetch_one();
  writer.finish();
  if (encoder) encoder->finish();
  out.commit();

  stats.frames = int(times.size());
  stats.video_written = out.video;
  stats.frames_written = out.frames;
  if (stats.ffmpeg_missing)
    stats.video_command = frames_to_video_command(request.folder / "frames",
                                                  request.folder / "video.mp4", settings.fps);
  stats.compose_seconds = writer.compose_seconds;
  stats.output_seconds = writer.output_seconds;
  stats.wall_seconds = seconds_since(start);
  return stats;
}

}  // namespace elbowsim
