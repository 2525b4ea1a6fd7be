// FXAA (render/fxaa.hpp) on synthetic frames: a straight edge drawn with
// one sample per pixel (a staircase) comes out closer to the edge's true
// coverage of each pixel; flat areas and gentle gradients are left alone.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "render/fxaa.hpp"

using namespace elbowsim;

namespace {

constexpr int kSize = 64;

// Grey frame, white where a pixel's centre is below the line y = y0 + slope x
// (rows top-down, so "below" is larger y); `transpose` swaps x and y (a
// steep edge instead of a shallow one).
std::vector<std::uint8_t> staircase(double y0, double slope, bool transpose) {
  std::vector<std::uint8_t> rgb(kSize * kSize * 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double px = transpose ? y : x, py = transpose ? x : y;
      const std::uint8_t v = py + 0.5 > y0 + slope * (px + 0.5) ? 230 : 20;
      for (int c = 0; c < 3; ++c) rgb[std::size_t((y * kSize + x) * 3 + c)] = v;
    }
  return rgb;
}

// The pixel's value if it were covered exactly: the share of its area below the line.
double coverage_value(int x, int y, double y0, double slope, bool transpose) {
  const double px = transpose ? y : x, py = transpose ? x : y;
  // The line's height over the pixel's column, integrated in 100 strips.
  double below = 0;
  for (int k = 0; k < 100; ++k) {
    const double line = y0 + slope * (px + (k + 0.5) / 100);
    below += std::clamp(py + 1 - line, 0.0, 1.0) / 100;
  }
  return 20 + 210 * below;
}

// Mean |value - exact coverage value| over the pixels the edge crosses (away from the border).
double edge_error(const std::vector<std::uint8_t>& rgb, double y0, double slope, bool transpose) {
  double sum = 0;
  int n = 0;
  for (int y = 4; y < kSize - 4; ++y)
    for (int x = 4; x < kSize - 4; ++x) {
      const double exact = coverage_value(x, y, y0, slope, transpose);
      if (exact <= 20.5 || exact >= 229.5) continue;  // not on the edge
      sum += std::abs(rgb[std::size_t((y * kSize + x) * 3)] - exact);
      ++n;
    }
  REQUIRE(n > 20);
  return sum / n;
}

}  // namespace

TEST_CASE("fxaa: a staircase edge moves toward the pixels' true coverage, shallow and steep") {
  for (const bool transpose : {false, true}) {
    for (const double slope : {0.13, 0.31}) {
      CAPTURE(transpose);
      CAPTURE(slope);
      std::vector<std::uint8_t> rgb = staircase(20.3, slope, transpose);
      const double before = edge_error(rgb, 20.3, slope, transpose);
      FxaaScratch scratch;
      const std::size_t changed = fxaa(rgb.data(), kSize, kSize, scratch);
      const double after = edge_error(rgb, 20.3, slope, transpose);
      MESSAGE("mean error on the edge: ", before, " -> ", after, " (", changed, " pixels changed)");
      CHECK(changed > 0);
      CHECK(after < 0.6 * before);
      // Grey stays grey: the three channels are blended alike.
      for (std::size_t i = 0; i < rgb.size(); i += 3) {
        CHECK(rgb[i] == rgb[i + 1]);
        CHECK(rgb[i] == rgb[i + 2]);
      }
    }
  }
}

TEST_CASE("fxaa: flat colour and a gentle gradient are left as they are") {
  std::vector<std::uint8_t> rgb(kSize * kSize * 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      std::uint8_t* p = &rgb[std::size_t((y * kSize + x) * 3)];
      p[0] = std::uint8_t(60 + x);  // 1 level per pixel: below FXAA's thresholds
      p[1] = std::uint8_t(100 + y / 2);
      p[2] = 180;
    }
  const std::vector<std::uint8_t> before = rgb;
  FxaaScratch scratch;
  CHECK(fxaa(rgb.data(), kSize, kSize, scratch) == 0);
  CHECK(rgb == before);
}
