// engine/contact/primitives.cpp: what of the arm can touch the table (balls and
// capsules on links), and the slots (a primitive's part on a box) that become rows.
#include <doctest/doctest.h>

#include <string>

#include "engine/contact/primitives.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

//   o---- link 0 ----O---- link 1 ----o      O: the joint between them
//   =========================================  one box (or two)
Model two_links(int boxes) {
  Model m = planar_arm({{0.4, 1.0, 0.2, 0.01}, {0.3, 1.0, 0.15, 0.01}});
  for (int b = 0; b < boxes; ++b) m.table.push_back(TableBox{});
  return m;
}

std::vector<std::string> names(const Model& m) {
  const ContactGeometry g = contact_geometry(m);
  std::vector<std::string> out;
  for (int k = 0; k < static_cast<int>(g.slots.size()); ++k) out.push_back(slot_name(m, g, k));
  return out;
}

}  // namespace

TEST_CASE("capsules: the shared joint ball once; ends and interiors are slots, per box") {
  const Model m = two_links(1);
  const ContactGeometry g = contact_geometry(m);
  REQUIRE(g.primitives.size() == 2);
  // Link 1 starts where link 0 ends, with the same radius: link 0's end keeps the slot.
  CHECK(g.primitives[0].end_b);
  CHECK_FALSE(g.primitives[1].end_a);
  // Link 0's start sits on joint 0's axis, fixed: no slot.
  CHECK_FALSE(g.primitives[0].end_a);
  CHECK(names(m) == std::vector<std::string>{"link0.end_b", "link0.interior", "link1.end_b",
                                             "link1.interior"});
  // A thicker link 1 keeps the ball at the joint instead.
  Model thick = two_links(1);
  thick.links[1].radius = 0.03;
  CHECK(names(thick) == std::vector<std::string>{"link0.interior", "link1.end_a", "link1.end_b",
                                                 "link1.interior"});
}

TEST_CASE("an elbow first, its ball covering the capsule ends it sits on; boxes named when many") {
  Model m = two_links(2);
  m.elbows = {Elbow{"elbow", 0, Eigen::Vector3d(0.4, 0, 0), 0.03}};  // at the joint, larger
  const ContactGeometry g = contact_geometry(m);
  REQUIRE(g.primitives.size() == 3);
  CHECK(g.primitives[0].elbow == 0);
  CHECK_FALSE(g.primitives[1].end_b);  // link 0's tip: inside the elbow's ball
  CHECK_FALSE(g.primitives[2].end_a);  // link 1's start: the same point
  CHECK(names(m) == std::vector<std::string>{
                        "elbow@box0", "elbow@box1", "link0.interior@box0", "link0.interior@box1",
                        "link1.end_b@box0",
                        "link1.interior@box0", "link1.end_b@box1", "link1.interior@box1"});
  // The table of slots per (primitive, box) covers every slot once, in order.
  REQUIRE(g.first_slot.size() == 3 * 2 + 1);
  CHECK(g.first_slot.front() == 0);
  CHECK(g.first_slot.back() == static_cast<int>(g.slots.size()));
  for (std::size_t pair = 0; pair + 1 < g.first_slot.size(); ++pair)
    for (int k = g.first_slot[pair]; k < g.first_slot[pair + 1]; ++k) {
      CHECK(g.slots[k].primitive == static_cast<int>(pair) / 2);
      CHECK(g.slots[k].box == static_cast<int>(pair) % 2);
    }
}

TEST_CASE("link solids on request: a sphere, a box (8 corners, 12 edges), none") {
  Model m = two_links(1);
  m.links[0].collision.kind = LinkCollision::Kind::sphere;
  m.links[0].collision.center = Eigen::Vector3d(0.2, 0, 0);
  m.links[0].collision.radius = 0.05;
  m.links[1].collision.kind = LinkCollision::Kind::box;
  m.links[1].collision.center = Eigen::Vector3d(0.15, 0, 0);
  m.links[1].collision.size = Eigen::Vector3d(0.3, 0.04, 0.02);
  const ContactGeometry g = contact_geometry(m);
  REQUIRE(g.primitives.size() == 1 + 8 + 12);
  CHECK(g.primitives[0].is_ball);
  CHECK(g.primitives[0].radius == 0.05);
  CHECK(g.primitives[0].a == Eigen::Vector3d(0.2, 0, 0));
  int corners = 0, edges = 0;
  for (std::size_t k = 1; k < g.primitives.size(); ++k) {
    const Primitive& p = g.primitives[k];
    CHECK(p.link == 1);
    CHECK(p.radius == 0);
    if (p.is_ball) {
      ++corners;
      // Every corner is centre +- half the size on each axis.
      CHECK(std::abs(std::abs(p.a.x() - 0.15) - 0.15) < 1e-15);
      CHECK(std::abs(std::abs(p.a.y()) - 0.02) < 1e-15);
      CHECK(std::abs(std::abs(p.a.z()) - 0.01) < 1e-15);
    } else {
      ++edges;
      CHECK_FALSE(p.end_a);  // the corners are the edges' ends
      CHECK_FALSE(p.end_b);
      CHECK(p.interior);
    }
  }
  CHECK(corners == 8);
  CHECK(edges == 12);
  CHECK(g.slots.size() == 1 + 8 + 12);  // one slot each on the one box
  CHECK(slot_name(m, g, 1) == "link1.corner0");
  CHECK(slot_name(m, g, 9) == "link1.edge0");
  m.links[0].collision.kind = m.links[1].collision.kind = LinkCollision::Kind::none;
  CHECK(contact_geometry(m).primitives.empty());
}

TEST_CASE("link solids on request: a capsule between two points (a URDF cylinder's), or a ball "
          "when they meet") {
  Model m = two_links(1);
  m.links[0].collision.kind = m.links[1].collision.kind = LinkCollision::Kind::none;
  LinkCollision& c = m.links[1].collision;
  c.kind = LinkCollision::Kind::capsule;
  c.from = Eigen::Vector3d(0.02, 0.01, 0);
  c.to = Eigen::Vector3d(0.25, 0.01, 0);
  c.radius = 0.035;
  ContactGeometry g = contact_geometry(m);
  REQUIRE(g.primitives.size() == 1);
  CHECK_FALSE(g.primitives[0].is_ball);
  CHECK(g.primitives[0].link == 1);
  CHECK(g.primitives[0].a == c.from);
  CHECK(g.primitives[0].b == c.to);
  CHECK(g.primitives[0].radius == 0.035);
  c.to = c.from;
  g = contact_geometry(m);
  REQUIRE(g.primitives.size() == 1);
  CHECK(g.primitives[0].is_ball);
  CHECK(g.primitives[0].a == c.from);
}
