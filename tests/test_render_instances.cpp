// The renderer's instance lists (render/instances.hpp), without GL: culling
// to the inset's orthographic window keeps what reaches into it and drops
// what lies wholly outside, whatever its depth.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <vector>

#include "render/instances.hpp"

using namespace elbowsim;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// Instances of one shape in a list.
std::size_t count(const ShapeInstances& s, Shape shape) {
  return s[std::size_t(shape)].size() / kInstanceFloats;
}

// A unit shape along x from a to b with radius r (cylinder: z from 0 to 1).
void add_x(std::vector<float>& out, const Vector3d& a, double length, double r) {
  Matrix3d linear;
  linear << 0, 0, length, 0, r, 0, -r, 0, 0;  // unit z -> x, unit x -> -z
  add_instance(out, linear, a, Color{1, 1, 1});
}

}  // namespace

TEST_CASE("cull_to_window: what reaches into the orthographic window is kept, the rest dropped") {
  // Looking along +y at the origin: the window is x in +-0.0667, z in +-0.05.
  Camera c;
  c.eye = Vector3d(0, -1, 0);
  c.target = Vector3d::Zero();
  c.up = Vector3d::UnitZ();
  c.ortho_height = 0.1;
  c.aspect = 4.0 / 3.0;
  ShapeInstances in;
  const Color white{1, 1, 1};
  add_instance(in[sphere], 0.01 * Matrix3d::Identity(), Vector3d(0, 0, 0), white);    // inside
  add_instance(in[sphere], 0.01 * Matrix3d::Identity(), Vector3d(0.2, 0, 0), white);  // right of it
  add_instance(in[sphere], 0.05 * Matrix3d::Identity(), Vector3d(0.1, 0.3, 0),
               white);                                                                 // reaches in
  add_instance(in[sphere], 0.01 * Matrix3d::Identity(), Vector3d(0, 5, 0.09), white);  // above it
  add_x(in[cylinder], Vector3d(0.5, 0, 0), 0.01, 0.01);  // short, far right
  add_x(in[cylinder], Vector3d(-1, 0, 0), 2, 0.01);      // long, across the window
  ShapeInstances out;
  out[box].assign(kInstanceFloats, 0.0f);  // cleared first
  cull_to_window(in, c, out);
  CHECK(count(out, sphere) == 2);
  CHECK(count(out, cylinder) == 1);
  CHECK(count(out, box) == 0);
  // The kept ones as they were, in order: the first and third sphere, the second cylinder.
  const std::vector<float>& s = in[sphere];
  std::vector<float> kept(s.begin(), s.begin() + kInstanceFloats);
  kept.insert(kept.end(), s.begin() + 2 * kInstanceFloats, s.begin() + 3 * kInstanceFloats);
  CHECK(out[sphere] == kept);
  CHECK(out[cylinder] ==
        std::vector<float>(in[cylinder].begin() + kInstanceFloats, in[cylinder].end()));
}
