// engine/dynamics/crba.cpp: the composite-rigid-body mass matrix, checked against the
// paper's Walker-Orin matrix (the oracle), the parallel-axis theorem and the kinetic energy.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::random_chain;

namespace {

// One revolute joint carrying one link; motor none unless `armature`.
Model one_link(const Joint& joint, const Link& link, bool armature) {
  Model m;
  m.name = "one_link";
  m.dof = 1;
  m.joints = {joint};
  m.links = {link};
  m.effects.motor = armature ? MotorModel::full : MotorModel::none;
  m.effects.rotor_inertia = armature;
  m.motors = {elbowsim::testing::small_servo()};
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("mass matrix: Walker-Orin == CRBA (1e-10 relative), symmetric positive definite") {
  for (int n = 1; n <= 12; ++n) {
    CAPTURE(n);
    const Model model = random_chain(n, 100 + n);
    Data data(model);
    const Eigen::VectorXd q = 3.0 * Eigen::VectorXd::Random(n);
    forward_kinematics(model, data, q);
    mass_matrix_walker_orin(model, data);
    const Eigen::MatrixXd M_wo = data.mass_matrix;
    data.mass_matrix.setZero();
    mass_matrix_crba(model, data);
    const Eigen::MatrixXd M_crba = data.mass_matrix;
    const double scale = M_crba.cwiseAbs().maxCoeff();
    CHECK((M_wo - M_crba).cwiseAbs().maxCoeff() <= 1e-10 * scale);
    CHECK((M_crba - M_crba.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M_crba);
    CHECK(eig.eigenvalues().minCoeff() > 0);
  }
}

TEST_CASE("crba: one link about its joint is I_axis + m d^2 (parallel axes), at any q, plus Jm") {
  // The textbook case: axis z through the origin, com at distance d = 0.3 m on x.
  Joint z_joint;
  Link rod;
  rod.mass = 2.0;
  rod.com = Eigen::Vector3d(0.3, 0, 0);
  rod.inertia = Eigen::Vector3d(0.001, 0.015, 0.016).asDiagonal();
  // A general one: tilted joint frame and axis, com off the axis in all three directions,
  // a rotated inertia. d^2 = |a x c|^2 for the unit axis a, both in the link frame.
  Joint tilted;
  tilted.origin_rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  tilted.origin_position = Eigen::Vector3d(0.1, -0.2, 0.3);
  tilted.axis = Eigen::Vector3d(0.3, -0.5, 0.8);
  Link lump;
  lump.mass = 1.7;
  lump.com = Eigen::Vector3d(0.25, 0.05, -0.1);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(-1, 0.5, 2).normalized()).toRotationMatrix();
  lump.inertia = R * Eigen::Vector3d(0.02, 0.03, 0.04).asDiagonal() * R.transpose();
  const Eigen::Vector3d a = tilted.axis.normalized();
  const double expected_tilted = a.dot(lump.inertia * a) + lump.mass * a.cross(lump.com).squaredNorm();
  const double jm = 5e-7 * 50 * 50;  // small_servo: Im k^2
  for (bool armature : {false, true}) {
    const Model textbook = one_link(z_joint, rod, armature), general = one_link(tilted, lump, armature);
    Data data_t(textbook), data_g(general);
    for (double q : {0.0, 0.8, -2.5}) {
      CAPTURE(armature);
      CAPTURE(q);
      const Eigen::VectorXd qv = Eigen::VectorXd::Constant(1, q);
      forward_kinematics(textbook, data_t, qv);
      mass_matrix_crba(textbook, data_t);
      forward_kinematics(general, data_g, qv);
      mass_matrix_crba(general, data_g);
      // A handful of roundings on numbers of order 0.2: 1e-14 relative.
      CHECK(approx(data_t.mass_matrix(0, 0), 0.016 + 2.0 * 0.3 * 0.3 + (armature ? jm : 0.0), 0, 1e-14));
      CHECK(approx(data_g.mass_matrix(0, 0), expected_tilted + (armature ? jm : 0.0), 0, 1e-14));
    }
  }
}

TEST_CASE("crba: 1/2 qd^T (M + Jm) qd == the kinetic energy from link velocities (energy.cpp)") {
  // Two independent computations of T: M from composite inertias, T from each link's
  // v_c and omega (stored_energy). Rounding only: 1e-12 relative.
  for (int n = 1; n <= 8; ++n) {
    CAPTURE(n);
    const Model model = random_chain(n, 300 + n);
    Data data(model);
    const Eigen::VectorXd q = 3.0 * Eigen::VectorXd::Random(n), qd = 2.0 * Eigen::VectorXd::Random(n);
    forward_kinematics(model, data, q);
    mass_matrix_crba(model, data);
    EnergyTerms e;
    stored_energy(model, data, qd, data.current, e);
    const double from_m = 0.5 * qd.dot(data.mass_matrix * qd);
    CHECK(approx(from_m, e.kinetic_links + e.kinetic_rotors, 0, 1e-12));
  }
}
