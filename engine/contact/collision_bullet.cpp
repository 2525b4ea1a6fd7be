// CollisionWorld on Bullet (BulletCollision + LinearMath only, never BulletDynamics).
// The only file of the program that includes Bullet: it turns Bullet's answers into the
// plain records of collision.hpp.
//
// Precision. Debian ships two builds of Bullet side by side: libBulletCollision.so (float)
// and libBulletCollision-float64.so (built with BT_USE_DOUBLE_PRECISION, see
// BulletConfig-float64.cmake). We link the float64 build and compile this file with
// BT_USE_DOUBLE_PRECISION (engine/CMakeLists.txt): btScalar, and with it the layout of
// btVector3 and btTransform, must match the library's, and a float build would limit
// distances to ~1e-7 m.
//
// Method. Each query is a pairwise closest-point problem solved by btGjkPairDetector:
// GJK between the shapes' cores (a sphere's centre, a capsule's segment, the box), minus
// the margins; EPA (btGjkEpaPenetrationDepthSolver) only when the cores overlap. We prefer
// it to btCollisionWorld::contactPairTest, which for every pair and call creates and frees
// a collision algorithm and a persistent manifold, needs a large distance threshold to
// report separated pairs at all, and (convex-convex algorithm) adds perturbed extra contact
// points we would have to filter out. GJK gives one signed distance, a normal and a point,
// for any separation, and allocates nothing.
//
// Margins. btSphereShape and btCapsuleShape carry their whole radius as margin, so their
// core is a point or a segment and GJK's answer minus the radius is exact. btBoxShape keeps
// its faces at the given half extents but rounds its edges and corners by its margin
// (default 0.04 m, shrunk to a tenth of the smallest half extent): we set the box margin to
// 0 so that the box is exactly the table box. Then, while a sphere's centre is outside the
// box (distance > -radius), the distance is exact to rounding.
//
// Broad phase. A link-box pair goes to GJK only when their axis-aligned bounding boxes
// (btCollisionShape::getAabb at the current poses) overlap, so links far from every box
// cost a few comparisons. We do not use btCollisionWorld's Dbvt broadphase: for a handful
// of links and boxes its tree and pair cache cost more than the direct test, and they grow
// (allocate) as pairs appear. Elbow queries cannot use AABBs (the nearest box may be far
// away): they try every box whose bounding sphere could still beat the best distance so far.
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <btBulletCollisionCommon.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <limits>

#include "engine/contact/collision.hpp"

#ifndef BT_USE_DOUBLE_PRECISION
#error "collision_bullet.cpp must be built with BT_USE_DOUBLE_PRECISION (Bullet's float64 build)"
#endif

namespace elbowsim {

namespace {

std::atomic<long> g_worlds_built{0};

// Bullet's allocations, counted (they go to malloc, unseen by operator new).
std::atomic<long> g_bullet_allocations{0};
void* counting_alloc(std::size_t size) {
  ++g_bullet_allocations;
  return std::malloc(size);
}
void counting_free(void* block) { std::free(block); }
const bool g_counting_installed = [] {
  btAlignedAllocSetCustom(counting_alloc, counting_free);
  return true;
}();


btVector3 to_bt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

Eigen::Vector3d to_eigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

btTransform to_bt(const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  const btMatrix3x3 basis(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1),
                          R(2, 2));
  return btTransform(basis, to_bt(p));
}

// Signed distance between two convex objects at their current poses (GJK, EPA when the
// cores overlap). The normal points from b toward a; the point lies on b's surface.
struct ClosestPoints {
  bool valid = false;
  double distance = std::numeric_limits<double>::infinity();  // [m] < 0 when penetrating
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

ClosestPoints closest_points(const btCollisionObject& a, const btCollisionObject& b,
                             btVoronoiSimplexSolver& simplex, btGjkEpaPenetrationDepthSolver& epa) {
  const auto* shape_a = static_cast<const btConvexShape*>(a.getCollisionShape());
  const auto* shape_b = static_cast<const btConvexShape*>(b.getCollisionShape());
  btGjkPairDetector gjk(shape_a, shape_b, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = a.getWorldTransform();
  input.m_transformB = b.getWorldTransform();
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;  // report any separation
  btPointCollector result;
  gjk.getClosestPoints(input, result, nullptr);
  ClosestPoints out;
  if (!result.m_hasResult) return out;
  out.valid = true;
  out.distance = result.m_distance;
  out.normal = to_eigen(result.m_normalOnBInWorld).normalized();
  out.point = to_eigen(result.m_pointInWorld);
  return out;
}

}  // namespace

struct CollisionWorld::Impl {
  std::vector<std::unique_ptr<btConvexShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> elbows, boxes;  // the GJK oracle's objects
  std::vector<const btConvexShape*> primitive_shape;  // [primitives]
  std::vector<btTransform> in_link;                   // [primitives] shape frame in its link frame
  std::vector<int> primitive_link;                    // [primitives]
  std::vector<Eigen::Vector3d> box_center;            // [boxes] world [m]
  std::vector<double> box_reach;                      // [boxes] half diagonal [m]
  std::vector<btVector3> box_min, box_max;            // [boxes] world AABB [m]
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;

