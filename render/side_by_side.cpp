#include "render/side_by_side.hpp"

#include <chrono>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "render/png_writer.hpp"
#include "render/yuv.hpp"

namespace elbowsim {

SideBySide::SideBySide(std::vector<int> widths, int height, VideoEncoder* encoder,
                       std::optional<std::filesystem::path> frames)
    : widths_(std::move(widths)),
      height_(height),
      encoder_(encoder),
      frames_dir_(std::move(frames)),
      next_index_(widths_.size(), 0),
      done_(widths_.size(), false) {
  for (int w : widths_) {
    offsets_.push_back(width_);
    width_ += w;
  }
  if (frames_dir_) rgba_.assign(std::size_t(width_) * std::size_t(height_) * 4, 0);
  if (encoder_) panel_yuv_.resize(widths_.size());
}

namespace {

// Each plane of a panel's YUV 4:2:0 frame (w x h) copied into the composed
// frame's (total_w x h) at column x0 (even): Y at full size, U and V at
// half. From a composed frame instead (`from_composed`): the panel's part
// of it. Without `from`: black (all zero, as at the start).
void copy_planes(const std::uint8_t* from, bool from_composed, int w, int h, std::uint8_t* to,
                 int total_w, int x0) {
  const std::uint8_t* src = from;
  std::uint8_t* dst = to;
  for (const int k : {1, 2, 2}) {  // Y, U, V: sizes divided by k
    const std::size_t pw = std::size_t(w / k), tw = std::size_t(total_w / k);
    const std::size_t column = std::size_t(x0 / k), rows = std::size_t(h / k);
    for (std::size_t y = 0; y < rows; ++y) {
      std::uint8_t* out = dst + y * tw + column;
      if (!src)
        std::memset(out, 0, pw);
      else
        std::memcpy(out, src + (from_composed ? y * tw + column : y * pw), pw);
    }
    if (src) src += (from_composed ? tw : pw) * rows;
    dst += tw * rows;
  }
}

}  // namespace

void SideBySide::put(int panel, int index, ConstRgbaView frame, const std::uint8_t* yuv) {
  const std::size_t p = std::size_t(panel);
  if (frame.width != widths_[p] || frame.height != height_)
    throw std::invalid_argument("side by side: a panel's frame of another size than its panel's");
  if (encoder_ && !yuv) {  // converted here, before waiting for the lock
    panel_yuv_[p].resize(yuv420_bytes(widths_[p], height_));
    rgba_to_yuv420(frame, panel_yuv_[p].data());
    yuv = panel_yuv_[p].data();
  }
  std::unique_lock lock(mutex_);
  next_.wait(lock, [&] { return aborted_ || index_ == index; });
  if (aborted_) return;
  if (frames_dir_) {
    const RgbaView composed = top_down(rgba_.data(), width_, height_);
    for (int y = 0; y < height_; ++y)
      std::memcpy(composed.pixel(offsets_[p], y), frame.row(y), std::size_t(widths_[p]) * 4);
  }
  // Straight into the buffer the encoder takes the composed frame from.
  if (encoder_)
    copy_planes(yuv, false, widths_[p], height_, encoder_->next_yuv(), width_, offsets_[p]);
  next_index_[std::size_t(panel)] = index + 1;
  if (complete()) write_frame();
}

void SideBySide::done(int panel) {
  std::lock_guard lock(mutex_);
  done_[std::size_t(panel)] = true;
  // The others may have handed over the frame this panel does not have.
  if (!aborted_ && complete()) write_frame();
}

bool SideBySide::complete() const {
  bool any = false;  // a panel has it: all done and none has it is the end, not a frame
  for (std::size_t p = 0; p < done_.size(); ++p) {
    const bool has = next_index_[p] > index_;
    if (!has && !done_[p]) return false;
    any = any || has;
  }
  return any;
}

void SideBySide::abort() {
  std::lock_guard lock(mutex_);
  aborted_ = true;
  next_.notify_all();
}

void SideBySide::write_frame() {
  const auto start = std::chrono::steady_clock::now();
  try {
    if (encoder_) {
      // A panel that has ended keeps its last frame: its part of the
      // previous composed frame (none yet: black).
      for (std::size_t p = 0; p < widths_.size(); ++p)
        if (next_index_[p] <= index_)
          copy_planes(encoder_->yuv(), true, widths_[p], height_, encoder_->next_yuv(), width_,
                      offsets_[p]);
      encoder_->encode_next_yuv();
    }
    if (frames_dir_)
      write_png(*frames_dir_ / frame_file_name(index_), top_down(rgba_.data(), width_, height_));
    ++frames_;
  } catch (const std::exception& e) {
    error_ = e.what();
    aborted_ = true;
  }
  output_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++index_;
  next_.notify_all();
}

}  // namespace elbowsim
