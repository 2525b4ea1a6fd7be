// Closed-form contact geometry (engine/contact/geometry): spheres and
// segments against boxes, worked out by hand, against Bullet's GJK (the
// oracle: CollisionWorld) and against dense sampling.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "engine/contact/collision.hpp"
#include "engine/contact/geometry.hpp"
#include "engine/run/step.hpp"
#include "support/contact_scenes.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

TableBox make_box(const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                  const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  return TableBox{center, size, rotation};
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

}  // namespace

TEST_CASE("sphere over a box face: the face axis exactly, the distance along it") {
  //        o  centre, radius r
  //   -----+-----  top z = 0.05
  const TableBox box = make_box({0.1, 0, 0}, {1.0, 0.8, 0.1});
  for (double radius : {1e-9, 0.03}) {
    const BoxContact c = sphere_box({0.3, 0.2, 0.05 + radius + 1e-3}, radius, box);
    CAPTURE(radius);
    CHECK(c.feature == BoxFeature::face);
    CHECK(c.face_axis == 2);
    CHECK(c.normal == Eigen::Vector3d(0, 0, 1));  // exactly: no tilt from rounding
    CHECK(c.distance == doctest::Approx(1e-3).epsilon(1e-12));
    CHECK(c.point.isApprox(Eigen::Vector3d(0.3, 0.2, 0.05), 1e-15));
  }
  // A rotated box: the normal is exactly its rotated face axis.
  std::mt19937 rng(3);
  const Eigen::Matrix3d R = random_rotation(rng);
  const TableBox tilted = make_box({0, 0, 0}, {1, 1, 1}, R);
  const BoxContact c = sphere_box(R * Eigen::Vector3d(0.1, -0.2, 0.9), 0.1, tilted);
  CHECK(c.feature == BoxFeature::face);
  CHECK(c.normal == Eigen::Vector3d(R.col(2)));
  CHECK(c.distance == doctest::Approx(0.3).epsilon(1e-12));
}

TEST_CASE("sphere beside an edge, at a corner and inside: distances by hand") {
  const TableBox box = make_box({0, 0, 0}, {2, 2, 2});  // the cube [-1, 1]^3
  // Beside the edge x = 1, z = 1 (y inside): distance sqrt(0.3^2 + 0.4^2) - r.
  const BoxContact edge = sphere_box({1.3, 0.5, 1.4}, 0.1, box);
  CHECK(edge.feature == BoxFeature::edge);
  CHECK(edge.distance == doctest::Approx(0.5 - 0.1).epsilon(1e-15));
  CHECK(edge.normal.isApprox(Eigen::Vector3d(0.6, 0, 0.8), 1e-15));
  CHECK(edge.point.isApprox(Eigen::Vector3d(1, 0.5, 1), 1e-15));
  // At the corner (1, 1, 1), off by (1, 2, 2): distance 3 - r.
  const BoxContact corner = sphere_box({2, 3, 3}, 0.5, box);
  CHECK(corner.feature == BoxFeature::corner);
  CHECK(corner.distance == doctest::Approx(2.5).epsilon(1e-15));
  // Inside, nearest to the face y = -1 (0.1 away): distance -(0.1 + r).
  const BoxContact inside = sphere_box({0.2, -0.9, 0.5}, 0.05, box);
  CHECK(inside.feature == BoxFeature::inside);
  CHECK(inside.face_axis == 1);
  CHECK(inside.normal == Eigen::Vector3d(0, -1, 0));
  CHECK(inside.distance == doctest::Approx(-0.15).epsilon(1e-14));
  CHECK(inside.point.isApprox(Eigen::Vector3d(0.2, -1, 0.5), 1e-15));
}

