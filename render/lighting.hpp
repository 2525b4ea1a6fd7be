// The two lights of a view and the key light's shadow-map projection, without
// GL: gl_renderer.cpp shades with them, tests find where a shadow falls.
#pragma once

#include <Eigen/Geometry>

#include "render/camera.hpp"

namespace elbowsim {

struct Lighting {
  Eigen::Vector3d key = Eigen::Vector3d::UnitZ();   // unit, toward the key light (casts shadows)
  Eigen::Vector3d fill = Eigen::Vector3d::UnitX();  // unit, toward the fill light
};

// Lights that follow the view: the key mostly from above (world z), a little
// from the viewer's side and from the left, so tops are brighter than the
// faces toward the camera and shadows fall to the right, where they show
// beside what casts them; a dim fill from the viewer's right.
Lighting view_lighting(const Camera& camera);

// The key light's view for a shadow map: orthographic along -key, holding
// all of `bounds` [m] between its clip planes, in texels of a fixed size (the
// bounds' diagonal over `max_texels`), as few as hold it.
struct ShadowView {
  Camera camera;
  int width = 0, height = 0;  // [texels] of the map, each at most max_texels
  double texel = 0;           // [m] side of one texel in the world
};
ShadowView shadow_view(const Eigen::Vector3d& key, const Eigen::AlignedBox3d& bounds,
                       int max_texels);

}  // namespace elbowsim
