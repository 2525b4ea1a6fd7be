// RGBA frames (rgba_view.hpp) -> planar YUV 4:2:0 (what the H.264 encoder takes), in BT.709
// with limited ("TV") range, the matrix HD video players assume. Done here,
// not by FFmpeg's swscale, so that it is done once (a side-by-side reuses it) and the
// video's colour matrix is the one its header names.
#pragma once

#include <cstdint>

#include "render/rgba_view.hpp"

namespace elbowsim {

// Bytes of a width x height frame in YUV 4:2:0: the luma plane, then the two
// chroma planes of (width / 2) x (height / 2).
inline std::size_t yuv420_bytes(int width, int height) {
  return std::size_t(width) * std::size_t(height) * 3 / 2;
}

// frame: width and height even (the fourth bytes are not read). yuv:
// yuv420_bytes(width, height). Luma per pixel; chroma per 2 x 2 block from
// the block's mean colour. Integer arithmetic, rounded.
void rgba_to_yuv420(ConstRgbaView frame, std::uint8_t* yuv);

}  // namespace elbowsim
