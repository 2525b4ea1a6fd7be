// How finely a round shape (sphere, dome, cylinder, shaft) is tessellated:
// by its radius on screen, the fewest slices whose outline stays within
// kOutlineError pixels of round. Small shapes then cost few triangles -
// llvmpipe pays for every triangle, however few pixels it covers - and the
// inset's magnified forearm gets more slices than the main view's.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace elbowsim {

inline constexpr std::array<int, 6> kSlices = {8, 12, 16, 24, 32, 48};
// [px] A polygon of n slices around a circle of radius r px strays from it
// by r (1 - cos(pi / n)) at most. Half a pixel: the experiment's frames at
// 3x zoom, against 24 slices everywhere, differ only in faint facets on the
// joint caps' outlines (16 slices there).
inline constexpr double kOutlineError = 0.5;

// The index into kSlices for a round shape `radius_px` in radius on screen.
inline int detail_level(double radius_px) {
  for (int level = 0; level + 1 < int(kSlices.size()); ++level)
    if (radius_px * (1 - std::cos(std::numbers::pi / kSlices[std::size_t(level)])) <= kOutlineError)
      return level;
  return int(kSlices.size()) - 1;
}

}  // namespace elbowsim
