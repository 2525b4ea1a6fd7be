// Anti-aliasing of a finished frame on the CPU: FXAA (Lottes, "FXAA 3.11",
// NVIDIA 2011, its "quality" algorithm) on 8-bit RGBA (rgba_view.hpp). Each pixel whose
// luma contrast with its four neighbours is high is taken to lie on an edge:
// the edge's direction (horizontal or vertical) comes from the 3 x 3 luma,
// its two ends from a walk along it, and the pixel is blended with its
// neighbour across the edge by how far it is from the nearer end, which
// turns a staircase back into the slope it came from. The frames are drawn
// with one sample per pixel and this pass replaces multisampling, which on
// llvmpipe costs about as much as drawing the frame itself.
#pragma once

#include <cstdint>
#include <vector>

#include "render/rgba_view.hpp"

namespace elbowsim {

// Buffers reused from frame to frame (sized on first use).
struct FxaaScratch {
  std::vector<std::uint8_t> luma;  // the frame's luma with a border (fxaa.cpp)
  std::vector<std::uint8_t> mask;  // width: which pixels of a row are on an edge
  struct Blend {
    std::int32_t offset;  // [bytes] of the pixel changed from the frame's top row (frames < 2 GiB)
    std::uint8_t rgb[3];  // its new colour
  };
  std::vector<Blend> blends;  // the pass's changes, applied after it has read everything
};

// Anti-aliases `frame` in place (red, green and blue; the fourth bytes are
// left as they are). Returns the number of pixels changed.
std::size_t fxaa(RgbaView frame, FxaaScratch& scratch);

}  // namespace elbowsim
