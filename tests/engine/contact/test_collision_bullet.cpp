// engine/contact/collision_bullet.cpp: CollisionWorld against distances worked out by hand:
// spheres over flat, rotated and stepped tables, beside edges and corners, and link
// capsules pushed into the table.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "engine/contact/collision.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;

namespace {

constexpr double kRadius = 0.03;  // [m] elbow sphere radius
constexpr double kExact = 1e-9;   // [m] "exact": GJK between a point and a box, in double

// One link 0.6 m long along +x (q = 0), its elbow sphere at the middle, (0.3, 0, 0) in the
// link frame. The base is moved so that the elbow centre lands on `centre`.
Model elbow_at(const Eigen::Vector3d& centre, const std::vector<TableBox>& table) {
  Model m = elbowsim::testing::planar_arm({{0.6, 1.0, 0.3, 0.03}});
  m.base.translation() = centre - Eigen::Vector3d(0.3, 0, 0);
  m.elbows.push_back(Elbow{"mid", 0, Eigen::Vector3d(0.3, 0, 0), kRadius});
  m.table = table;
  m.effects.contact = true;
  finalize(m);
  return m;
}

TableBox box(const Eigen::Vector3d& center, const Eigen::Vector3d& size,
             const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  return TableBox{center, size, rotation};
}

// The single elbow's contact record at q = 0.
ElbowContact contact_of(const Model& model) {
  Data data(model);
  forward_kinematics(model, data, Eigen::VectorXd::Zero(model.dof));
  CollisionWorld world(model);
  std::vector<ElbowContact> contacts;
  world.elbow_contacts(model, data, contacts);
  REQUIRE(contacts.size() == 1);
  return contacts[0];
}

}  // namespace

TEST_CASE("sphere over a flat box top: exact signed distance, normal +z, point on the top") {
  //        o  centre (0.3, 0, r + d)
  //   -----+---------------  top z = 0
  //   |  box 1.0 x 0.8 x 0.05 |
  const TableBox table = box({0.4, 0.1, -0.025}, {1.0, 0.8, 0.05});
  for (const double d : {0.3, 1e-3, 1e-7, 0.0, -2e-3, -0.029}) {
    CAPTURE(d);
    const ElbowContact c = contact_of(elbow_at({0.3, 0, kRadius + d}, {table}));
    CHECK(c.elbow == 0);
    CHECK(c.box == 0);
    CHECK(approx(c.distance, d, kExact));
    CHECK(approx(c.normal, Eigen::Vector3d::UnitZ(), kExact));
    CHECK(approx(c.point, Eigen::Vector3d(0.3, 0, 0), kExact));
  }
}

TEST_CASE("sphere centre inside the box: EPA still gives depth and normal") {
  // Deeper than the radius the cores overlap and Bullet switches to EPA, which iterates to
  // a tolerance (in a random sweep: distance within 3e-12 m, normal within 2e-10).
  const TableBox table = box({0.4, 0.1, -0.1}, {1.0, 0.8, 0.2});
  for (const double d : {-0.04, -0.06, -0.1}) {
    CAPTURE(d);
    const ElbowContact c = contact_of(elbow_at({0.3, 0, kRadius + d}, {table}));
    CHECK(c.box == 0);
    CHECK(approx(c.distance, d, kExact));
    CHECK(approx(c.normal, Eigen::Vector3d::UnitZ(), 1e-8));
  }
  // Nearer the bottom than the top: the way out, and the normal, point down.
  const ElbowContact c = contact_of(elbow_at({0.3, 0, -0.15}, {table}));
  CHECK(approx(c.distance, -0.05 - kRadius, kExact));
  CHECK(approx(c.normal, -Eigen::Vector3d::UnitZ(), 1e-8));
}

