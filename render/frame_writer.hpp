// The writer thread of one render: takes frames as GL read them back,
// finishes them where they lie (RGBA rows bottom-up, viewed top-down:
// rgba_view.hpp; at a render scale of 2 averaged down first), FXAA, the
// inset's marks and the overlay text, and hands them on: to the video encoder, as PNG files, and to
// a side-by-side composition. Hands the pixel buffers back for reuse.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <queue>
#include <string>
#include <thread>
#include <vector>

#include "render/fxaa.hpp"
#include "render/overlay.hpp"
#include "render/rgba_view.hpp"
#include "render/side_by_side.hpp"
#include "render/video_encoder.hpp"

namespace elbowsim {

// What the writer thread draws over a frame: the text box and the inset's marks.
struct PanelText {
  std::vector<std::string> lines;
  std::optional<InsetOverlay> inset;  // output pixels of the frame
};

// A frame read back, on its way to the writer thread.
struct ReadFrame {
  int index = 0;
  std::vector<std::uint8_t> rgba;  // render size, rows bottom-up
  PanelText text;
};

// A frame `read` back from GL (RGBA rows bottom-up, `scale` times the
// output size width x height) as the output frame: at scale 1 `read` itself
// viewed top-down; at scale 2 its 2 x 2 blocks averaged into `averaged`
// (sized here), rows top-down.
RgbaView output_frame(std::vector<std::uint8_t>& read, int width, int height, int scale,
                      std::vector<std::uint8_t>& averaged);

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

// Where a writer's finished frames go; any may be absent.
struct FrameOutputs {
  VideoEncoder* encoder = nullptr;
  std::optional<std::filesystem::path> frames;  // PNG folder
  SideBySide* side_by_side = nullptr;
  int panel = 0;  // this render's panel in side_by_side
};

// Joined (after the frames queued so far) when it goes out of scope.
class FrameWriter {
 public:
  // Output frames width x height [px], read back at `scale` times that;
  // `fxaa`: anti-alias them (fxaa.hpp) before the overlay goes on.
  FrameWriter(int width, int height, int scale, bool fxaa, FrameOutputs outputs);
  ~FrameWriter() { join(); }

  std::vector<std::uint8_t> buffer() { return *free_.pop(); }  // waits for a free one
  void push(ReadFrame frame) { queue_.push(std::move(frame)); }
  // No more frames: the thread ends after the queued ones and tells the
  // side-by-side this panel is done (whose other panels wait for it until then).
  void close() { queue_.close(); }
  bool failed() const { return failed_; }
  // Waits for the queued frames; rethrows what failed in the thread.
  void finish();
  double compose_seconds = 0, output_seconds = 0;  // read after finish()

 private:
  void join();
  void run();
  void write(ReadFrame& frame, std::vector<std::uint8_t>& averaged);

  int width_, height_, scale_;
  bool fxaa_;
  FxaaScratch fxaa_scratch_;
  FrameOutputs out_;
  int box_width_ = 0;  // the overlay box only grows during a render
  InsetOverlayLayer inset_marks_;
  Channel<ReadFrame> queue_;
  Channel<std::vector<std::uint8_t>> free_;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
  std::thread thread_;
};

}  // namespace elbowsim
