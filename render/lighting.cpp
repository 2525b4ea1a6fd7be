#include "render/lighting.hpp"

#include <algorithm>

#include "render/scene.hpp"

namespace elbowsim {

Lighting view_lighting(const Camera& camera) {
  const CameraBasis basis = camera.basis();
  const Eigen::Vector3d &back = basis.back, &right = basis.right;
  Lighting out;
  out.key = (0.7 * Eigen::Vector3d::UnitZ() + 0.35 * back - 0.4 * right).normalized();
  out.fill = (0.8 * right + 0.2 * back).normalized();
  return out;
}

Camera shadow_camera(const Eigen::Vector3d& key, const Eigen::AlignedBox3d& bounds) {
  // A sphere around the bounds; the light looks at its centre from 2 radii away.
  const double radius = std::max(0.5 * bounds.diagonal().norm(), 1e-3);
  Camera c;
  c.target = bounds.center();
  c.eye = c.target + 2 * radius * key.normalized();
  c.up = frame_with_z(key.normalized()).col(0);  // any direction square to the light
  c.ortho_height = 2 * radius;
  c.aspect = 1;
  c.near = radius;
  c.far = 3 * radius;
  return c;
}

}  // namespace elbowsim
