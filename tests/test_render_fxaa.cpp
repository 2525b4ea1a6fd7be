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
// RGBA, the fourth byte 77 (FXAA must leave it as it is).
std::vector<std::uint8_t> staircase(double y0, double slope, bool transpose) {
  std::vector<std::uint8_t> rgba(kSize * kSize * 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double px = transpose ? y : x, py = transpose ? x : y;
      const std::uint8_t v = py + 0.5 > y0 + slope * (px + 0.5) ? 230 : 20;
      for (int c = 0; c < 3; ++c) rgba[std::size_t((y * kSize + x) * 4 + c)] = v;
      rgba[std::size_t((y * kSize + x) * 4 + 3)] = 77;
    }
  return rgba;
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
double edge_error(const std::vector<std::uint8_t>& rgba, double y0, double slope, bool transpose) {
  double sum = 0;
  int n = 0;
  for (int y = 4; y < kSize - 4; ++y)
    for (int x = 4; x < kSize - 4; ++x) {
      const double exact = coverage_value(x, y, y0, slope, transpose);
      if (exact <= 20.5 || exact >= 229.5) continue;  // not on the edge
      sum += std::abs(rgba[std::size_t((y * kSize + x) * 4)] - exact);
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
      std::vector<std::uint8_t> rgba = staircase(20.3, slope, transpose);
      const double before = edge_error(rgba, 20.3, slope, transpose);
      FxaaScratch scratch;
      const std::size_t changed = fxaa(top_down(rgba.data(), kSize, kSize), scratch);
      const double after = edge_error(rgba, 20.3, slope, transpose);
      MESSAGE("mean error on the edge: ", before, " -> ", after, " (", changed, " pixels changed)");
      CHECK(changed > 0);
      CHECK(after < 0.6 * before);
      // Grey stays grey: the three channels are blended alike; the fourth byte is untouched.
      for (std::size_t i = 0; i < rgba.size(); i += 4) {
        CHECK(rgba[i] == rgba[i + 1]);
        CHECK(rgba[i] == rgba[i + 2]);
        CHECK(rgba[i + 3] == 77);
      }
    }
  }
}

TEST_CASE("fxaa: a frame viewed bottom-up (GL's read-back) comes out as its top-down copy does") {
  for (const bool transpose : {false, true}) {
    CAPTURE(transpose);
    std::vector<std::uint8_t> top = staircase(20.3, 0.31, transpose);
    std::vector<std::uint8_t> bottom(top.size());  // the same image, rows stored last to first
    const std::size_t row = kSize * 4;
    auto flip = [&](const std::vector<std::uint8_t>& from, std::vector<std::uint8_t>& to) {
      for (int y = 0; y < kSize; ++y)
        std::copy_n(from.begin() + std::ptrdiff_t(y * row), row,
                    to.begin() + std::ptrdiff_t((kSize - 1 - y) * row));
    };
    flip(top, bottom);
    FxaaScratch scratch;
    const std::size_t changed = fxaa(top_down(top.data(), kSize, kSize), scratch);
    CHECK(fxaa(bottom_up(bottom.data(), kSize, kSize), scratch) == changed);
    std::vector<std::uint8_t> flipped_back(top.size());
    flip(bottom, flipped_back);
    CHECK(flipped_back == top);
  }
}

TEST_CASE("fxaa: flat colour and a gentle gradient are left as they are") {
  std::vector<std::uint8_t> rgba(kSize * kSize * 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      std::uint8_t* p = &rgba[std::size_t((y * kSize + x) * 4)];
      p[0] = std::uint8_t(60 + x);  // 1 level per pixel: below FXAA's thresholds
      p[1] = std::uint8_t(100 + y / 2);
      p[2] = 180;
      p[3] = 255;
    }
  const std::vector<std::uint8_t> before = rgba;
  FxaaScratch scratch;
  CHECK(fxaa(top_down(rgba.data(), kSize, kSize), scratch) == 0);
  CHECK(rgba == before);
}
