// A pinhole camera (or an orthographic one, for the inset's magnified view):
// pose, vertical field of view and clip planes, with the OpenGL view and
// projection matrices and the same maths as a pixel projector (tests use
// project() to find where a world point lands in a frame).
#pragma once

#include <Eigen/Geometry>
#include <optional>

#include "render/render_settings.hpp"

namespace elbowsim {

// Orthonormal camera basis: right, true up, and back (from target toward eye).
struct CameraBasis {
  Eigen::Vector3d right, up, back;
};

CameraBasis camera_basis(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                         const Eigen::Vector3d& up);

struct Camera {
  Eigen::Vector3d eye = Eigen::Vector3d(0, -2, 0);   // [m] world
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  // [m] world, centre of the view
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();     // world; need not be orthogonal
  double fov_deg = 40;                               // vertical field of view [deg]
  double aspect = 16.0 / 9.0;                        // width / height
  double near = 0.05, far = 20;                      // [m] clip distances along the view
  // [m] > 0: orthographic, showing this height of the world at every depth
  // (fov_deg unused); 0: perspective.
  double ortho_height = 0;

  CameraBasis basis() const { return camera_basis(eye, target, up); }
  // World -> camera (right-handed, looking down -z): the usual lookAt.
  Eigen::Matrix4d view() const;
  // Camera -> clip space (OpenGL: depth -1 at near, +1 at far).
  Eigen::Matrix4d projection() const;
  // Pixel of a world point in a width x height image, x to the right and y
  // down from the top-left corner, in pixel units (the centre of pixel (i, j)
  // is (i + 0.5, j + 0.5)); nullopt when the point is behind the camera.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p, int width, int height) const;
  // Pixels per metre, in an image `height` px tall, of a length at `p` that
  // is square to the view direction.
  double pixels_per_metre(const Eigen::Vector3d& p, int height) const;
  // The same camera moved (eye and target) by `shift` [m].
  Camera moved(const Eigen::Vector3d& shift) const;
};

// Unit vector from the target toward the eye for a preset.
Eigen::Vector3d preset_direction(CameraPreset preset);
// The camera's up vector for a preset (top looks down, so +y is up there).
Eigen::Vector3d preset_up(CameraPreset preset);

// The camera a scene asks for: explicit settings as given, or a preset's
// direction framed so that all of `frame` (an axis-aligned box [m], e.g. the
// space the arm sweeps plus the table) is in view with a 6 % margin. The
// clip planes enclose `depth` (the frame plus what else is drawn, e.g. the
// floor grid). `aspect` = width / height of the image or panel.
// Near and far planes around everything in `depth` [m], seen from the eye.
void fit_clip(Camera& camera, const Eigen::AlignedBox3d& depth);

Camera make_camera(const CameraSettings& settings, const Eigen::AlignedBox3d& frame,
                   const Eigen::AlignedBox3d& depth, double aspect);

}  // namespace elbowsim
