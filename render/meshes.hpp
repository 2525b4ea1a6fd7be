// Unit shapes tessellated once, as triangle lists with outward normals and
// counter-clockwise winding seen from outside. The renderer uploads each to a
// vertex buffer and draws every instance of it with one transform each.
#pragma once

#include <cstdint>
#include <vector>

namespace elbowsim {

struct Mesh {
  std::vector<float> vertices;         // x, y, z, nx, ny, nz per vertex
  std::vector<std::uint32_t> indices;  // 3 per triangle
};

Mesh unit_sphere(int slices, int stacks);  // radius 1 about the origin
// unit_sphere(slices, 2 stacks)'s half with z >= 0, open at z = 0.
Mesh unit_dome(int slices, int stacks);
Mesh unit_cylinder(int slices);            // radius 1, z from 0 to 1, capped
Mesh unit_tube(int slices);                // unit_cylinder's side only (open ends)
Mesh unit_cone(int slices);                // base radius 1 at z = 0, apex at z = 1, capped
Mesh unit_box();                           // [-1/2, 1/2]^3
Mesh unit_square();  // [-1/2, 1/2] in x and z at y = 0, both sides (normals +-y)
// A ring about the z axis: centre line of radius 1 in the x-y plane, tube of
// radius `minor` (< 1).
Mesh unit_torus(int slices, int sides, double minor);

}  // namespace elbowsim
