// engine/control/inverse_kinematics.cpp: the table plane under a point, solve_ik on its
// own (hand and elbow rows, the posture in the null space, limits), and the plan's IK
// residuals on the paper's 4-link arm.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "engine/control/inverse_kinematics.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// A 3-link planar arm (x-z plane) with an elbow sphere at the end of link 0.
Model three_links() {
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.3, 0.8, 0.15, 0.008}, {0.2, 0.5, 0.1, 0.004}});
  m.elbows = {Elbow{"elbow", 0, Eigen::Vector3d(0.3, 0, 0), 0.03}};
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("table_plane_under: the top face of the box under the point, else of the nearest box") {
  Model m = three_links();
  TableBox flat, tilted;
  flat.center = Eigen::Vector3d(0, 0, -0.05), flat.size = Eigen::Vector3d(1, 1, 0.1);
  tilted.center = Eigen::Vector3d(2, 0, 0.3), tilted.size = Eigen::Vector3d(0.5, 0.5, 0.2);
  tilted.rotation = Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitY()).toRotationMatrix();
  m.table = {flat, tilted};
  const TablePlane a = table_plane_under(m, Eigen::Vector3d(0.3, -0.2, 0.5));
  CHECK(a.normal == Eigen::Vector3d::UnitZ());
  CHECK(approx(a.point, Eigen::Vector3d::Zero(), 1e-16));
  const TablePlane b = table_plane_under(m, Eigen::Vector3d(2.1, 0.1, 1.0));
  CHECK(b.normal == tilted.rotation.col(2));
  CHECK(approx(b.point, Eigen::Vector3d(tilted.center + tilted.rotation * Eigen::Vector3d(0, 0, 0.1)), 1e-15));
  // Over neither footprint: the box with the nearer centre.
  CHECK(table_plane_under(m, Eigen::Vector3d(1.7, 0.9, 0)).normal == tilted.rotation.col(2));
  CHECK(table_plane_under(m, Eigen::Vector3d(-0.8, 0.9, 0)).normal == Eigen::Vector3d::UnitZ());
  m.table.clear();  // no table: the default plane z = 0
  CHECK(table_plane_under(m, Eigen::Vector3d(1, 1, 1)).normal == Eigen::Vector3d::UnitZ());
}

TEST_CASE("solve_ik: hand on target and elbow at its clearance to 1e-12 m, residuals reported") {
  const Model m = three_links();
  Data data(m);
  const Eigen::Vector3d q0(-0.3, 0.8, 0.4);
  forward_kinematics(m, data, q0);
  const Eigen::Vector3d hand0 = point_position(data, m.hand_link, m.hand_point);
  IkProblem problem;
  problem.hand = hand0 + Eigen::Vector3d(-0.05, 0.0, -0.03);
  problem.elbows = {0};
  TablePlane plane;
  plane.point = Eigen::Vector3d(0, 0, -0.13);
  problem.planes = {plane};
  problem.clearance = 0.01;
  problem.posture = q0;
  const IkResult r = solve_ik(m, data, problem, q0);
  forward_kinematics(m, data, r.q);
  const double hand_miss = (point_position(data, m.hand_link, m.hand_point) - problem.hand).norm();
  const double elbow_gap = point_position(data, 0, m.elbows[0].point).z() - 0.03 + 0.13;
  MESSAGE("IK: ", r.iterations, " iterations, hand ", hand_miss, " m, elbow ", elbow_gap - 0.01, " m");
  // The undamped polish ends at ~1e-13 m (inverse_kinematics.hpp).
  CHECK(hand_miss < 1e-12);
  CHECK(std::abs(elbow_gap - 0.01) < 1e-12);
  CHECK(approx(r.hand_residual, hand_miss, 1e-15));
  CHECK(approx(r.elbow_residual, std::abs(elbow_gap - 0.01), 1e-15));
}

TEST_CASE("solve_ik: the redundancy goes to the posture (q - posture in the row space of J)") {
  // Hand only: 2 effective rows (x, z) for 3 joints, one free direction. At the solution
  // closest to the posture, q - posture has no component along the null space of J.
  // Converged to the polish: 1e-9 rad.
  const Model m = three_links();
  Data data(m);
  const Eigen::Vector3d posture(-0.2, 0.9, 0.5);
  forward_kinematics(m, data, posture);
  IkProblem problem;
  problem.hand = point_position(data, m.hand_link, m.hand_point) + Eigen::Vector3d(-0.04, 0, 0.06);
  problem.posture = posture;
  const IkResult r = solve_ik(m, data, problem, posture);
  CHECK(r.hand_residual < 1e-12);
  forward_kinematics(m, data, r.q);
  Matrix3Xd J(3, 3);
  point_jacobian(m, data, m.hand_link, m.hand_point, J);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::Vector3d null = svd.matrixV().col(2);  // J has rank 2 (no reach along y)
  CHECK(std::abs(null.dot(r.q - posture)) < 1e-9);
  CHECK((r.q - posture).norm() > 1e-3);  // it did move
}

TEST_CASE("solve_ik: joint limits clamp every iterate") {
  const Model m = three_links();
  Data data(m);
  const Eigen::Vector3d q0(-0.3, 0.8, 0.4);
  forward_kinematics(m, data, q0);
  IkProblem problem;
  problem.hand = point_position(data, m.hand_link, m.hand_point) + Eigen::Vector3d(0.1, 0, 0.1);
  problem.posture = q0;
  problem.q_min = Eigen::Vector3d::Constant(-0.35);
  problem.q_max = Eigen::Vector3d(-0.25, 2.0, 2.0);  // the shoulder kept in [-0.35, -0.25]
  const IkResult r = solve_ik(m, data, problem, q0);
  CHECK(r.q[0] >= -0.35);
  CHECK(r.q[0] <= -0.25);
  CHECK((r.q.array() >= problem.q_min.array()).all());
  CHECK((r.q.array() <= problem.q_max.array()).all());
}

TEST_CASE("IK: hand on its targets and the elbow on the table (or at its clearance) within 1e-9 m") {
  for (bool elbow_on : {true, false}) {
    WritingArm arm;
    arm.elbow_on = elbow_on;
    const auto [m, x] = arm.scene();
    const auto plan = make_plan(m, x);
    Data data(m);
    const Elbow& elbow = m.elbows[0];
    const double table_top = m.table[0].center.z() + m.table[0].size.z() / 2;
    double hand_worst = 0, elbow_worst = 0;
    for (std::size_t k = 0; k < plan->q.size(); k += 10) {
      forward_kinematics(m, data, plan->q[k]);
      hand_worst = std::max(hand_worst, (point_position(data, m.hand_link, m.hand_point) - plan->hand[k]).norm());
      const double gap = point_position(data, elbow.link, elbow.point).z() - elbow.radius - table_top;
      elbow_worst = std::max(elbow_worst, std::abs(gap - x.task.elbow_clearance));
    }
    CAPTURE(elbow_on);
    MESSAGE("IK residuals: hand ", hand_worst, " m, elbow ", elbow_worst, " m");
    CHECK(hand_worst < 1e-9);
    CHECK(elbow_worst < 1e-9);
    // The hand really moves along the 6 cm line.
    CHECK((plan->hand.back() - plan->hand.front()).norm() == doctest::Approx(std::hypot(0.06, 0.02)));
  }
}