  btConvexShape* own(std::unique_ptr<btConvexShape> shape) {
    shapes.push_back(std::move(shape));
    return shapes.back().get();
  }
  void add_object(btConvexShape* shape, const btTransform& pose,
                  std::vector<std::unique_ptr<btCollisionObject>>& list) {
    auto object = std::make_unique<btCollisionObject>();
    object->setCollisionShape(shape);
    object->setWorldTransform(pose);
    list.push_back(std::move(object));
  }
  // A sphere at a (link frame), or a capsule from a to b along its own x axis.
  void add_primitive(const Primitive& p) {
    const Eigen::Vector3d along = p.b - p.a;
    const double length = along.norm();
    primitive_link.push_back(p.link);
    if (length == 0) {
      primitive_shape.push_back(own(std::make_unique<btSphereShape>(p.radius)));
      in_link.push_back(to_bt(Eigen::Matrix3d::Identity(), p.a));
      return;
    }
    const Eigen::Matrix3d R =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), along).toRotationMatrix();
    primitive_shape.push_back(own(std::make_unique<btCapsuleShapeX>(p.radius, length)));
    in_link.push_back(to_bt(R, 0.5 * (p.a + p.b)));
  }
};

CollisionWorld::CollisionWorld(const Model& model) : CollisionWorld(model, contact_geometry(model)) {}

CollisionWorld::CollisionWorld(const Model& model, const ContactGeometry& geometry)
    : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  for (const Primitive& p : geometry.primitives) w.add_primitive(p);
  // The oracle's elbow spheres (poses set per query).
  for (const Elbow& e : model.elbows)
    w.add_object(w.own(std::make_unique<btSphereShape>(e.radius)), btTransform::getIdentity(),
                 w.elbows);
  // Table boxes with sharp edges (margin 0), fixed in the world.
  for (const TableBox& box : model.table) {
    auto shape = std::make_unique<btBoxShape>(to_bt(0.5 * box.size));
    shape->setMargin(0);
    const btTransform pose = to_bt(box.rotation, box.center);
    btVector3 lo, hi;
    shape->getAabb(pose, lo, hi);
    w.add_object(w.own(std::move(shape)), pose, w.boxes);
    w.box_center.push_back(box.center);
    w.box_reach.push_back(0.5 * box.size.norm());
    w.box_min.push_back(lo);
    w.box_max.push_back(hi);
  }
  ++g_worlds_built;
}

CollisionWorld::~CollisionWorld() = default;

long CollisionWorld::worlds_built() { return g_worlds_built.load(); }

long CollisionWorld::bullet_allocations() {
  (void)g_counting_installed;
  return g_bullet_allocations.load();
}

void CollisionWorld::elbow_contacts(const Model& model, const Data& data,
                                    std::vector<ElbowContact>& out) {
  Impl& w = *impl_;
  out.resize(model.elbows.size());
  for (int k = 0; k < static_cast<int>(model.elbows.size()); ++k) {
    // Sphere centre r = o_i + R_i p (link frame point p of link i).
    const Elbow& elbow = model.elbows[k];
    const Eigen::Vector3d centre =
        data.origin[elbow.link] + data.rotation[elbow.link] * elbow.point;
    btCollisionObject& sphere = *w.elbows[k];
    sphere.getWorldTransform().setOrigin(to_bt(centre));
    // Nearest box: the smallest signed distance over all boxes. A box whose bounding sphere
    // is already farther than the best distance cannot win; it is skipped without GJK
    // (~0.3-0.5 us per query in Bullet).
    ElbowContact& contact = out[k];
    contact = ElbowContact{k, -1, std::numeric_limits<double>::infinity(), Eigen::Vector3d::UnitZ(),
                           Eigen::Vector3d::Zero()};
    for (int b = 0; b < static_cast<int>(w.boxes.size()); ++b) {
      const double lower_bound = (centre - w.box_center[b]).norm() - w.box_reach[b] - elbow.radius;
      if (lower_bound >= contact.distance) continue;
      const ClosestPoints c = closest_points(sphere, *w.boxes[b], w.simplex, w.epa);
      if (!c.valid || c.distance >= contact.distance) continue;
      contact.box = b;
      contact.distance = c.distance;
      contact.normal = c.normal;
      contact.point = c.point;
    }
  }
}

void CollisionWorld::near_pairs(const Data& data, double margin, std::vector<int>& out) {
  Impl& w = *impl_;
  out.clear();
  const int boxes = static_cast<int>(w.boxes.size());
  const btVector3 widen(margin, margin, margin);
  for (int k = 0; k < static_cast<int>(w.primitive_shape.size()); ++k) {
    const int link = w.primitive_link[k];
    const btTransform pose = to_bt(data.rotation[link], data.origin[link]) * w.in_link[k];
    btVector3 lo, hi;
    w.primitive_shape[k]->getAabb(pose, lo, hi);
    lo -= widen;
    hi += widen;
    for (int b = 0; b < boxes; ++b)
      if (TestAabbAgainstAabb2(lo, hi, w.box_min[b], w.box_max[b])) out.push_back(k * boxes + b);
  }
}

}  // namespace elbowsim
