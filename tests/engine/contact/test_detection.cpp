// engine/contact/detection.cpp: detect_contacts (forward kinematics at the q of data.x,
// then Bullet's distances) and normal_speed, on their own.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "engine/contact/detection.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

constexpr double kRadius = 0.03;  // [m] elbow sphere
constexpr double kExact = 1e-9;   // [m] GJK between a point and a box (collision_bullet.cpp)

// One link 0.6 m long on a joint about -y, its base z0 above a table box whose top face is
// z = 0 (rotated by `tilt` about x through its top centre); the elbow sphere sits at the
// middle of the link, so its centre is (0.3 cos q, 0, z0 + 0.3 sin q).
Model elbow_over_table(double z0, double tilt = 0.0) {
  Model m = planar_arm({{0.6, 1.0, 0.3, 0.03}});
  m.base.translation() = Eigen::Vector3d(0, 0, z0);
  m.elbows = {Elbow{"mid", 0, Eigen::Vector3d(0.3, 0, 0), kRadius}};
  TableBox top;
  top.size = Eigen::Vector3d(1.0, 0.8, 0.05);
  top.rotation = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).toRotationMatrix();
  top.center = top.rotation * Eigen::Vector3d(0, 0, -0.025) + Eigen::Vector3d(0.3, 0, 0);
  m.table = {top};
  m.effects.contact = true;
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("detect_contacts: the analytic distance of the elbow sphere over the table top, at the q of x") {
  const double z0 = 0.04;
  const Model m = elbow_over_table(z0);
  Data data(m);
  for (const double q : {0.0, 0.1, -0.05, -0.04}) {
    CAPTURE(q);
    place(m, data, Eigen::VectorXd::Constant(1, q), Eigen::VectorXd::Zero(1), 0.0);
    data.q[0] = 1.0;  // not the state: detection must read data.x
    detect_contacts(m, data);
    const ElbowContact& c = data.contact.detected[0];
    const Eigen::Vector3d centre(0.3 * std::cos(q), 0, z0 + 0.3 * std::sin(q));
    CHECK(c.elbow == 0);
    CHECK(c.box == 0);
    CHECK(approx(c.distance, centre.z() - kRadius, kExact));  // negative below, as for q = -0.05
    CHECK(approx(c.normal, Eigen::Vector3d::UnitZ(), kExact));
    CHECK(approx(c.point, Eigen::Vector3d(centre.x(), 0, 0), kExact));
    // The stages read the table normal and point under each elbow from these copies.
    CHECK(data.contact.normal[0] == c.normal);
    CHECK(data.contact.surface[0] == c.point);
    // And the link frames are those of q (forward kinematics was run).
    CHECK(approx(data.rotation[0](2, 0), std::sin(q), 1e-15));
  }
}

TEST_CASE("normal_speed: the elbow centre's speed along the table normal, < 0 approaching") {
  // d/dt (0.3 sin q) = 0.3 cos q qd along z; along a face tilted by a about x, the
  // normal is (0, -sin a, cos a) and the speed is cos a times that. Rounding: 1e-15.
  for (const double tilt : {0.0, std::numbers::pi / 6}) {
    const Model m = elbow_over_table(0.04, tilt);
    Data data(m);
    for (const double qd : {-2.0, 0.5}) {
      const double q = 0.1;
      place(m, data, Eigen::VectorXd::Constant(1, q), Eigen::VectorXd::Constant(1, qd), 0.0);
      detect_contacts(m, data);
      CAPTURE(tilt);
      CAPTURE(qd);
      CHECK(approx(data.contact.normal[0],
                   Eigen::Vector3d(0, -std::sin(tilt), std::cos(tilt)), kExact));
      const double expected = std::cos(tilt) * 0.3 * std::cos(q) * qd;
      CHECK(approx(normal_speed(m, data, 0), expected, 1e-9));  // the normal is GJK's: 1e-9
      CHECK((normal_speed(m, data, 0) < 0) == (qd < 0));
    }
  }
}
