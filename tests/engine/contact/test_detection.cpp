// engine/contact/detection.cpp: detect_contacts (forward kinematics at the q of data.x,
// then Bullet's distances) and normal_speed, on their own.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "engine/contact/collision.hpp"
#include "engine/contact/detection.hpp"
#include "engine/contact/geometry.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

constexpr double kRadius = 0.03;  // [m] elbow sphere
constexpr double kExact = 1e-9;   // [m] closed form (geometry.cpp): exact to rounding

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
    const SlotContact& c = data.contact.detected[0];
    const Eigen::Vector3d centre(0.3 * std::cos(q), 0, z0 + 0.3 * std::sin(q));
    CHECK(data.contact.primitive_of(0).elbow == 0);  // slot 0: the elbow on box 0
    CHECK(data.contact.slot(0).box == 0);
    CHECK(approx(c.distance, centre.z() - kRadius, kExact));  // negative below, as for q = -0.05
    CHECK(approx(c.normal, Eigen::Vector3d::UnitZ(), kExact));
    CHECK(approx(c.point, Eigen::Vector3d(centre.x(), 0, 0), kExact));
    // The rows of a step read the frame frozen from the detection when it starts.
    freeze_frames(data);
    CHECK(data.contact.normal[0] == c.normal);
    CHECK(data.contact.surface[0] == c.point);
    CHECK(data.contact.feature[0] == BoxFeature::face);
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
      CHECK(approx(data.contact.detected[0].normal,
                   Eigen::Vector3d(0, -std::sin(tilt), std::cos(tilt)), kExact));
      const double expected = std::cos(tilt) * 0.3 * std::cos(q) * qd;
      CHECK(approx(normal_speed(m, data, 0), expected, 1e-9));  // the normal is GJK's: 1e-9
      CHECK((normal_speed(m, data, 0) < 0) == (qd < 0));
    }
  }
}

TEST_CASE("detect_contacts: a link capsule's end and interior slots, exact depths, far slots +inf") {
  //   o---- link 0 ----o               z = 0 (radius 0.02)
  //                      \  q2 < 0
  //   ====================\==========  table top z = -0.03
  //                        \ link 1 (0.4 m), tip at z = -0.4 sin(theta)
  Model m = planar_arm({{0.3, 1, 0.15, 0.01}, {0.4, 1, 0.2, 0.01}});
  TableBox side, table;  // a side table out of reach, and the table under the arm
  side.center = Eigen::Vector3d(-2, 2, -0.1);
  side.size = Eigen::Vector3d(0.5, 0.5, 0.1);
  table.center = Eigen::Vector3d(0.5, 0, -0.28);
  table.size = Eigen::Vector3d(2, 2, 0.5);
  m.table = {side, table};
  m.effects.contact = true;
  m.contact.detection_margin = 0.02;  // the level arm below is 1 cm over the table
  finalize(m);
  Data data(m);
  data.contact.world = std::make_shared<CollisionWorld>(m, data.contact.geometry);
  // The slot of link 1's tip (its capsule's end b) on the table (box 1).
  int tip = -1;
  for (int k = 0; k < data.contact.slots(); ++k) {
    const Primitive& p = data.contact.primitive_of(k);
    if (p.link == 1 && data.contact.slot(k).part == ContactSlot::Part::end_b &&
        data.contact.slot(k).box == 1)
      tip = k;
  }
  REQUIRE(tip >= 0);
  for (double depth : {-0.005, 0.004, 0.008, 0.19 - 0.2 + 0.1}) {
    // The capsule's lowest point is the tip minus the radius: depth = 0.4 sin(theta) - 0.01.
    const double theta = std::asin((depth + 0.01) / 0.4);
    data.x.head(2) = Eigen::Vector2d(0, -theta);
    detect_contacts(m, data);
    CAPTURE(depth);
    CHECK(approx(data.contact.detected[tip].distance, -depth, 1e-12));
    CHECK(data.contact.detected[tip].normal == Eigen::Vector3d::UnitZ());  // the top face, exactly
    // Nothing of the arm is near the side table: its slots stay far.
    for (int k = 0; k < data.contact.slots(); ++k)
      if (data.contact.slot(k).box == 0 && data.contact.primitive_of(k).elbow < 0)
        CHECK(data.contact.detected[k].distance == std::numeric_limits<double>::infinity());
  }
  // A level arm 1 cm over the table: link 1's start is shared with link 0's tip
  // (one ball keeps the slots), so the table sees link 0's ends and link 1's tip.
  data.x.head(2).setZero();
  detect_contacts(m, data);
  CHECK(approx(data.contact.detected[tip].distance, 0.01, 1e-12));
}

TEST_CASE("detect_contacts: a capsule lying across the table's edge rests on its interior slot") {
  // One link 0.6 m along +x, 2 cm over a table whose edge is at x = 0.4, tilted
  // down 0.1 rad about the edge side: the nearest point of the segment is over the edge.
  Model m = planar_arm({{0.6, 1.0, 0.3, 0.03}});
  m.links[0].radius = 0.01;
  TableBox table;
  table.center = Eigen::Vector3d(-0.1, 0, -0.05);
  table.size = Eigen::Vector3d(1.0, 0.8, 0.1);  // top z = 0, edge x = 0.4
  m.table = {table};
  m.base.translation() = Eigen::Vector3d(0, 0, 0.05);
  m.effects.contact = true;
  finalize(m);
  Data data(m);
  data.contact.world = std::make_shared<CollisionWorld>(m, data.contact.geometry);
  data.x[0] = -0.2;  // the link goes down past the edge
  detect_contacts(m, data);
  int interior = -1;
  for (int k = 0; k < data.contact.slots(); ++k)
    if (data.contact.slot(k).part == ContactSlot::Part::interior) interior = k;
  REQUIRE(interior >= 0);
  const SlotContact& c = data.contact.detected[interior];
  // The segment z = 0.05 - x tan(0.2) (x along the link) passes the edge (0.4, 0) at height
  // 0.05 - 0.4 tan 0.2 = -0.031: it goes into the box before the edge; the nearest point of a
  // segment entering the box is its deepest point.
  CHECK(c.distance < 0);
  CHECK(c.feature == BoxFeature::face);  // inside the box: its rows rest on the nearest face
}
