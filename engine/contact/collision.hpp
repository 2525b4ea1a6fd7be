// Collision detection between the arm and the table, the first of contact's three parts
// (detection -> rows -> solve). This header is Bullet-free: the queries return the plain
// records of contact_data.hpp, and only collision_bullet.cpp includes Bullet.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

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

  // How many blocks Bullet has allocated in this process (its btAlignedAlloc, which
  // bypasses operator new): a query must not add to it once the world exists.
  static long bullet_allocations();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace elbowsim
