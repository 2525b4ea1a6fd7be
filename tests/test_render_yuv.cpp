// RGBA -> YUV 4:2:0 (render/yuv.hpp), as the encoder takes it: BT.709
// limited range, checked against the standard's formulas in floating point;
// and the writer's view of GL's read-back (render/frame_writer.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "render/frame_writer.hpp"
#include "render/yuv.hpp"

using namespace elbowsim;

namespace {

// BT.709: Y' from R'G'B' in 0..255, then 8-bit limited range (16..235, 16..240).
double luma(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
double y_code(double r, double g, double b) { return 16 + 219.0 / 255.0 * luma(r, g, b); }
double cb_code(double r, double g, double b) {
  return 128 + 224.0 / 255.0 * (b - luma(r, g, b)) / 1.8556;
}
double cr_code(double r, double g, double b) {
  return 128 + 224.0 / 255.0 * (r - luma(r, g, b)) / 1.5748;
}

}  // namespace

TEST_CASE("rgba_to_yuv420: BT.709 limited range, luma per pixel, chroma per 2x2 block mean") {
  constexpr int w = 8, h = 6;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<std::uint8_t> rgba(w * h * 4);
  for (std::uint8_t& c : rgba) c = std::uint8_t(byte(random));  // the 4th bytes too: not read
  // Corners with known codes: black, white, pure green, a grey.
  const std::uint8_t known[4][3] = {{0, 0, 0}, {255, 255, 255}, {0, 255, 0}, {90, 90, 90}};
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) rgba[std::size_t(k * 4 + c)] = known[k][c];
  std::vector<std::uint8_t> yuv(yuv420_bytes(w, h));
  REQUIRE(yuv.size() == w * h + 2 * (w / 2) * (h / 2));
  rgba_to_yuv420(top_down(rgba.data(), w, h), yuv.data());
  CHECK(int(yuv[0]) == 16);   // black
  CHECK(int(yuv[1]) == 235);  // white
  CHECK(int(yuv[2]) == 173);  // green: 16 + 219 x 0.7152 = 172.6
  CHECK(int(yuv[3]) == 93);   // grey 90: 16 + 219 x 90 / 255 = 93.3
  const std::uint8_t* u = yuv.data() + w * h;
  const std::uint8_t* v = u + (w / 2) * (h / 2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = &rgba[std::size_t((y * w + x) * 4)];
      CAPTURE(x);
      CAPTURE(y);
      CHECK(std::abs(yuv[std::size_t(y * w + x)] - y_code(p[0], p[1], p[2])) <= 0.501);
    }
  for (int y = 0; y < h / 2; ++y)
    for (int x = 0; x < w / 2; ++x) {
      double mean[3] = {0, 0, 0};
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          for (int c = 0; c < 3; ++c)
            mean[c] += rgba[std::size_t(((2 * y + dy) * w + 2 * x + dx) * 4 + c)] / 4.0;
      CAPTURE(x);
      CAPTURE(y);
      const std::size_t i = std::size_t(y * (w / 2) + x);
      CHECK(std::abs(u[i] - cb_code(mean[0], mean[1], mean[2])) <= 0.501);
      CHECK(std::abs(v[i] - cr_code(mean[0], mean[1], mean[2])) <= 0.501);
    }
  // A grey frame has no colour at all.
  std::vector<std::uint8_t> grey(w * h * 4, 131);
  rgba_to_yuv420(top_down(grey.data(), w, h), yuv.data());
  CHECK(int(u[0]) == 128);
  CHECK(int(v[0]) == 128);
}

TEST_CASE(
    "rgba_to_yuv420: a bottom-up frame (walked in memory order) gives its top-down copy's YUV") {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> byte(0, 255);
  for (const auto& [w, h] : {std::pair{2, 2}, std::pair{6, 4}, std::pair{1280, 10}}) {
    CAPTURE(w);
    CAPTURE(h);
    std::vector<std::uint8_t> bottom_up_rows(std::size_t(w) * std::size_t(h) * 4);
    for (std::uint8_t& c : bottom_up_rows) c = std::uint8_t(byte(random));
    std::vector<std::uint8_t> top_down_rows(bottom_up_rows.size());
    const std::size_t row = std::size_t(w) * 4;
    for (int y = 0; y < h; ++y)
      std::copy_n(bottom_up_rows.begin() + std::ptrdiff_t((h - 1 - y) * row), row,
                  top_down_rows.begin() + std::ptrdiff_t(y * row));
    std::vector<std::uint8_t> from_bottom_up(yuv420_bytes(w, h)), from_top_down(from_bottom_up);
    rgba_to_yuv420(bottom_up(bottom_up_rows.data(), w, h), from_bottom_up.data());
    rgba_to_yuv420(top_down(top_down_rows.data(), w, h), from_top_down.data());
    CHECK(from_bottom_up == from_top_down);
  }
}

TEST_CASE(
    "output_frame: GL's bottom-up rows viewed top-down in place; 2x2 blocks averaged at scale 2") {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (const int width : {1, 2, 3, 17, 1280}) {
    for (const int scale : {1, 2}) {
      CAPTURE(width);
      CAPTURE(scale);
      const int height = 3;
      const int in_width = width * scale, in_height = height * scale;
      std::vector<std::uint8_t> read(std::size_t(in_width) * std::size_t(in_height) * 4);
      for (std::uint8_t& b : read) b = std::uint8_t(byte(random));
      const std::vector<std::uint8_t> before = read;
      std::vector<std::uint8_t> averaged;
      const RgbaView out = output_frame(read, width, height, scale, averaged);
      REQUIRE(out.width == width);
      REQUIRE(out.height == height);
      CHECK(read == before);  // the read-back is not changed
      // At scale 1 the frame is the read-back itself: nothing was copied.
      if (scale == 1) CHECK(out.row(height - 1) == read.data());
      bool same = true;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
          for (int c = 0; c < 4; ++c) {
            int sum = 0;
            for (int dy = 0; dy < scale; ++dy)
              for (int dx = 0; dx < scale; ++dx) {
                const int row = in_height - 1 - (y * scale + dy);  // GL's rows are bottom-up
                sum += before[(std::size_t(row) * std::size_t(in_width) +
                               std::size_t(x * scale + dx)) *
                                  4 +
                              std::size_t(c)];
              }
            const int expected = scale == 1 ? sum : (sum + 2) / 4;
            same = same && out.pixel(x, y)[c] == expected;
          }
      CHECK(same);
    }
  }
}
