#include "render/lighting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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

namespace {

// Blinn-Phong's specular factor of one light: (n.h)^48, 0 behind the face.
double shine(const Eigen::Vector3d& n, const Eigen::Vector3d& l, const Eigen::Vector3d& v) {
  if (n.dot(l) <= 0) return 0;
  const double s = std::max(n.dot((l + v).normalized()), 0.0);
  const double s2 = s * s, s4 = s2 * s2, s8 = s4 * s4, s16 = s8 * s8;
  return s16 * s16 * s16;
}

}  // namespace

bool specular_shows(const Lighting& lights, const Eigen::Vector3d& eye,
                    const Eigen::Matrix4f& model) {
  const Eigen::Matrix3d a = model.topLeftCorner<3, 3>().cast<double>();
  const Eigen::Vector3d centre = model.col(3).head<3>().cast<double>();
  const Eigen::Matrix3d normals = a.inverse().transpose();
  const double key = lights.specular * lights.key_color.maxCoeff();
  const double fill = lights.specular * lights.fill_color.maxCoeff();
  constexpr int kGrid = 17;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-0.5, 0.5}) {
      const Eigen::Vector3d n = (side * normals.col(axis)).normalized();
      const Eigen::Vector3d face = centre + side * a.col(axis);
      if (n.dot(eye - face) <= 0) continue;  // faces away: not seen
      const Eigen::Vector3d u = 0.5 * a.col((axis + 1) % 3), w = 0.5 * a.col((axis + 2) % 3);
      for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
          const Eigen::Vector3d p =
              face + (2.0 * i / (kGrid - 1) - 1) * u + (2.0 * j / (kGrid - 1) - 1) * w;
          const Eigen::Vector3d v = (eye - p).normalized();
          if (key * shine(n, lights.key, v) + fill * shine(n, lights.fill, v) >= 0.5 / 255)
            return true;
        }
    }
  return false;
}

ShadowView shadow_view(const Eigen::Vector3d& key, const Eigen::AlignedBox3d& bounds,
                       int max_texels) {
  const Eigen::Vector3d back = key.normalized();
  const double diagonal = std::max(bounds.diagonal().norm(), 2e-3);
  // The bounds' corners seen along the light: of the rectangles around them,
  // turned in the light's plane by whole degrees, the smallest. (A sphere
  // around the bounds, as before, took twice the texels for the experiment.)
  const Eigen::Matrix3d frame = frame_with_z(back);
  Eigen::Matrix<double, 3, 8> corners;
  for (int k = 0; k < 8; ++k) corners.col(k) = bounds.corner(Eigen::AlignedBox3d::CornerType(k));
  using Along = Eigen::RowVectorXd;  // the corners' coordinates along one direction
  const auto along = [&](const Eigen::Vector3d& d) -> Along { return d.transpose() * corners; };
  const auto span = [](const Along& x) { return x.maxCoeff() - x.minCoeff(); };
  const auto ends = [](const Along& x) { return x.maxCoeff() + x.minCoeff(); };
  Eigen::Vector3d right = frame.col(0);
  double best_area = std::numeric_limits<double>::infinity();
  for (int degree = 0; degree < 90; ++degree) {  // a rectangle turned by 90 degrees is the same
    const double a = degree * std::numbers::pi / 180;
    const Eigen::Vector3d u = std::cos(a) * frame.col(0) + std::sin(a) * frame.col(1);
    const double area = span(along(u)) * span(along(back.cross(u)));
    if (area < best_area) best_area = area, right = u;
  }
  const Eigen::Vector3d up = back.cross(right);
  const Along pu = along(right), pv = along(up), pd = along(back);
  ShadowView s;
  s.texel = diagonal / max_texels;
  const auto texels = [&](const Along& x) {
    return std::clamp(int(std::ceil(span(x) / s.texel)), 1, max_texels);
  };
  s.width = texels(pu);
  s.height = texels(pv);
  const double half_depth = 0.5 * span(pd);
  const double margin = 0.02 * diagonal;  // the clip planes clear of the bounds
  Camera& c = s.camera;
  c.target = 0.5 * (ends(pu) * right + ends(pv) * up + ends(pd) * back);  // the middle
  c.eye = c.target + (half_depth + margin) * back;
  c.up = up;
  c.ortho_height = s.height * s.texel;
  c.aspect = double(s.width) / s.height;
  c.near = 0.5 * margin;
  c.far = 2 * half_depth + 1.5 * margin;
  return s;
}

}  // namespace elbowsim
