#include "render/yuv.hpp"

namespace elbowsim {

namespace {

// BT.709 (Kr 0.2126, Kb 0.0722) for 8-bit limited range, times 2^16:
//   Y  = 16  + (219/255) (0.2126 R + 0.7152 G + 0.0722 B)
//   Cb = 128 + (224/255) (B - Y') / 1.8556,   Cr = 128 + (224/255) (R - Y') / 1.5748
// with Y' = 0.2126 R + 0.7152 G + 0.0722 B, expanded into the coefficients below.
constexpr int kYr = 11966, kYg = 40254, kYb = 4064;    // sum 56284 = 65536 * 219 / 255
constexpr int kUr = -6596, kUg = -22189, kUb = 28785;  // sum 0 (grey has no colour)
constexpr int kVr = 28784, kVg = -26145, kVb = -2639;  // sum 0; 28784 = 65536 * 224 / 255 / 2
constexpr int kHalf = 1 << 15;

std::uint8_t luma(const std::uint8_t* p) {
  return std::uint8_t(16 + ((kYr * p[0] + kYg * p[1] + kYb * p[2] + kHalf) >> 16));
}

}  // namespace

void rgb_to_yuv420(const std::uint8_t* rgb, int width, int height, std::uint8_t* yuv) {
  const std::size_t w = std::size_t(width), row = w * 3;
  std::uint8_t* y_plane = yuv;
  std::uint8_t* u_plane = yuv + w * std::size_t(height);
  std::uint8_t* v_plane = u_plane + (w / 2) * std::size_t(height / 2);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* p = rgb + std::size_t(y) * row;
    std::uint8_t* out = y_plane + std::size_t(y) * w;
    for (std::size_t x = 0; x < w; ++x) out[x] = luma(p + 3 * x);
  }
  for (int y = 0; y < height / 2; ++y) {
    const std::uint8_t* top = rgb + std::size_t(2 * y) * row;
    const std::uint8_t* bottom = top + row;
    std::uint8_t* u = u_plane + std::size_t(y) * (w / 2);
    std::uint8_t* v = v_plane + std::size_t(y) * (w / 2);
    for (std::size_t x = 0; x < w / 2; ++x) {
      // Sums of 4 pixels: the coefficients then carry a factor 4 (>> 18, not >> 16).
      int s[3];
      for (int c = 0; c < 3; ++c)
        s[c] = top[6 * x + c] + top[6 * x + 3 + c] + bottom[6 * x + c] + bottom[6 * x + 3 + c];
      u[x] = std::uint8_t(128 + ((kUr * s[0] + kUg * s[1] + kUb * s[2] + (1 << 17)) >> 18));
      v[x] = std::uint8_t(128 + ((kVr * s[0] + kVg * s[1] + kVb * s[2] + (1 << 17)) >> 18));
    }
  }
}

}  // namespace elbowsim
