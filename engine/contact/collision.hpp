// Collision detection between the arm and the table, the first of contact's three parts
// (detection -> rows -> solve). This header is Bullet-free; only collision_bullet.cpp
// includes Bullet.
//
// Bullet decides which of the arm's primitives (primitives.hpp) are near which table box:
// each primitive is a Bullet shape (a sphere, or a capsule along a segment) placed at its
// link's pose, and a primitive-box pair is near when their axis-aligned bounds, Bullet's
// getAabb, overlap once widened by contact.detection_margin (the broad phase). The distance,
// normal and point of a near pair then come in closed form from the feature of the box they
// lie on (geometry.hpp), which keeps a face normal exact and costs tens of nanoseconds where
// GJK costs ~0.4 us. Bullet's GJK (elbow_contacts) stays as the oracle the closed form is
// tested against.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

// Closest approach of one elbow sphere to the table (the nearest box), by Bullet's GJK.
struct ElbowContact {
  int elbow = -1;          // index into model.elbows
  int box = -1;            // nearest table box (-1, distance +inf when the table is empty)
  double distance = 0;     // [m] signed: sphere surface to box surface, < 0 when penetrating
  Eigen::Vector3d normal;  // unit, world, pointing from the table toward the elbow
  Eigen::Vector3d point;   // [m] world, the point on the table surface
};

// Bullet collision objects for one Model: a shape per primitive of `geometry` and a box per
// table box. Built once by reset() for a contact scene; queries read link poses from Data
// (forward_kinematics already done) and must get the Model it was built from.
class CollisionWorld {
 public:
  CollisionWorld(const Model& model, const ContactGeometry& geometry);
  explicit CollisionWorld(const Model& model);  // with contact_geometry(model)
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  // The broad phase: every (primitive, box) pair whose Bullet bounds, widened by `margin`
  // [m], overlap, as primitive * boxes + box in increasing order. Clears and fills `out`;
  // allocates nothing when out has the capacity primitives x boxes.
  void near_pairs(const Data& data, double margin, std::vector<int>& out);

  // The oracle: one record per elbow, elbow k against its nearest box by GJK (EPA deeper
  // than the radius). out is resized to model.elbows.size(); no allocation after that.
  void elbow_contacts(const Model& model, const Data& data, std::vector<ElbowContact>& out);

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
