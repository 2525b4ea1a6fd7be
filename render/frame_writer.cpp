#include "render/frame_writer.hpp"

#include <chrono>
#include <cstring>

#include "render/png_writer.hpp"

namespace elbowsim {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

RgbaView output_frame(std::vector<std::uint8_t>& read, int width, int height, int scale,
                      std::vector<std::uint8_t>& averaged) {
  if (scale == 1) return bottom_up(read.data(), width, height);
  const std::size_t in_width = std::size_t(width) * std::size_t(scale);
  averaged.resize(std::size_t(width) * std::size_t(height) * 4);
  const RgbaView out = top_down(averaged.data(), width, height);
  const ConstRgbaView in = bottom_up(read.data(), int(in_width), height * scale);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = in.row(2 * y);
    const std::uint8_t* below = in.row(2 * y + 1);
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < width; ++x, row += 8, below += 8, o += 4)
      for (int c = 0; c < 4; ++c)
        o[c] = std::uint8_t((row[c] + row[c + 4] + below[c] + below[c + 4] + 2) / 4);
  }
  return out;
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
  std::vector<std::uint8_t> averaged;  // at scale 2
  while (std::optional<ReadFrame> frame = queue_.pop()) {
    if (!failed_) {
      try {
        write(*frame, averaged);
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

void FrameWriter::write(ReadFrame& frame, std::vector<std::uint8_t>& averaged) {
  Clock::time_point start = Clock::now();
  const RgbaView out = output_frame(frame.rgba, width_, height_, scale_, averaged);
  if (fxaa_) fxaa(out, fxaa_scratch_);
  if (frame.text.inset) inset_marks_.draw(out, *frame.text.inset);
  box_width_ = draw_overlay(out, {0, 0, width_, height_}, frame.text.lines, box_width_);
  compose_seconds += seconds_since(start);
  start = Clock::now();
  if (out_.encoder) out_.encoder->write(out);
  if (out_.frames) write_png(*out_.frames / frame_file_name(frame.index), out);
  if (out_.side_by_side)
    out_.side_by_side->put(out_.panel, frame.index, out,
                           out_.encoder ? out_.encoder->yuv() : nullptr);
  output_seconds += seconds_since(start);
}

}  // namespace elbowsim
