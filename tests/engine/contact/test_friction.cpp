// engine/contact/friction: the tangents of a contact (one for a planar arm,
// two otherwise), its contact point (the ball's surface under its centre, so
// a spinning ball slides there) and the sliding laws' scale.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/friction.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("tangent_basis: one tangent in a planar arm's plane, two orthonormal ones otherwise") {
  Model planar = planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.3, 0.8, 0.15, 0.008}});
  finalize(planar);
  REQUIRE(planar.planar_axis.norm() == doctest::Approx(1));
  const Eigen::Vector3d axis = planar.planar_axis;
  Eigen::Vector3d t1, t2;
  for (const double angle : {0.0, 0.3, 1.2, -2.5}) {
    // A normal in the arm's plane (the plane orthogonal to its joint axis).
    const Eigen::Vector3d n = Eigen::AngleAxisd(angle, axis) * Eigen::Vector3d::UnitZ();
    REQUIRE(std::abs(n.dot(axis)) < 1e-15);
    CHECK(tangent_basis(planar, n, t1, t2) == 1);
    CHECK(approx(t1.norm(), 1.0, 1e-15));
    CHECK(std::abs(t1.dot(n)) < 1e-15);
    CHECK(std::abs(t1.dot(axis)) < 1e-15);
    CHECK(t2.isZero());
  }
  // Tilted out of the plane, a planar arm's contact has two tangents too.
  const Eigen::Vector3d tilted = (Eigen::Vector3d::UnitZ() + 0.1 * axis).normalized();
  CHECK(tangent_basis(planar, tilted, t1, t2) == 2);

  const Model spatial = chain_with_elbows(5, 1, 41);
  REQUIRE(spatial.planar_axis.isZero());
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d n = trial < 3 ? Eigen::Vector3d::Unit(trial) : Eigen::Vector3d::Random().normalized();
    CAPTURE(n.transpose());
    REQUIRE(tangent_basis(spatial, n, t1, t2) == 2);
    CHECK(approx(t1.norm(), 1.0, 1e-15));
    CHECK(approx(t2.norm(), 1.0, 1e-15));
    CHECK(std::abs(t1.dot(n)) < 1e-15);
    CHECK(std::abs(t2.dot(n)) < 1e-15);
    CHECK(std::abs(t1.dot(t2)) < 1e-15);
    CHECK(approx(t1.cross(t2), n, 1e-15));  // right-handed: (t1, t2, n)
  }
}

TEST_CASE("contact point: the ball's surface point under its centre; its tangential velocity by differences") {
  const Model m = chain_with_elbows(6, 2, 43);
  Data data(m);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(6), qd = Eigen::VectorXd::Random(6);
  forward_kinematics(m, data, q);
  for (int k = 0; k < 2; ++k) {
    CAPTURE(k);
    const Primitive& ball = data.contact.primitive_of(k);
    const Eigen::Vector3d n = Eigen::Vector3d::Random().normalized();
    const Eigen::Vector3d local = contact_point_local(data, k, n);
    const Eigen::Vector3d centre = point_position(data, ball.link, data.contact.detected[k].local);
    CHECK(approx(point_position(data, ball.link, local), centre - ball.radius * n, 1e-15));

    // The contact point held in its link, moved along q + t qd: central
    // differences with h = 1e-6 (truncation ~h^2, rounding ~1e-16/h: 1e-9).
    const double h = 1e-6;
    Data moved(m);
    forward_kinematics(m, moved, q + h * qd);
    const Eigen::Vector3d up = point_position(moved, ball.link, local);
    forward_kinematics(m, moved, q - h * qd);
    const Eigen::Vector3d down = point_position(moved, ball.link, local);
    const Eigen::Vector3d v = (up - down) / (2 * h);
    const Eigen::Vector3d v_t = tangential_velocity(data, k, n, qd);
    CHECK(std::abs(v_t.dot(n)) < 1e-14);
    CHECK(approx(v_t, v - n * n.dot(v), 1e-9));
  }
}

TEST_CASE("contact point: a ball spinning on the spot slides at omega r; its centre is still") {
  // One link turning about -y at omega; a ball of radius r centred on the
  // joint axis, the table under it (n = +z). The contact point (0, 0, -r)
  // moves at omega x p: |v_t| = omega r, although the centre does not move.
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.01}});
  const double r = 0.05, omega = 2.0;
  m.elbows = {Elbow{"ball", 0, Eigen::Vector3d::Zero(), r}};
  m.table = {TableBox{Eigen::Vector3d(0, 0, -r - 0.05), Eigen::Vector3d(1, 1, 0.1)}};
  for (Link& link : m.links) link.collision.kind = LinkCollision::Kind::none;
  finalize(m);
  Data data(m);
  forward_kinematics(m, data, Eigen::VectorXd::Zero(1));
  const Eigen::VectorXd qd = Eigen::VectorXd::Constant(1, omega);
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d v_t = tangential_velocity(data, 0, n, qd);
  const Eigen::Vector3d w = omega * m.joints[0].axis;
  CHECK(approx(v_t, w.cross(Eigen::Vector3d(0, 0, -r)), 1e-15));
  CHECK(approx(v_t.norm(), omega * r, 1e-15));
  CHECK(point_velocity(data, 0, Eigen::Vector3d::Zero(), qd).norm() < 1e-15);
}

TEST_CASE("friction_scale: coulomb 1; tanh(v / tanh_velocity); v / max(v, slip_velocity)") {
  FrictionOptions f;
  f.tanh_velocity = 1e-3;
  f.slip_velocity = 1e-4;
  f.law = FrictionLaw::coulomb;
  for (const double v : {0.0, 1e-9, 1.0}) CHECK(friction_scale(f, v) == 1.0);
  f.law = FrictionLaw::tanh;
  CHECK(friction_scale(f, 0.0) == 0.0);
  CHECK(approx(friction_scale(f, 1e-3), std::tanh(1.0), 1e-15));
  CHECK(approx(friction_scale(f, 1e-6), 1e-3, 1e-9));  // slope 1 / tanh_velocity at 0
  CHECK(approx(friction_scale(f, 1.0), 1.0, 1e-15));
  f.law = FrictionLaw::saturated;
  CHECK(friction_scale(f, 0.0) == 0.0);
  CHECK(approx(friction_scale(f, 5e-5), 0.5, 1e-15));
  CHECK(friction_scale(f, 1e-4) == 1.0);
  CHECK(friction_scale(f, 3.0) == 1.0);
}
