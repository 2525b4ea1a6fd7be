// The frames of several renders placed side by side, left to right, as one
// video and/or PNG frames (the comparison of a scenario's variants): each
// render's writer thread hands over its finished frames, overlay included,
// and frame k is written once every render still running has handed over
// its frame k. A render that has ended leaves its last frame in place, so
// the composition lasts as long as the longest render. The panels are the
// renders' own frames, copied: nothing is drawn twice.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "render/rgba_view.hpp"
#include "render/video_encoder.hpp"

namespace elbowsim {

class SideBySide {
 public:
  // Panels `widths` [px] wide, all `height` [px] high; outputs to `encoder`
  // (may be null) and as PNG frames into `frames` (when given), both owned
  // by the caller.
  SideBySide(std::vector<int> widths, int height, VideoEncoder* encoder,
             std::optional<std::filesystem::path> frames);

  int width() const { return width_; }
  int height() const { return height_; }

  // Panel `panel`'s frame `index` (its width x height; `yuv`: the same in
  // YUV 4:2:0 when the caller has it, else null):
  // waits until frame `index` is the one being composed, copies the panel
  // in and, when it completes the frame, writes it. Frames of a panel come
  // in order from 0. Returns at once after abort(). The video is composed
  // from the panels' YUV planes: the panels' widths are even, so no chroma
  // sample straddles a seam and the planes joined row by row are the YUV of
  // the RGB frames joined, without converting it again.
  void put(int panel, int index, ConstRgbaView frame, const std::uint8_t* yuv = nullptr);
  // The panel has no more frames.
  void done(int panel);
  // Stops: wakes every waiter; put() does nothing from now on.
  void abort();

  // After every panel is done (or after abort()): frames written, the first
  // output error ("" if none), time spent writing [s].
  int frames() const { return frames_; }
  const std::string& error() const { return error_; }
  double output_seconds() const { return output_seconds_; }

 private:
  // With the lock held: whether every panel has handed over the frame being
  // composed or has ended before it (its last frame stays in place).
  bool complete() const;
  void write_frame();  // with the lock held, once complete

  std::vector<int> offsets_;  // [px] of each panel's left edge
  std::vector<int> widths_;
  int width_ = 0, height_;
  VideoEncoder* encoder_;
  std::optional<std::filesystem::path> frames_dir_;
  std::vector<std::uint8_t> rgba_;  // the composed frame, rows top-down (for PNG frames)
  // Each panel's YUV when its caller has none (touched by that panel's caller only).
  std::vector<std::vector<std::uint8_t>> panel_yuv_;
  std::mutex mutex_;
  std::condition_variable next_;
  int index_ = 0;                // frame being composed
  std::vector<int> next_index_;  // of each panel: the frame it hands over next
  std::vector<bool> done_;       // of each panel: no more frames
  bool aborted_ = false;
  int frames_ = 0;
  std::string error_;
  double output_seconds_ = 0;
};

}  // namespace elbowsim
