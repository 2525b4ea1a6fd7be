// Collision detection between the arm and the table (DESIGN.md §3, "elbow contact";
// STYLE.md lesson 5: detection -> rows -> solve). This header is Bullet-free: the queries
// return plain records, and only collision_bullet.cpp includes Bullet.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

// Closest approach of one elbow sphere to the table (the nearest box).
struct ElbowContact {
  int elbow = -1;          // index into model.elbows
  int box = -1;            // nearest table box (-1, distance +inf when the table is empty)
  double distance = 0;     // [m] signed: sphere surface to box surface, < 0 when penetrating
  Eigen::Vector3d normal;  // unit, world, pointing from the table toward the elbow
  Eigen::Vector3d point;   // [m] world, the point on the table surface
};

// A link capsule (from data.origin[i] to the link's tip, radius link.radius) that reaches
// into the table.
struct LinkPenetration {
  int link = -1;     // index into model.links
  int box = -1;      // index into model.table
  double depth = 0;  // [m] > 0, the shortest move of the capsule that frees it from the box
};

// Bullet collision objects for one Model: a sphere per elbow, a capsule per link and a box
// per table box. Build it only when effects.contact is on; a query reads link poses from
// Data (forward_kinematics already done) and must get the Model it was built from.
class CollisionWorld {
 public:
  explicit CollisionWorld(const Model& model);  // builds spheres, capsules, boxes
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  // One record per elbow: out[k] is elbow k against its nearest box. out is resized to
  // model.elbows.size() (once: the caller keeps it); no heap allocation after the first call.
  // While the sphere centre is outside the box (distance > -radius) the distance is exact to
  // rounding (GJK); deeper, it comes from Bullet's iterative EPA (measured within 1e-11 m).
  void elbow_contacts(const Model& model, const Data& data, std::vector<ElbowContact>& out);

  // Link capsules deeper than model.contact.link_warning_depth in any box, one record per
  // (link, box) pair, sorted by link then box; clears and fills out. The capsule radius is
  // the link radius: elbow spheres are normally larger, so a link resting on its elbow does
  // not penetrate. Allocates only when more pairs overlap than on any earlier call.
  void link_penetrations(const Model& model, const Data& data, std::vector<LinkPenetration>& out);

  // How many CollisionWorld objects this process has built (a scene with contact off must
  // build none).
  static long worlds_built();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace elbowsim