TEST_CASE("box rotated 30 degrees about x: distance along the tilted face normal") {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(std::numbers::pi / 6, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0.2, -0.1, -0.3);
  const TableBox table = box(center, {1.0, 0.8, 0.1}, R);
  const Eigen::Vector3d n = R * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d on_face = center + R * Eigen::Vector3d(0.05, 0.1, 0.05);  // top face
  for (const double d : {0.2, 1e-3, 0.0, -5e-3}) {
    CAPTURE(d);
    const ElbowContact c = contact_of(elbow_at(on_face + (kRadius + d) * n, {table}));
    CHECK(approx(c.distance, d, kExact));
    CHECK(approx(c.normal, n, kExact));
    CHECK(approx(c.point, on_face, kExact));
  }
}

TEST_CASE("two boxes making a step: the record names the nearest box") {
  //              C    B                        A
  //   +----------+    o                        o
  //   | high (1) |C                                       z =  0.0
  //   |          |+-------------------------------+       z = -0.1
  //   |          ||          low (0)               |
  //  x=-0.5     x=0                              x=1
  const std::vector<TableBox> step = {box({0.5, 0, -0.15}, {1.0, 1.0, 0.1}),
                                      box({-0.25, 0, -0.1}, {0.5, 1.0, 0.2})};
  SUBCASE("A: over the low box, far from the step") {
    const ElbowContact c = contact_of(elbow_at({0.6, 0, 0.05}, step));
    CHECK(c.box == 0);
    CHECK(approx(c.distance, 0.15 - kRadius, kExact));
    CHECK(approx(c.normal, Eigen::Vector3d::UnitZ(), kExact));
  }
  SUBCASE("B: over the high box") {
    const ElbowContact c = contact_of(elbow_at({-0.2, 0, 0.05}, step));
    CHECK(c.box == 1);
    CHECK(approx(c.distance, 0.05 - kRadius, kExact));
  }
  SUBCASE("C: low, next to the step wall, which is nearer than the floor") {
    const ElbowContact c = contact_of(elbow_at({0.04, 0, -0.05}, step));
    CHECK(c.box == 1);
    CHECK(approx(c.distance, 0.04 - kRadius, kExact));
    CHECK(approx(c.normal, Eigen::Vector3d::UnitX(), kExact));
    CHECK(approx(c.point, Eigen::Vector3d(0, 0, -0.05), kExact));
  }
}

TEST_CASE("sphere beside an edge and a corner: the normal points from the edge to the centre") {
  // Box x in [-0.5, 0.5], y in [-0.4, 0.4], z in [-0.1, 0]; edge at x = 0.5, z = 0.
  const TableBox table = box({0, 0, -0.05}, {1.0, 0.8, 0.1});
  SUBCASE("edge") {
    const ElbowContact c = contact_of(elbow_at({0.53, 0.1, 0.04}, {table}));
    CHECK(approx(c.distance, 0.05 - kRadius, kExact));  // |(0.03, 0, 0.04)| = 0.05
    CHECK(approx(c.normal, Eigen::Vector3d(0.6, 0, 0.8), kExact));
    CHECK(approx(c.point, Eigen::Vector3d(0.5, 0.1, 0), kExact));
  }
  SUBCASE("edge, penetrating") {
    const ElbowContact c = contact_of(elbow_at({0.512, 0.1, 0.016}, {table}));
    CHECK(approx(c.distance, 0.02 - kRadius, kExact));  // |(0.012, 0, 0.016)| = 0.02
    CHECK(approx(c.normal, Eigen::Vector3d(0.6, 0, 0.8), kExact));
  }
  SUBCASE("corner") {
    const ElbowContact c = contact_of(elbow_at({0.52, 0.44, 0.04}, {table}));
    const Eigen::Vector3d offset(0.02, 0.04, 0.04);  // from the corner (0.5, 0.4, 0)
    CHECK(approx(c.distance, offset.norm() - kRadius, kExact));
    CHECK(approx(c.normal, offset.normalized(), kExact));
    CHECK(approx(c.point, Eigen::Vector3d(0.5, 0.4, 0), kExact));
  }
}

