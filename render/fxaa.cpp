#include "render/fxaa.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "render/vector_clones.hpp"

namespace elbowsim {

namespace {

// FXAA 3.11's thresholds, its "high quality" ones: a pixel is on an edge if
// the luma range of it and its 4 neighbours is at least kEdgeMin and at least
// kEdgeRelative of their largest luma (luma in 0..255 here: 8 = 0.0312 x 255,
// 1/8 = 0.125). kSubpix: how much of its neighbours' average a lone pixel
// (a thin line, a corner) takes, FXAA's default 0.75.
constexpr int kEdgeMin = 8;
constexpr int kEdgeRelativeShift = 3;
constexpr float kSubpix = 0.75f;
// The walk along an edge: steps in pixels (integers, so each sample is the
// mean of two pixels), 25 pixels each way at most; the luma plane has a
// border of kPad pixels (copies of the frame's outermost ones, a texture's
// clamp to edge), so the walk never leaves it.
constexpr int kSteps[] = {1, 1, 1, 1, 1, 2, 2, 2, 2, 4, 8};
constexpr int kPad = 27;

// The two loops over every pixel are vector clones (vector_clones.hpp).

// Luma with Rec. 601 weights in 1/256 (FXAA needs an ordering of
// brightness, not a standard), each pixel read as one word, so that it vectorises.
ELBOWSIM_VECTOR_CLONES void luma_row(const std::uint8_t* rgba, int width, std::uint8_t* luma) {
  for (int x = 0; x < width; ++x) {
    std::uint32_t p;
    std::memcpy(&p, rgba + 4 * x, 4);
    const std::uint32_t r = (p >> kRedShift) & 255, g = (p >> kGreenShift) & 255,
                        b = (p >> kBlueShift) & 255;
    luma[x] = std::uint8_t((77 * r + 150 * g + 29 * b) >> 8);
  }
}

// The padded luma plane: (width + 2 kPad) x (height + 2 kPad), the frame at (kPad, kPad).
void padded_luma(ConstRgbaView frame, std::vector<std::uint8_t>& l) {
  const int width = frame.width, height = frame.height;
  const std::size_t stride = std::size_t(width + 2 * kPad);
  l.resize(stride * std::size_t(height + 2 * kPad));
  for (int k = 0; k < height; ++k) {
    const int y = frame.stride < 0 ? height - 1 - k : k;  // in memory order: reads stream forward
    std::uint8_t* row = l.data() + std::size_t(y + kPad) * stride;
    luma_row(frame.row(y), width, row + kPad);
    std::fill(row, row + kPad, row[kPad]);
    std::fill(row + kPad + width, row + stride, row[kPad + width - 1]);
  }
  const auto first = l.begin() + std::ptrdiff_t(kPad * stride);
  const auto last = l.begin() + std::ptrdiff_t((height + kPad - 1) * stride);
  for (int y = 0; y < kPad; ++y) {
    std::copy(first, first + std::ptrdiff_t(stride), l.begin() + std::ptrdiff_t(y * stride));
    std::copy(last, last + std::ptrdiff_t(stride),
              l.begin() + std::ptrdiff_t((height + kPad + y) * stride));
  }
}

// Which pixels of a luma row (`width` pixels from `row`, rows `stride`
// apart) are on an edge: the early exit of FXAA, in bytes so that the loop
// vectorises.
ELBOWSIM_VECTOR_CLONES void edge_mask(const std::uint8_t* row, std::size_t stride, int width,
                                      std::uint8_t* mask) {
  const std::uint8_t *up = row - stride, *down = row + stride;
  for (int x = 0; x < width; ++x) {
    const std::uint8_t m = row[x], n = up[x], s = down[x], e = row[x + 1], w = row[x - 1];
    const std::uint8_t hi = std::max(std::max(std::max(m, n), std::max(s, e)), w);
    const std::uint8_t lo = std::min(std::min(std::min(m, n), std::min(s, e)), w);
    const std::uint8_t threshold =
        std::max(std::uint8_t(kEdgeMin), std::uint8_t(hi >> kEdgeRelativeShift));
    mask[x] = std::uint8_t(hi - lo) >= threshold;
  }
}

// The walk from luma index i along `along` (+-1 pixel or +-1 row): how far
// [px] to where the mean of the edge's two sides (i + k along and the pixel
// `across` from it) has moved from the mean at i by at least a quarter of
// the step across the edge (the edge ends or turns), or to the last step.
// Sums of two lumas: `twice_mean` is twice the mean at i, `gradient` that
// step, `end` gets the sum there minus twice_mean.
int walk(const std::uint8_t* l, std::ptrdiff_t i, std::ptrdiff_t along, std::ptrdiff_t across,
         int twice_mean, int gradient, int& end) {
  int k = 0;
  for (int step : kSteps) {
    k += step;
    const std::ptrdiff_t j = i + k * along;
    end = l[j] + l[j + across] - twice_mean;
    if (2 * std::abs(end) >= gradient) break;
  }
  return k;
}

// FXAA 3.11 quality for the edge pixel at luma index i (rows `stride` apart):
// the blend weight (0..0.75) toward its neighbour `across` (set here).
float edge_blend(const std::uint8_t* l, std::ptrdiff_t i, std::ptrdiff_t stride,
                 std::ptrdiff_t& across) {
  const int m = l[i], n = l[i - stride], s = l[i + stride], w = l[i - 1], e = l[i + 1];
  const int nw = l[i - stride - 1], ne = l[i - stride + 1];
  const int sw = l[i + stride - 1], se = l[i + stride + 1];
  const int range = std::max({m, n, s, w, e}) - std::min({m, n, s, w, e});
  // Second differences across rows vs across columns: which way the edge runs.
  const int horizontal =
      std::abs(nw + sw - 2 * w) + 2 * std::abs(n + s - 2 * m) + std::abs(ne + se - 2 * e);
  const int vertical =
      std::abs(nw + ne - 2 * n) + 2 * std::abs(w + e - 2 * m) + std::abs(sw + se - 2 * s);
  const bool along_x = horizontal >= vertical;
  // The sub-pixel term: a pixel unlike its whole neighbourhood (lone dots, thin lines).
  const int contrast = std::abs(2 * (n + s + w + e) + nw + ne + sw + se - 12 * m);
  const float c = std::min(float(contrast) / float(12 * range), 1.0f);
  const float f = (3 - 2 * c) * c * c;
  const float subpix = f * f * kSubpix;
  // The side across the edge with the larger step in luma.
  const int before = along_x ? n : w, after = along_x ? s : e;
  const bool toward_before = std::abs(before - m) >= std::abs(after - m);
  const int other = toward_before ? before : after;
  const std::ptrdiff_t step = along_x ? 1 : stride;
  across = (along_x ? stride : 1) * (toward_before ? -1 : 1);
  const int twice_mean = m + other;
  const int gradient = std::max(std::abs(before - m), std::abs(after - m));
  int end_n = 0, end_p = 0;
  const int dist_n = walk(l, i, -step, across, twice_mean, gradient, end_n);
  const int dist_p = walk(l, i, step, across, twice_mean, gradient, end_p);
  // Blend only toward the nearer end whose luma moved the other way from m
  // (the staircase's step is on this pixel's side), by 1/2 at the end, 0 mid-span.
  const bool m_below = m < other;
  const bool nearer_n = dist_n < dist_p;
  const bool good = ((nearer_n ? end_n : end_p) < 0) != m_below;
  const float offset =
      good ? 0.5f - float(std::min(dist_n, dist_p)) / float(dist_n + dist_p) : 0.0f;
  return std::max(offset, subpix);
}

}  // namespace

std::size_t fxaa(RgbaView frame, FxaaScratch& scratch) {
  const int width = frame.width, height = frame.height;
  if (width < 1 || height < 1) return 0;
  padded_luma(frame, scratch.luma);
  scratch.mask.resize(std::size_t(width));
  scratch.blends.clear();
  const std::ptrdiff_t stride = width + 2 * kPad;
  const std::uint8_t* l = scratch.luma.data();
  for (int y = 0; y < height; ++y) {
    const std::ptrdiff_t row = (y + kPad) * stride + kPad;
    edge_mask(l + row, std::size_t(stride), width, scratch.mask.data());
    for (int x = 0; x < width; ++x) {
      if (std::uint64_t eight; x + 8 <= width) {  // most pixels are not on an edge
        std::memcpy(&eight, &scratch.mask[std::size_t(x)], 8);
        if (eight == 0) {
          x += 7;
          continue;
        }
      }
      if (!scratch.mask[std::size_t(x)]) continue;
      std::ptrdiff_t across = 0;
      const float t = edge_blend(l, row + x, stride, across);
      if (t <= 0) continue;
      // The neighbour across, in the frame (clamped at its border, like the luma).
      const int nx = std::clamp(x + int(across == 1) - int(across == -1), 0, width - 1);
      const int ny = std::clamp(y + int(across > 1) - int(across < -1), 0, height - 1);
      const std::uint8_t* a = frame.pixel(x, y);
      const std::uint8_t* b = frame.pixel(nx, ny);
      FxaaScratch::Blend blend{std::int32_t(a - frame.top), {}};
      for (int k = 0; k < 3; ++k)
        blend.rgb[k] = std::uint8_t(float(a[k]) + t * float(b[k] - a[k]) + 0.5f);
      scratch.blends.push_back(blend);
    }
  }
  for (const FxaaScratch::Blend& b : scratch.blends) std::memcpy(frame.top + b.offset, b.rgb, 3);
  return scratch.blends.size();
}

}  // namespace elbowsim
