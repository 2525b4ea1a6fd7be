// Anti-aliasing of a finished frame on the CPU: FXAA (Lottes, "FXAA 3.11",
// NVIDIA 2011, its "quality" algorithm) on 8-bit RGB. Each pixel whose
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

namespace elbowsim {

// Buffers reused from frame to frame (sized on first use).
struct FxaaScratch {
  std::vector<std::uint8_t> luma;  // the frame's luma with a border (fxaa.cpp)
  std::vector<std::uint8_t> mask;  // width: which pixels of a row are on an edge
  struct Blend {
    std::uint32_t pixel;  // index of the pixel changed
    std::uint8_t rgb[3];  // its new colour
  };
  std::vector<Blend> blends;  // the pass's changes, applied after it has read everything
};

// rgb: width * height pixels, 3 bytes each, rows top-down; anti-aliased in place.
// Returns the number of pixels changed.
std::size_t fxaa(std::uint8_t* rgb, int width, int height, FxaaScratch& scratch);

}  // namespace elbowsim
