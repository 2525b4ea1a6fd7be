#include "render/side_by_side.hpp"

#include <chrono>
#include <cstring>
#include <exception>

#include "render/png_writer.hpp"

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
  rgb_.assign(std::size_t(width_) * std::size_t(height_) * 3, 0);
}

void SideBySide::put(int panel, int index, const std::uint8_t* rgb) {
  std::unique_lock lock(mutex_);
  next_.wait(lock, [&] { return aborted_ || index_ == index; });
  if (aborted_) return;
  const std::size_t row = std::size_t(widths_[std::size_t(panel)]) * 3;
  const std::size_t stride = std::size_t(width_) * 3;
  const std::size_t offset = std::size_t(offsets_[std::size_t(panel)]) * 3;
  for (int y = 0; y < height_; ++y)
    std::memcpy(rgb_.data() + std::size_t(y) * stride + offset, rgb + std::size_t(y) * row, row);
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
    if (encoder_) encoder_->write(rgb_.data());
    if (frames_dir_)
      write_png(*frames_dir_ / frame_file_name(index_), width_, height_, rgb_.data());
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
