// The two lights of a view and the key light's shadow-map projection, without
// GL: gl_renderer.cpp shades with them, tests find where a shadow falls.
#pragma once

#include <Eigen/Geometry>

#include "render/camera.hpp"

namespace elbowsim {

// Blinn-Phong's terms (gl_shaders.hpp kLighting): ambient k + sum over the
// lights of colour (max(n.l, 0) k + specular max(n.h, 0)^48).
struct Lighting {
  Eigen::Vector3d key = Eigen::Vector3d::UnitZ();   // unit, toward the key light (casts shadows)
  Eigen::Vector3d fill = Eigen::Vector3d::UnitX();  // unit, toward the fill light
  Eigen::Vector3f key_color{0.72f, 0.72f, 0.72f};
  Eigen::Vector3f fill_color{0.22f, 0.22f, 0.24f};
  float ambient = 0.32f;
  float specular = 0.22f;
};

// Lights that follow the view: the key mostly from above (world z), a little
// from the viewer's side and from the left, so tops are brighter than the
// faces toward the camera and shadows fall to the right, where they show
// beside what casts them; a dim fill from the viewer's right.
Lighting view_lighting(const Camera& camera);

// Whether the specular terms reach half a level (of 255) anywhere on a face
// of a box seen from `eye`: the unit box [-1/2, 1/2]^3 placed by `model`
// (an instance's transform), each face that faces the eye sampled on a
// 17 x 17 grid. A highlight is about 19 degrees of view across at half its
// height, so such a grid does not step over one on a face in view. Where
// none shows, lighting a box per vertex is within a level of per fragment.
bool specular_shows(const Lighting& lights, const Eigen::Vector3d& eye,
                    const Eigen::Matrix4f& model);

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
