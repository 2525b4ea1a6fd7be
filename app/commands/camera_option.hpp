// The render command's --camera and --follow options, parsed over the
// scenario's render.camera (GL-free; tested without a process).
#pragma once

#include <string>

#include "render/render_settings.hpp"

namespace elbowsim {

// --camera TEXT: a preset name, or comma-separated items key=value where a
// vector's other two numbers follow as plain items:
//   top        front,fov=25        eye=0.6,-0.9,0.2,target=0.6,0,0,fov=20
// Keys: preset=NAME, eye=X,Y,Z and target=X,Y,Z [m] (together; not with a
// preset), up=X,Y,Z, fov=DEG (vertical, in [1, 170]). fov alone keeps the
// scenario's view and changes its field of view. Returns "" when valid
// (camera changed), else the message (camera unchanged).
std::string apply_camera_option(const std::string& text, CameraSettings& camera);

// --follow hand|none.
std::string apply_follow_option(const std::string& text, CameraSettings& camera);

}  // namespace elbowsim
