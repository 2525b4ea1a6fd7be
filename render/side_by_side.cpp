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
  if (encoder_) {
    yuv_.assign(yuv420_bytes(width_, height_), 0);
    panel_yuv_.resize(widths_.size());
  }
}

namespace {

// Each plane of a panel's YUV 4:2:0 frame (w x h) copied into the composed
// frame's (total_w x h) at column x0 (even): Y at full size, U and V at half.
void copy_planes(const std::uint8_t* from, int w, int h, std::uint8_t* to, int total_w, int x0) {
  const std::uint8_t* src = from;
  std::uint8_t* dst = to;
  for (const int k : {1, 2, 2}) {  // Y, U, V: sizes divided by k
    const std::size_t pw = std::size_t(w / k), tw = std::size_t(total_w / k);
    for (int y = 0; y < h / k; ++y)
      std::memcpy(dst + std::size_t(y) * tw + std::size_t(x0 / k), src + std::size_t(y) * pw, pw);
    src += pw * std::size_t(h / k);
    dst += tw * std::size_t(h / k);
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
  if (encoder_) copy_planes(yuv, widths_[p], height_, yuv_.data(), width_, offsets_[p]);
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
    if (encoder_) encoder_->write_yuv(yuv_.data());
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
