#include "render/camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace elbowsim {

CameraBasis camera_basis(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                         const Eigen::Vector3d& up) {
  CameraBasis b;
  b.back = (eye - target).normalized();
  b.right = up.cross(b.back).normalized();
  b.up = b.back.cross(b.right);
  return b;
}

namespace {

double tan_half(double fov_deg) { return std::tan(0.5 * fov_deg * std::numbers::pi / 180.0); }

std::array<Eigen::Vector3d, 8> corners(const Eigen::AlignedBox3d& box) {
  std::array<Eigen::Vector3d, 8> out;
  for (int k = 0; k < 8; ++k) out[k] = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k));
  return out;
}

// Distance from `centre` along `back` at which every corner of the frame
// projects inside the view: for a corner at (x, y, z) in the camera basis
// relative to the centre, the eye at distance D sees it at depth D - z, so
// |x| <= (D - z) tan_h and |y| <= (D - z) tan_v.
double framing_distance(const CameraBasis& b, const Eigen::AlignedBox3d& frame,
                        const Eigen::Vector3d& centre, double tan_v, double tan_h) {
  double distance = 0;
  for (const Eigen::Vector3d& c : corners(frame)) {
    const Eigen::Vector3d d = c - centre;
    const double z = d.dot(b.back);
    distance = std::max(
        {distance, z + std::abs(d.dot(b.right)) / tan_h, z + std::abs(d.dot(b.up)) / tan_v});
  }
  return distance;
}

// The frame seen along -back, centred in the image: perspective makes its
// near side look bigger, so the target moves sideways until the projected
// extents are symmetric (a few fixed-point steps), then the distance is refit.
void frame_view(Camera& camera, const CameraBasis& b, const Eigen::AlignedBox3d& frame, double tan_v,
                double tan_h) {
  Eigen::Vector3d centre = frame.center();
  double distance = 0;
  for (int iteration = 0; iteration < 4; ++iteration) {
    distance = std::max(framing_distance(b, frame, centre, tan_v, tan_h), 0.05);
    const Eigen::Vector3d eye = centre + distance * b.back;
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const Eigen::Vector3d& c : corners(frame)) {
      const Eigen::Vector3d d = c - eye;
      const double depth = -d.dot(b.back);
      lo_x = std::min(lo_x, d.dot(b.right) / depth), hi_x = std::max(hi_x, d.dot(b.right) / depth);
      lo_y = std::min(lo_y, d.dot(b.up) / depth), hi_y = std::max(hi_y, d.dot(b.up) / depth);
    }
    centre += distance * (0.5 * (lo_x + hi_x) * b.right + 0.5 * (lo_y + hi_y) * b.up);
  }
  camera.target = centre;
  camera.eye = centre + distance * b.back;
}

}  // namespace

Eigen::Matrix4d Camera::view() const {
  const CameraBasis b = camera_basis(eye, target, up);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = b.right.transpose();
  m.block<1, 3>(1, 0) = b.up.transpose();
  m.block<1, 3>(2, 0) = b.back.transpose();
  m(0, 3) = -b.right.dot(eye);
  m(1, 3) = -b.up.dot(eye);
  m(2, 3) = -b.back.dot(eye);
  return m;
}

Eigen::Matrix4d Camera::projection() const {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  if (ortho_height > 0) {  // x, y scaled into [-1, 1]; depth linear from near to far
    p(0, 0) = 2 / (ortho_height * aspect);
    p(1, 1) = 2 / ortho_height;
    p(2, 2) = -2 / (far - near);
    p(2, 3) = -(far + near) / (far - near);
    p(3, 3) = 1;
    return p;
  }
  const double f = 1.0 / tan_half(fov_deg);
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (far + near) / (near - far);
  p(2, 3) = 2 * far * near / (near - far);
  p(3, 2) = -1;
  return p;
}

std::optional<Eigen::Vector2d> Camera::project(const Eigen::Vector3d& p, int width,
                                               int height) const {
  const Eigen::Vector4d clip = projection() * view() * p.homogeneous();
  if (clip.w() <= 0) return std::nullopt;
  const double x = clip.x() / clip.w(), y = clip.y() / clip.w();
  return Eigen::Vector2d(0.5 * (x + 1) * width, 0.5 * (1 - y) * height);
}

double Camera::pixels_per_metre(const Eigen::Vector3d& p, int height) const {
  if (ortho_height > 0) return height / ortho_height;
  const double depth = (p - eye).dot((target - eye).normalized());
  return height / (2 * std::max(depth, 1e-9) * tan_half(fov_deg));
}

Camera Camera::moved(const Eigen::Vector3d& shift) const {
  Camera out = *this;
  out.eye += shift;
  out.target += shift;
  return out;
}

// Near and far planes around everything in `depth`, seen from eye along -back.
void fit_clip(Camera& camera, const Eigen::AlignedBox3d& depth) {
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  double lo = 1e300, hi = 0;
  for (const Eigen::Vector3d& c : corners(depth)) {
    const double z = (c - camera.eye).dot(forward);
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  hi = std::max(hi, 0.1);
  camera.far = 1.05 * hi + 0.05;
  camera.near = std::clamp(0.9 * lo, camera.far * 1e-4, camera.far * 0.5);
}

Eigen::Vector3d preset_direction(CameraPreset preset) {
  switch (preset) {
    case CameraPreset::front:
      return Eigen::Vector3d(0, -1, 0);
    case CameraPreset::side:
      return Eigen::Vector3d(1, 0, 0);
    case CameraPreset::top:
      return Eigen::Vector3d(0, 0, 1);
    case CameraPreset::three_quarter:
      return Eigen::Vector3d(0.55, -1.0, 0.5).normalized();
  }
  return Eigen::Vector3d(0, -1, 0);
}

Eigen::Vector3d preset_up(CameraPreset preset) {
  return preset == CameraPreset::top ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
}

Camera make_camera(const CameraSettings& settings, const Eigen::AlignedBox3d& frame,
                   const Eigen::AlignedBox3d& depth, double aspect) {
  Camera camera;
  camera.fov_deg = settings.fov_deg;
  camera.aspect = aspect;
  if (settings.explicit_pose) {
    camera.eye = settings.eye;
    camera.target = settings.target;
    camera.up = settings.up;
  } else {
    // 6 % margin on each side of the frame.
    const double tan_v = tan_half(settings.fov_deg) / 1.06;
    const double tan_h = tan_v * aspect;
    const Eigen::Vector3d back = preset_direction(settings.preset);
    camera.up = preset_up(settings.preset);
    frame_view(camera, camera_basis(back, Eigen::Vector3d::Zero(), camera.up), frame, tan_v, tan_h);
  }
  Eigen::AlignedBox3d everything = depth;
  everything.extend(frame);
  fit_clip(camera, everything);
  return camera;
}

}  // namespace elbowsim
