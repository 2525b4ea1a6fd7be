#include "render/yuv.hpp"

#include <cstring>
#include <vector>

#include "render/vector_clones.hpp"

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

// The loops over every pixel are vector clones (vector_clones.hpp).

// One row of RGBA pixels -> the channels as separate rows (the loops below
// then vectorise), each pixel read as one word.
ELBOWSIM_VECTOR_CLONES void split(const std::uint8_t* rgba, std::size_t w, std::int32_t* r,
                                  std::int32_t* g, std::int32_t* b) {
  for (std::size_t x = 0; x < w; ++x) {
    std::uint32_t p;
    std::memcpy(&p, rgba + 4 * x, 4);
    r[x] = std::int32_t((p >> kRedShift) & 255);
    g[x] = std::int32_t((p >> kGreenShift) & 255);
    b[x] = std::int32_t((p >> kBlueShift) & 255);
  }
}

ELBOWSIM_VECTOR_CLONES void luma_row(const std::int32_t* r, const std::int32_t* g,
                                     const std::int32_t* b, std::size_t w, std::uint8_t* out) {
  for (std::size_t x = 0; x < w; ++x)
    out[x] = std::uint8_t(16 + ((kYr * r[x] + kYg * g[x] + kYb * b[x] + kHalf) >> 16));
}

// The two rows' channels summed (into `top`), for the chroma of 2x2 blocks.
ELBOWSIM_VECTOR_CLONES void add_rows(std::int32_t* top, const std::int32_t* bottom, std::size_t n) {
  for (std::size_t x = 0; x < n; ++x) top[x] += bottom[x];
}

// Chroma of 2x2 blocks from the column sums of two rows: sums of 4 pixels,
// so the coefficients carry a factor 4 (>> 18, not >> 16).
ELBOWSIM_VECTOR_CLONES void chroma_row(const std::int32_t* r, const std::int32_t* g,
                                       const std::int32_t* b, std::size_t half, std::uint8_t* u,
                                       std::uint8_t* v) {
  for (std::size_t x = 0; x < half; ++x) {
    const int sr = r[2 * x] + r[2 * x + 1], sg = g[2 * x] + g[2 * x + 1],
              sb = b[2 * x] + b[2 * x + 1];
    u[x] = std::uint8_t(128 + ((kUr * sr + kUg * sg + kUb * sb + (1 << 17)) >> 18));
    v[x] = std::uint8_t(128 + ((kVr * sr + kVg * sg + kVb * sb + (1 << 17)) >> 18));
  }
}

}  // namespace

void rgba_to_yuv420(ConstRgbaView frame, std::uint8_t* yuv) {
  const int width = frame.width, height = frame.height;
  const std::size_t w = std::size_t(width);
  std::uint8_t* y_plane = yuv;
  std::uint8_t* u_plane = yuv + w * std::size_t(height);
  std::uint8_t* v_plane = u_plane + (w / 2) * std::size_t(height / 2);
  // Two rows' channels as 32-bit integers, per thread (kept between frames).
  thread_local std::vector<std::int32_t> channels;
  channels.resize(6 * w);
  std::int32_t* c[2][3];
  for (int k = 0; k < 6; ++k) c[k / 3][k % 3] = channels.data() + std::size_t(k) * w;
  // Pairs of rows in the order they lie in memory (a frame read back from
  // GL lies bottom-up), so that the reads stream forward.
  const int pairs = height / 2;
  for (int k = 0; k < pairs; ++k) {
    const int pair = frame.stride < 0 ? pairs - 1 - k : k;
    for (int r = 0; r < 2; ++r) {
      const int y = 2 * pair + r;
      split(frame.row(y), w, c[r][0], c[r][1], c[r][2]);
      luma_row(c[r][0], c[r][1], c[r][2], w, y_plane + std::size_t(y) * w);
    }
    for (int ch = 0; ch < 3; ++ch) add_rows(c[0][ch], c[1][ch], w);
    chroma_row(c[0][0], c[0][1], c[0][2], w / 2, u_plane + std::size_t(pair) * (w / 2),
               v_plane + std::size_t(pair) * (w / 2));
  }
}

}  // namespace elbowsim