TEST_CASE("elbows on turned links: the sphere follows the link's world pose") {
  // Two links (0.3, 0.4); elbows at the middle of each; a table far below, top z = -0.5.
  Model m = elbowsim::testing::planar_arm({{0.3, 1, 0.15, 0.01}, {0.4, 1, 0.2, 0.01}});
  m.elbows = {Elbow{"e0", 0, {0.15, 0, 0}, 0.02}, Elbow{"e1", 1, {0.2, 0.05, 0}, 0.025}};
  m.table = {box({0, 0, -0.6}, {4, 4, 0.2})};
  finalize(m);
  Data data(m);
  const Eigen::Vector2d q(0.4, -1.3);
  forward_kinematics(m, data, q);
  CollisionWorld world(m);
  std::vector<ElbowContact> contacts;
  world.elbow_contacts(m, data, contacts);
  REQUIRE(contacts.size() == 2);
  for (int k = 0; k < 2; ++k) {
    const Elbow& e = m.elbows[k];
    const Eigen::Vector3d centre = point_position(data, e.link, e.point);
    CHECK(contacts[k].elbow == k);
    CHECK(approx(contacts[k].distance, centre.z() + 0.5 - e.radius, kExact));
    CHECK(approx(contacts[k].point, Eigen::Vector3d(centre.x(), centre.y(), -0.5), kExact));
  }
}

TEST_CASE("elbow_contacts allocates nothing after the first call") {
  const Model model = elbow_at({0.3, 0, 0.1}, {box({0.4, 0.1, -0.025}, {1.0, 0.8, 0.05})});
  Data data(model);
  forward_kinematics(model, data, Eigen::VectorXd::Zero(model.dof));
  CollisionWorld world(model);
  std::vector<ElbowContact> contacts;
  world.elbow_contacts(model, data, contacts);
  const long before = elbowsim::testing::allocation_count();
  for (int i = 0; i < 10; ++i) world.elbow_contacts(model, data, contacts);
  CHECK(elbowsim::testing::allocation_count() == before);
}

TEST_CASE("broad phase: the pairs whose Bullet bounds meet, widened by the margin") {
  //   o---- link 0 ----o               z = 0 (radius 0.02)
  //                      \  q2 < 0
  //   ====================\==========  table top z = -0.03
  //                        \ link 1 (0.4 m), tip at z = -0.4 sin(theta)
  Model m = elbowsim::testing::planar_arm({{0.3, 1, 0.15, 0.01}, {0.4, 1, 0.2, 0.01}});
  // Box 0 is a side table out of reach; box 1 the table under the arm.
  m.table = {box({-2, 2, -0.1}, {0.5, 0.5, 0.1}), box({0.5, 0, -0.28}, {2, 2, 0.5})};
  m.effects.contact = true;
  finalize(m);
  Data data(m);
  CollisionWorld world(m, data.contact.geometry);
  const int boxes = 2;
  const auto near = [&](double theta, double margin) {
    forward_kinematics(m, data, Eigen::Vector2d(0, -theta));
    std::vector<int> out;
    world.near_pairs(data, margin, out);
    return out;
  };
  // Primitives: link 0's capsule (0), link 1's (1). Level, 1 cm above the top.
  CHECK(near(0.0, 0.0).empty());
  CHECK(near(0.0, 0.011) == std::vector<int>{0 * boxes + 1, 1 * boxes + 1});
  // Link 1 dipped into the top: near without a margin; the side table never.
  CHECK(near(std::asin(0.045), 0.0) == std::vector<int>{1 * boxes + 1});
  CHECK(near(0.3, 1.0) == std::vector<int>{0 * boxes + 1, 1 * boxes + 1});
}

TEST_CASE("worlds_built() counts every CollisionWorld once") {
  const Model model = elbow_at({0.3, 0, 0.1}, {box({0, 0, -0.025}, {1, 1, 0.05})});
  const long before = CollisionWorld::worlds_built();
  {
    CollisionWorld a(model);
    CHECK(CollisionWorld::worlds_built() == before + 1);
    CollisionWorld b(model);
    CHECK(CollisionWorld::worlds_built() == before + 2);
  }
  CHECK(CollisionWorld::worlds_built() == before + 2);  // destroying does not count down
}
