// Pixels of frames the renderer tests read back: a frame as GL returns it
// (RGBA, rows bottom-up) and colour checks that allow for lighting.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "render/png_writer.hpp"
#include "render/scene.hpp"

namespace render_pixels {

using elbowsim::Color;

struct Pixel {
  int r, g, b;
};

// A frame read back: RGBA rows bottom-up -> pixel (x, y) from the top-left.
struct Image {
  int width, height;
  std::vector<std::uint8_t> rgba;
  Pixel at(double x, double y) const {
    const std::size_t i =
        (std::size_t(height - 1 - int(y)) * std::size_t(width) + std::size_t(x)) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2]};
  }
  void save(const std::filesystem::path& path) const {  // for looking at
    elbowsim::write_png(path, elbowsim::bottom_up(rgba.data(), width, height));
  }
};

// Lit colour of a surface of base colour c: a brightness factor in
// [0.45, 1.45] times c, hue kept (chromaticity within 0.04).
inline bool looks_like(const Pixel& p, const Color& c) {
  const double ps = p.r + p.g + p.b, cs = 255.0 * (c.r + c.g + c.b);
  if (ps <= 0 || ps < 0.45 * cs || ps > 1.45 * cs) return false;
  const double d[3] = {p.r / ps - 255 * c.r / cs, p.g / ps - 255 * c.g / cs,
                       p.b / ps - 255 * c.b / cs};
  return std::abs(d[0]) < 0.04 && std::abs(d[1]) < 0.04 && std::abs(d[2]) < 0.04;
}

inline bool is_background(const Pixel& p, const Color& c) {
  return std::abs(p.r - 255 * c.r) <= 1.5 && std::abs(p.g - 255 * c.g) <= 1.5 &&
         std::abs(p.b - 255 * c.b) <= 1.5;
}

inline std::string show(const Pixel& p) {
  return std::to_string(p.r) + "," + std::to_string(p.g) + "," + std::to_string(p.b);
}

}  // namespace render_pixels
