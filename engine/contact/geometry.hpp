// Closest features between the arm's collision primitives and a table box,
// in closed form: a sphere (a point with a radius) or a capsule (a segment
// with a radius) against a box. The feature the answer lies on (a face, an
// edge, a corner) decides the normal: on a face it is exactly the box's face
// axis, so a body resting on a face has an exact constraint row whatever its
// radius (no tilt from rounding a numerical separating vector).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "engine/model.hpp"

namespace elbowsim {

enum class BoxFeature { face, edge, corner, inside };

const char* to_string(BoxFeature f);

struct BoxContact {
  double distance = 0;     // [m] signed, primitive surface to box surface; < 0 penetrating
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, world, from the box toward the primitive
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // [m] world, the closest point of the box surface
  BoxFeature feature = BoxFeature::face;  // where `point` lies (inside: the centre is in the box)
  int face_axis = -1;      // the box axis 0..2 of a face (or of the nearest face, inside); -1 otherwise
  Eigen::Vector3d edge = Eigen::Vector3d::Zero();  // unit, world, along an edge; zero otherwise
};

// A sphere of `radius` centred at `centre` (world) against `box`. Inside the
// box, the nearest face is the answer (least penetration).
BoxContact sphere_box(const Eigen::Vector3d& centre, double radius, const TableBox& box);

// The parameter t in [0, 1] of the point a + t (b - a) of a segment (world)
// nearest to the box; where the segment enters the box, the deepest point
// (farthest inside from the box surface). Exact: the squared distance is
// convex and piecewise quadratic in t, minimised on each piece.
double segment_box_parameter(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const TableBox& box);

// The box's axis-aligned bounds in world coordinates [m].
Eigen::AlignedBox3d box_bounds(const TableBox& box);

}  // namespace elbowsim
