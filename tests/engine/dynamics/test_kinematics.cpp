// engine/dynamics/kinematics.cpp: point Jacobian and Jdot*qd against central finite
// differences of forward kinematics.
#include <doctest/doctest.h>

#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;

namespace {

Eigen::Vector3d position_at(const Model& model, Data& data, const Eigen::VectorXd& q, int link,
                            const Eigen::Vector3d& p) {
  forward_kinematics(model, data, q);
  return point_position(data, link, p);
}

}  // namespace

TEST_CASE("point Jacobian == finite differences of forward kinematics") {
  const int n = 7;
  const Model model = elbowsim::testing::random_chain(n, 11);
  Data data(model);
  const Eigen::VectorXd q = 2.0 * Eigen::VectorXd::Random(n);
  const Eigen::Vector3d p(0.1, -0.2, 0.05);
  const double h = 1e-6;
  for (int link = 0; link < n; ++link) {
    forward_kinematics(model, data, q);
    Matrix3Xd J(3, n);
    point_jacobian(model, data, link, p, J);
    Matrix3Xd J_fd(3, n);
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd qp = q, qm = q;
      qp[j] += h;
      qm[j] -= h;
      J_fd.col(j) = (position_at(model, data, qp, link, p) - position_at(model, data, qm, link, p)) / (2 * h);
    }
    // Central differences: error ~ h^2 |d3r| ~ 1e-12, plus roundoff 1e-16/h ~ 1e-10.
    CHECK(approx(J, J_fd, 1e-8));
  }
}

TEST_CASE("Jdot*qd == d/dt (J(q + t qd) qd) by finite differences; velocity == J qd") {
  const int n = 6;
  const Model model = elbowsim::testing::random_chain(n, 12);
  Data data(model);
  const Eigen::VectorXd q = 2.0 * Eigen::VectorXd::Random(n);
  const Eigen::VectorXd qd = 1.5 * Eigen::VectorXd::Random(n);
  const Eigen::Vector3d p(-0.1, 0.3, 0.2);
  const double h = 1e-5;
  for (int link = 0; link < n; ++link) {
    auto velocity_at = [&](double s) {
      forward_kinematics(model, data, q + s * qd);
      Matrix3Xd J(3, n);
      point_jacobian(model, data, link, p, J);
      return Eigen::Vector3d(J * qd);
    };
    const Eigen::Vector3d fd = (velocity_at(h) - velocity_at(-h)) / (2 * h);
    forward_kinematics(model, data, q);
    CHECK(approx(point_jacobian_dot_qd(data, link, p, qd), fd, 1e-7));
    CHECK(approx(point_velocity(data, link, p, qd), velocity_at(0.0), 1e-12));
  }
}

TEST_CASE("forward_kinematics at the last call's q reuses it; another q or model computes anew") {
  const Model a = elbowsim::testing::random_chain(6, 91), b = elbowsim::testing::random_chain(6, 92);
  const Eigen::VectorXd q1 = Eigen::VectorXd::Random(6), q2 = Eigen::VectorXd::Random(6);
  Data fresh(a), data(a);
  forward_kinematics(a, fresh, q1);
  forward_kinematics(a, data, q2);
  forward_kinematics(a, data, q1);  // back to q1: computed, not the q2 frames
  forward_kinematics(a, data, q1);  // the same q: kept
  for (int i = 0; i < 6; ++i) {
    CHECK(data.rotation[i] == fresh.rotation[i]);  // bit for bit
    CHECK(data.origin[i] == fresh.origin[i]);
    CHECK(data.inertia[i] == fresh.inertia[i]);
  }
  // Same q, another model (same sizes): its own frames.
  Data other(b);
  forward_kinematics(b, other, q1);
  forward_kinematics(b, data, q1);
  for (int i = 0; i < 6; ++i) CHECK(data.rotation[i] == other.rotation[i]);
  // A joint angle of -0 is not +0 to the test (bit for bit), yet gives the same frames.
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(6), minus_zero = -zero;
  forward_kinematics(a, data, zero);
  forward_kinematics(a, fresh, minus_zero);
  CHECK(data.rotation[5].isApprox(fresh.rotation[5], 1e-15));
}
