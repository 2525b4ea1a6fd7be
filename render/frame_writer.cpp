#include "render/frame_writer.hpp"

#include <chrono>
#include <cstring>

#include "render/png_writer.hpp"
#include "render/vector_clones.hpp"

namespace elbowsim {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One row of RGBA pixels -> RGB (a byte loop cost 1 ns per pixel, 5 % of a
// render). Four pixels at a time by a byte shuffle where the compiler has
// one (GCC's vector extension: a vector clone, vector_clones.hpp), each
// 16-byte store's last 4 bytes overwritten by the next; then a pixel at a
// time as 4 bytes, the next overwriting the alpha; the last as 3.
#if defined(__GNUC__) && !defined(__clang__)
using Bytes16 = std::uint8_t __attribute__((vector_size(16)));
ELBOWSIM_VECTOR_CLONES void drop_alpha(const std::uint8_t* rgba, int width, std::uint8_t* rgb) {
  const Bytes16 pick = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 15, 15, 15, 15};
  int x = 0;
  for (; x + 6 <= width; x += 4) {  // the store ends 2 bytes short of the row's end, or more
    Bytes16 four;
    std::memcpy(&four, rgba + 4 * x, 16);
    const Bytes16 three = __builtin_shuffle(four, pick);
    std::memcpy(rgb + 3 * x, &three, 16);
  }
  for (; x + 1 < width; ++x) std::memcpy(rgb + 3 * x, rgba + 4 * x, 4);
  if (x < width) std::memcpy(rgb + 3 * x, rgba + 4 * x, 3);
}
#else
void drop_alpha(const std::uint8_t* rgba, int width, std::uint8_t* rgb) {
  int x = 0;
  for (; x + 1 < width; ++x) std::memcpy(rgb + 3 * x, rgba + 4 * x, 4);
  if (x < width) std::memcpy(rgb + 3 * x, rgba + 4 * x, 3);
}
#endif

}  // namespace

void to_rgb(const std::uint8_t* rgba, int width, int height, int scale, std::uint8_t* rgb) {
  const std::size_t in_width = std::size_t(width) * std::size_t(scale);
  const int in_height = height * scale;
  for (int y = 0; y < height; ++y) {
    std::uint8_t* out = rgb + std::size_t(y) * std::size_t(width) * 3;
    const std::uint8_t* row = rgba + std::size_t(in_height - 1 - y * scale) * in_width * 4;
    if (scale == 1) {
      drop_alpha(row, width, out);
      continue;
    }
    const std::uint8_t* below = row - in_width * 4;  // the next row up in the image
    for (int x = 0; x < width; ++x, row += 8, below += 8, out += 3)
      for (int c = 0; c < 3; ++c)
        out[c] = std::uint8_t((row[c] + row[c + 4] + below[c] + below[c + 4] + 2) / 4);
  }
}

FrameWriter::FrameWriter(int width, int height, int scale, bool fxaa, FrameOutputs outputs)
    : width_(width), height_(height), scale_(scale), fxaa_(fxaa), out_(std::move(outputs)) {
  const std::size_t bytes =
      std::size_t(width) * std::size_t(height) * std::size_t(scale * scale) * 4;
  for (int k = 0; k < 3; ++k) free_.push(std::vector<std::uint8_t>(bytes));
  thread_ = std::thread([this] { run(); });
}

void FrameWriter::finish() {
  join();
  if (error_) std::rethrow_exception(error_);
}

void FrameWriter::join() {
  queue_.close();
  if (thread_.joinable()) thread_.join();
}

void FrameWriter::run() {
  std::vector<std::uint8_t> rgb(std::size_t(width_) * std::size_t(height_) * 3);
  while (std::optional<ReadFrame> frame = queue_.pop()) {
    if (!failed_) {
      try {
        write(*frame, rgb);
      } catch (...) {
        error_ = std::current_exception();
        failed_ = true;
        // No frames from here on: the composition must not wait for them.
        if (out_.side_by_side) out_.side_by_side->abort();
      }
    }
    free_.push(std::move(frame->rgba));
  }
  if (out_.side_by_side) out_.side_by_side->done(out_.panel);
}

void FrameWriter::write(const ReadFrame& frame, std::vector<std::uint8_t>& rgb) {
  Clock::time_point start = Clock::now();
  to_rgb(frame.rgba.data(), width_, height_, scale_, rgb.data());
  if (fxaa_) fxaa(rgb.data(), width_, height_, fxaa_scratch_);
  if (frame.text.inset) draw_inset_overlay(rgb.data(), width_, height_, *frame.text.inset);
  box_width_ = draw_overlay(rgb.data(), width_, height_, {0, 0, width_, height_}, frame.text.lines,
                            box_width_);
  compose_seconds += seconds_since(start);
  start = Clock::now();
  if (out_.encoder) out_.encoder->write(rgb.data());
  if (out_.frames)
    write_png(*out_.frames / frame_file_name(frame.index), width_, height_, rgb.data());
  if (out_.side_by_side)
    out_.side_by_side->put(out_.panel, frame.index, rgb.data(),
                           out_.encoder ? out_.encoder->yuv() : nullptr);
  output_seconds += seconds_since(start);
}

}  // namespace elbowsim
