// A rectangle of an image in pixels, from the top-left corner.
#pragma once

namespace elbowsim {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

}  // namespace elbowsim
