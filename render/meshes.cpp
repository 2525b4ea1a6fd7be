#include "render/meshes.hpp"

#include <cmath>
#include <numbers>

namespace elbowsim {

namespace {

std::uint32_t add_vertex(Mesh& m, double x, double y, double z, double nx, double ny, double nz) {
  m.vertices.insert(m.vertices.end(),
                    {float(x), float(y), float(z), float(nx), float(ny), float(nz)});
  return std::uint32_t(m.vertices.size() / 6 - 1);
}

void add_triangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  m.indices.insert(m.indices.end(), {a, b, c});
}

// A disc of radius 1 at height z facing +z (up) or -z.
void add_disc(Mesh& m, int slices, double z, bool up) {
  const double s = up ? 1 : -1;
  const std::uint32_t centre = add_vertex(m, 0, 0, z, 0, 0, s);
  const std::uint32_t first = std::uint32_t(m.vertices.size() / 6);
  for (int j = 0; j <= slices; ++j) {
    const double phi = 2 * std::numbers::pi * j / slices;
    add_vertex(m, std::cos(phi), std::sin(phi), z, 0, 0, s);
  }
  for (int j = 0; j < slices; ++j) {
    if (up)
      add_triangle(m, centre, first + j, first + j + 1);
    else
      add_triangle(m, centre, first + j + 1, first + j);
  }
}

}  // namespace

namespace {

// The first `drawn` stacks (from +z down) of a unit sphere cut into
// `slices` x `stacks`: all of them for a sphere, half for a dome.
Mesh sphere_stacks(int slices, int stacks, int drawn) {
  Mesh m;
  for (int i = 0; i <= drawn; ++i) {
    const double theta = std::numbers::pi * i / stacks;  // from +z down
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2 * std::numbers::pi * j / slices;
      const double x = std::sin(theta) * std::cos(phi), y = std::sin(theta) * std::sin(phi),
                   z = std::cos(theta);
      add_vertex(m, x, y, z, x, y, z);
    }
  }
  const int row = slices + 1;
  for (int i = 0; i < drawn; ++i)
    for (int j = 0; j < slices; ++j) {
      // Quad a b c d; at a pole two of its corners are the pole, and only
      // the triangle without both is kept (keeping the other left a hole).
      const std::uint32_t a = i * row + j, b = (i + 1) * row + j, c = b + 1, d = a + 1;
      if (i != stacks - 1) add_triangle(m, a, b, c);
      if (i != 0) add_triangle(m, a, c, d);
    }
  return m;
}

}  // namespace

Mesh unit_sphere(int slices, int stacks) { return sphere_stacks(slices, stacks, stacks); }

Mesh unit_dome(int slices, int stacks) { return sphere_stacks(slices, 2 * stacks, stacks); }

Mesh unit_cylinder(int slices) {
  Mesh m = unit_tube(slices);
  add_disc(m, slices, 1, true);
  add_disc(m, slices, 0, false);
  return m;
}

Mesh unit_tube(int slices) {
  Mesh m;
  for (int j = 0; j <= slices; ++j) {
    const double phi = 2 * std::numbers::pi * j / slices;
    const double x = std::cos(phi), y = std::sin(phi);
    add_vertex(m, x, y, 0, x, y, 0);
    add_vertex(m, x, y, 1, x, y, 0);
  }
  for (int j = 0; j < slices; ++j) {
    const std::uint32_t a = 2 * j, b = 2 * (j + 1), c = b + 1, d = a + 1;
    add_triangle(m, a, b, c);
    add_triangle(m, a, c, d);
  }
  return m;
}

Mesh unit_cone(int slices) {
  Mesh m;
  const double k = 1 / std::sqrt(2.0);  // side normal (cos, sin, 1)/sqrt(2) for radius = height
  for (int j = 0; j < slices; ++j) {
    const double phi0 = 2 * std::numbers::pi * j / slices;
    const double phi1 = 2 * std::numbers::pi * (j + 1) / slices, mid = 0.5 * (phi0 + phi1);
    const std::uint32_t a =
        add_vertex(m, std::cos(phi0), std::sin(phi0), 0, k * std::cos(phi0), k * std::sin(phi0), k);
    const std::uint32_t b =
        add_vertex(m, std::cos(phi1), std::sin(phi1), 0, k * std::cos(phi1), k * std::sin(phi1), k);
    const std::uint32_t apex = add_vertex(m, 0, 0, 1, k * std::cos(mid), k * std::sin(mid), k);
    add_triangle(m, a, b, apex);
  }
  add_disc(m, slices, 0, false);
  return m;
}

Mesh unit_box() {
  Mesh m;
  // Each face: normal n and tangents u, v with u x v = n.
  const int faces[6][9] = {{1, 0, 0, 0, 1, 0, 0, 0, 1}, {-1, 0, 0, 0, 0, 1, 0, 1, 0},
                           {0, 1, 0, 0, 0, 1, 1, 0, 0}, {0, -1, 0, 1, 0, 0, 0, 0, 1},
                           {0, 0, 1, 1, 0, 0, 0, 1, 0}, {0, 0, -1, 0, 1, 0, 1, 0, 0}};
  for (const auto& f : faces) {
    const std::uint32_t first = std::uint32_t(m.vertices.size() / 6);
    for (const auto& [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      add_vertex(m, 0.5 * (f[0] + su * f[3] + sv * f[6]), 0.5 * (f[1] + su * f[4] + sv * f[7]),
                 0.5 * (f[2] + su * f[5] + sv * f[8]), f[0], f[1], f[2]);
    add_triangle(m, first, first + 1, first + 2);
    add_triangle(m, first, first + 2, first + 3);
  }
  return m;
}

Mesh unit_square() {
  Mesh m;
  for (const double side : {1.0, -1.0}) {  // a face toward +y, then one toward -y
    const std::uint32_t first = std::uint32_t(m.vertices.size() / 6);
    for (const auto& [x, z] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      add_vertex(m, 0.5 * x, 0, 0.5 * z, 0, side, 0);
    if (side > 0) {  // counter-clockwise seen from +y: x to z is clockwise there
      add_triangle(m, first, first + 2, first + 1);
      add_triangle(m, first, first + 3, first + 2);
    } else {
      add_triangle(m, first, first + 1, first + 2);
      add_triangle(m, first, first + 2, first + 3);
    }
  }
  return m;
}

Mesh unit_torus(int slices, int sides, double minor) {
  Mesh m;
  for (int i = 0; i <= slices; ++i) {
    const double phi = 2 * std::numbers::pi * i / slices;  // around z
    for (int j = 0; j <= sides; ++j) {
      const double psi = 2 * std::numbers::pi * j / sides;  // around the tube
      const double nx = std::cos(psi) * std::cos(phi), ny = std::cos(psi) * std::sin(phi),
                   nz = std::sin(psi);
      add_vertex(m, std::cos(phi) + minor * nx, std::sin(phi) + minor * ny, minor * nz, nx, ny, nz);
    }
  }
  const int row = sides + 1;
  for (int i = 0; i < slices; ++i)
    for (int j = 0; j < sides; ++j) {
      const std::uint32_t a = i * row + j, b = (i + 1) * row + j, c = b + 1, d = a + 1;
      add_triangle(m, a, b, c);
      add_triangle(m, a, c, d);
    }
  return m;
}

}  // namespace elbowsim
