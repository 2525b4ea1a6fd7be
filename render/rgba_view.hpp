// A frame in memory as the writer's passes see it: 4 bytes per pixel (red,
// green, blue, and a fourth byte no pass reads), rows `stride` bytes apart
// from the top row down. The stride may be negative: GL reads a frame back
// bottom-up, and a view that starts at its last row walks it top-down where
// it lies, so FXAA, the overlay and the YUV conversion work in the read-back
// buffer itself (no flipped RGB copy; 4-byte pixels also split into channels
// with shifts, not byte shuffles).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace elbowsim {

template <class Byte>
struct BasicRgbaView {
  Byte* top = nullptr;        // the top row's first byte
  int width = 0, height = 0;  // [px]
  std::ptrdiff_t stride = 0;  // [bytes] from a row to the one below it

  Byte* row(int y) const { return top + std::ptrdiff_t(y) * stride; }
  Byte* pixel(int x, int y) const { return row(y) + 4 * std::ptrdiff_t(x); }

  // A writable view is also a read-only one.
  template <class Other, class = std::enable_if_t<std::is_const_v<Byte> && !std::is_const_v<Other>>>
  BasicRgbaView(const BasicRgbaView<Other>& v)  // NOLINT: implicit on purpose
      : top(v.top), width(v.width), height(v.height), stride(v.stride) {}
  BasicRgbaView() = default;
  BasicRgbaView(Byte* top_row, int w, int h, std::ptrdiff_t row_stride)
      : top(top_row), width(w), height(h), stride(row_stride) {}
};

using RgbaView = BasicRgbaView<std::uint8_t>;
using ConstRgbaView = BasicRgbaView<const std::uint8_t>;

// Rows top-down, packed (stride 4 * width).
template <class Byte>
BasicRgbaView<Byte> top_down(Byte* pixels, int width, int height) {
  return {pixels, width, height, 4 * std::ptrdiff_t(width)};
}

// Rows bottom-up, packed, as GL reads them back: viewed top-down.
template <class Byte>
BasicRgbaView<Byte> bottom_up(Byte* pixels, int width, int height) {
  const std::ptrdiff_t row = 4 * std::ptrdiff_t(width);
  return {height > 0 ? pixels + (std::ptrdiff_t(height) - 1) * row : pixels, width, height, -row};
}

// The channels' places in a pixel read as one native 32-bit word.
inline constexpr int kRedShift = std::endian::native == std::endian::little ? 0 : 24;
inline constexpr int kGreenShift = std::endian::native == std::endian::little ? 8 : 16;
inline constexpr int kBlueShift = std::endian::native == std::endian::little ? 16 : 8;

}  // namespace elbowsim
