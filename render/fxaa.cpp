#include "render/fxaa.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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
// mean of two pixels), 25 pixels each way at most.
constexpr int kSteps[] = {1, 1, 1, 1, 1, 2, 2, 2, 2, 4, 8};

// Luma, Rec. 601 weights in 1/256 (FXAA needs an ordering of brightness, not a standard).
void compute_luma(const std::uint8_t* rgb, std::size_t n, std::uint8_t* luma) {
  for (std::size_t i = 0; i < n; ++i)
    luma[i] = std::uint8_t((77 * rgb[3 * i] + 150 * rgb[3 * i + 1] + 29 * rgb[3 * i + 2]) >> 8);
}

// Luma in 0..1 with coordinates clamped to the frame (a texture's clamp to edge).
struct Luma {
  const std::uint8_t* l;
  int w, h;
  float at(int x, int y) const {
    x = std::clamp(x, 0, w - 1);
    y = std::clamp(y, 0, h - 1);
    return l[std::size_t(y) * std::size_t(w) + std::size_t(x)] * (1.0f / 255.0f);
  }
};

// Which pixels of row y (not the frame's first or last) are on an edge: the
// early exit of FXAA, in bytes so that the loop vectorises.
void edge_mask(const std::uint8_t* l, int y, int width, std::uint8_t* mask) {
  const std::size_t w = std::size_t(width);
  const std::uint8_t* row = l + std::size_t(y) * w;
  const std::uint8_t *up = row - w, *down = row + w;
  for (std::size_t x = 1; x + 1 < w; ++x) {
    const std::uint8_t m = row[x], n = up[x], s = down[x], e = row[x + 1], west = row[x - 1];
    const std::uint8_t hi = std::max(std::max(std::max(m, n), std::max(s, e)), west);
    const std::uint8_t lo = std::min(std::min(std::min(m, n), std::min(s, e)), west);
    const std::uint8_t threshold =
        std::max(std::uint8_t(kEdgeMin), std::uint8_t(hi >> kEdgeRelativeShift));
    mask[x] = std::uint8_t(hi - lo) >= threshold;
  }
}

// Distance [px] along the edge to its end in one direction (dir -1 or +1):
// where the mean of the edge's two sides has moved from `average` by at
// least `gradient` (the edge ends or turns), or the last step; `end` gets
// that mean minus `average`.
int walk(const Luma& L, int x, int y, int ax, int ay, int cx, int cy, float average, float gradient,
         float& end) {
  int k = 0;
  for (int step : kSteps) {
    k += step;
    const int px = x + k * ax, py = y + k * ay;
    end = 0.5f * (L.at(px, py) + L.at(px + cx, py + cy)) - average;
    if (std::abs(end) >= gradient) break;
  }
  return k;
}

// FXAA 3.11 quality for one edge pixel: how far toward which neighbour to blend.
// Returns the blend weight (0..0.75) and sets (dx, dy) to the neighbour.
float edge_blend(const Luma& L, int x, int y, int& dx, int& dy) {
  const float m = L.at(x, y), n = L.at(x, y - 1), s = L.at(x, y + 1);
  const float w = L.at(x - 1, y), e = L.at(x + 1, y);
  const float nw = L.at(x - 1, y - 1), ne = L.at(x + 1, y - 1);
  const float sw = L.at(x - 1, y + 1), se = L.at(x + 1, y + 1);
  const float range = std::max({m, n, s, w, e}) - std::min({m, n, s, w, e});
  // Second differences across rows vs across columns: which way the edge runs.
  const float horizontal =
      std::abs(nw + sw - 2 * w) + 2 * std::abs(n + s - 2 * m) + std::abs(ne + se - 2 * e);
  const float vertical =
      std::abs(nw + ne - 2 * n) + 2 * std::abs(w + e - 2 * m) + std::abs(sw + se - 2 * s);
  const bool along_x = horizontal >= vertical;
  // The sub-pixel term: a pixel unlike its whole neighbourhood (lone dots, thin lines).
  const float c =
      std::min(std::abs((2 * (n + s + w + e) + nw + ne + sw + se) / 12 - m) / range, 1.0f);
  const float f = (3 - 2 * c) * c * c;
  const float subpix = f * f * kSubpix;
  // The side across the edge with the larger step in luma.
  const float before = along_x ? n : w, after = along_x ? s : e;
  const bool toward_before = std::abs(before - m) >= std::abs(after - m);
  const int side = toward_before ? -1 : 1;
  const int cx = along_x ? 0 : side, cy = along_x ? side : 0;
  const int ax = along_x ? 1 : 0, ay = along_x ? 0 : 1;
  const float average = 0.5f * (m + (toward_before ? before : after));
  const float gradient = 0.25f * std::max(std::abs(before - m), std::abs(after - m));
  float end_n = 0, end_p = 0;
  const int dist_n = walk(L, x, y, -ax, -ay, cx, cy, average, gradient, end_n);
  const int dist_p = walk(L, x, y, ax, ay, cx, cy, average, gradient, end_p);
  // Blend only toward the nearer end whose luma moved the other way from m
  // (the staircase's step is on this pixel's side), by 1/2 at the end, 0 mid-span.
  const bool m_below = m - average < 0;
  const bool nearer_n = dist_n < dist_p;
  const bool good = ((nearer_n ? end_n : end_p) < 0) != m_below;
  const float offset = good ? 0.5f - float(std::min(dist_n, dist_p)) / float(dist_n + dist_p) : 0;
  dx = cx;
  dy = cy;
  return std::max(offset, subpix);
}

}  // namespace

std::size_t fxaa(std::uint8_t* rgb, int width, int height, FxaaScratch& scratch) {
  if (width < 3 || height < 3) return 0;
  const std::size_t w = std::size_t(width), n = w * std::size_t(height);
  scratch.luma.resize(n);
  scratch.blends.clear();
  compute_luma(rgb, n, scratch.luma.data());
  const std::uint8_t* l = scratch.luma.data();
  const Luma L{l, width, height};
  scratch.mask.assign(w, 0);
  for (int y = 1; y + 1 < height; ++y) {
    edge_mask(l, y, width, scratch.mask.data());
    const std::size_t row = std::size_t(y) * w;
    for (int x = 1; x + 1 < width; ++x) {
      if (!scratch.mask[std::size_t(x)]) continue;
      const std::size_t i = row + std::size_t(x);
      int dx = 0, dy = 0;
      const float t = edge_blend(L, x, y, dx, dy);
      if (t <= 0) continue;
      const std::uint8_t* a = rgb + 3 * i;
      const std::uint8_t* b = a + 3 * (dy * std::ptrdiff_t(w) + dx);
      FxaaScratch::Blend blend{std::uint32_t(i), {}};
      for (int k = 0; k < 3; ++k)
        blend.rgb[k] = std::uint8_t(std::lround(float(a[k]) + t * float(b[k] - a[k])));
      scratch.blends.push_back(blend);
    }
  }
  for (const FxaaScratch::Blend& b : scratch.blends)
    for (int k = 0; k < 3; ++k) rgb[3 * std::size_t(b.pixel) + std::size_t(k)] = b.rgb[k];
  return scratch.blends.size();
}

}  // namespace elbowsim
