// What of the arm can touch the table: collision primitives fixed on links
// (a ball: a point with a radius; a capsule: a segment with a radius), and
// the slots where each may touch each table box. Every slot is a potential
// unilateral row of M*; the rows of a step are its resting slots.
//
//   declared elbow          one ball per elbow (named: tasks and metrics refer to it)
//   link capsule (default)  one segment, from the link frame's origin to its tip
//   link sphere             one ball
//   link box                its 8 corners (balls of radius 0) and 12 edges
//                           (segments of radius 0, interior only)
// A segment touches a box at either end or, when its middle is nearer than
// both ends (lying across an edge), at its nearest interior point: three
// slots per box, so a capsule lying flat rests on two rows. Where two balls
// sit at the same point (a capsule's end at the joint where the next capsule
// starts), only the largest keeps its slots: equal rows would be dependent.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "engine/model.hpp"

namespace elbowsim {

struct Primitive {
  int link = -1;
  Eigen::Vector3d a = Eigen::Vector3d::Zero();  // [m] link frame: the ball's centre, a segment's first end
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  // [m] a segment's second end (== a for a ball)
  double radius = 0;                            // [m] >= 0
  int elbow = -1;                               // the declared elbow it is; -1: a link's own solid
  bool is_ball = true;
  bool end_a = true, end_b = true;              // the ends that have slots (segments)
  bool interior = true;                         // the interior has slots (segments)
};

struct ContactSlot {
  enum class Part { ball, end_a, end_b, interior };
  int primitive = -1;
  int box = -1;
  Part part = Part::ball;
};

struct ContactGeometry {
  std::vector<Primitive> primitives;  // elbows first (primitive k is elbow k), then links' solids
  std::vector<ContactSlot> slots;     // every (primitive part, box), by primitive, then box
  std::vector<int> first_slot;        // [primitives x boxes + 1]: slots of primitive k on box b
                                      // are first_slot[k B + b] .. first_slot[k B + b + 1] - 1
  int boxes = 0;
};

// The primitives and slots of a model (elbows, link collisions, table boxes).
ContactGeometry contact_geometry(const Model& model);

const char* to_string(ContactSlot::Part part);

// A slot's name for events and messages: an elbow's name, or link<i>.<part>
// (ball, end_a, end_b, interior; a box link's corner<k> / edge<k>), then
// @box<b> when the table has more than one box. No commas or spaces.
std::string slot_name(const Model& model, const ContactGeometry& geometry, int slot);

}  // namespace elbowsim