TEST_CASE("sphere-box distances equal Bullet's GJK (the oracle) on random poses") {
  // One link with an elbow sphere at its middle; the base moves the sphere.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const TableBox box = make_box({u(rng), u(rng), u(rng)},
                                  {0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng)), 0.1 + std::abs(u(rng))},
                                  random_rotation(rng));
    const double radius = 0.01 + 0.05 * std::abs(u(rng));
    Model m = testing::planar_arm({{0.6, 1.0, 0.3, 0.03}});
    const Eigen::Vector3d centre = box.center + Eigen::Vector3d(u(rng), u(rng), u(rng));
    m.base.translation() = centre - Eigen::Vector3d(0.3, 0, 0);
    m.elbows.push_back(Elbow{"e", 0, Eigen::Vector3d(0.3, 0, 0), radius});
    m.table = {box};
    m.effects.contact = true;
    finalize(m);
    Data data(m);
    forward_kinematics(m, data, Eigen::VectorXd::Zero(1));
    CollisionWorld world(m);
    std::vector<ElbowContact> gjk;
    world.elbow_contacts(m, data, gjk);
    const BoxContact c = sphere_box(centre, radius, box);
    if (c.distance <= -radius) continue;  // centre inside: Bullet's EPA, not exact
    worst = std::max(worst, std::abs(c.distance - gjk[0].distance));
    CHECK(c.normal.dot(gjk[0].normal) > 1 - 1e-9);
  }
  MESSAGE("largest |closed form - GJK| distance: ", worst, " m");
  CHECK(worst < 1e-12);  // both exact to rounding outside the box
}

TEST_CASE("segment-box: the parameter found is the nearest (or deepest) point, against sampling") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int entering = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const TableBox box = make_box({0, 0, 0}, {0.4 + std::abs(u(rng)), 0.4 + std::abs(u(rng)), 0.2 + std::abs(u(rng))},
                                  random_rotation(rng));
    const Eigen::Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const double t = segment_box_parameter(a, b, box);
    REQUIRE(t >= 0);
    REQUIRE(t <= 1);
    const double found = sphere_box(a + t * (b - a), 0.0, box).distance;
    double best = 1e300;
    for (int k = 0; k <= 20000; ++k) {
      const double s = k / 20000.0;
      best = std::min(best, sphere_box(a + s * (b - a), 0.0, box).distance);
    }
    if (found < 0) ++entering;
    // Sampling can only do worse than the exact minimiser (up to rounding).
    CHECK(found <= best + 1e-14);
  }
  MESSAGE(entering, " of 400 random segments enter the box");
  CHECK(entering > 20);
  // A segment lying flat 1 cm over the top face: every point is equally near.
  const TableBox top = make_box({0, 0, -0.5}, {2, 2, 1});
  const double t = segment_box_parameter({-0.3, 0, 0.01}, {0.4, 0, 0.01}, top);
  CHECK(sphere_box(Eigen::Vector3d(-0.3 + 0.7 * t, 0, 0.01), 0, top).distance ==
        doctest::Approx(0.01).epsilon(1e-14));
  // Past an edge: z = 1.1 - x comes nearest to the edge (x = 1, z = 0) at
  // x = 1.05, t = 0.55, distance 0.05 sqrt(2).
  const double past_edge = segment_box_parameter({0.5, 0, 0.6}, {1.5, 0, -0.4}, top);
  CHECK(past_edge == doctest::Approx(0.55).epsilon(1e-12));
  const BoxContact edge = sphere_box(Eigen::Vector3d(0.5 + past_edge, 0, 0.6 - past_edge), 0, top);
  CHECK(edge.feature == BoxFeature::edge);
  CHECK(edge.distance == doctest::Approx(0.05 * std::sqrt(2.0)).epsilon(1e-12));
}

TEST_CASE("a static equilibrium stays static for any elbow radius: the face normal is exact") {
  // The leaning arm (contact_scenes.hpp) with the shoulder carrying half its load: the
  // table's force is the statics' (G1 - tau1) / (l1 cos q1), the accelerations zero.
  // With GJK's numerical normal a 1e-9 m sphere tilted the normal by rounding/radius.
  double force[2];
  int k = 0;
  for (double radius : {0.03, 1e-9}) {
    testing::ElbowArm arm;
    arm.r = radius;
    Model m = arm.model(0.5 * arm.G1(), 0.0);
    // Only the elbow touches: the links' 2 cm capsules would reach below a 1e-9 m ball.
    for (Link& link : m.links) link.collision.kind = LinkCollision::Kind::none;
    finalize(m);
    Data data(m);
    reset(m, data);
    CAPTURE(radius);
    REQUIRE(data.contact.rows() == 1);
    force[k++] = data.contact.fn[0];
    CHECK(data.contact.normal[0] == Eigen::Vector3d::UnitZ());
    CHECK(data.qdd.cwiseAbs().maxCoeff() <= 1e-12);
    CHECK(data.contact.fn[0] == doctest::Approx(arm.statics_force(0.5 * arm.G1())).epsilon(1e-12));
  }
  CHECK(force[0] == doctest::Approx(force[1]).epsilon(1e-12));
}
