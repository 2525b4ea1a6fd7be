// engine/contact/friction_lcp: Stewart and Trinkle's LCP gives forces that
// obey Coulomb's law, checked on the law itself (not on the LCP's variables):
// a block on a plane (stick below mu m g, slip above), random planar systems
// against every mode assignment enumerated, the 8-facet spatial cone,
// dependent rows, a problem with no solution, and no allocation.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>

#include "engine/contact/friction_lcp.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

constexpr double g = 9.81;

// A point mass m in the plane (x tangent, z normal) pushed by p along x: rows
// [n, t], A = I / m, b = (-g, p / m).
struct Block {
  double m = 2.0, mu = 0.5;
  Eigen::Vector2d f, w;
  double sigma = 0;
  bool solve(double p) {
    FrictionLcpScratch s(8);
    s.cones = {{0, 1, 1, mu}};
    const Eigen::Matrix2d A = Eigen::Matrix2d::Identity() / m;
    const Eigen::Vector2d b(-g, p / m);
    Eigen::VectorXd fv(2), sv(1);
    const bool solved = solve_friction_lcp(A, b, 1, s, fv, sv).solved;
    f = fv;
    w = A * f + b;
    sigma = sv[0];
    return solved;
  }
};

// Coulomb's law for planar contacts (one tangent each), rows [normals; tangents]:
// normal complementarity; |f_t| <= mu f_n; a sticking contact (sigma 0) does
// not slide; a sliding one's force is mu f_n against its slide, sigma = |w_t|.
void check_coulomb(const Eigen::VectorXd& f, const Eigen::VectorXd& w, const Eigen::VectorXd& sigma,
                   int cn, const std::vector<FrictionCone>& cones, double tol) {
  for (int i = 0; i < cn; ++i) {
    CHECK(f[i] >= -tol);
    CHECK(w[i] >= -tol);
    CHECK(std::abs(f[i] * w[i]) <= tol);
  }
  for (std::size_t k = 0; k < cones.size(); ++k) {
    const FrictionCone& c = cones[k];
    const double fn = f[c.normal_row], ft = f[c.tangent_row], wt = w[c.tangent_row];
    CAPTURE(k);
    CHECK(std::abs(ft) <= c.mu * fn + tol);
    if (sigma[k] <= tol) {
      CHECK(std::abs(wt) <= tol);
    } else {
      CHECK(approx(std::abs(wt), sigma[k], tol));
      CHECK(approx(ft, -c.mu * fn * (wt > 0 ? 1 : -1), tol));
    }
  }
}

// Every solution of the planar problem by enumeration: each contact off,
// sticking, or sliding toward +t or -t (f_t = -+mu f_n); its linear system
// solved and the law checked. Returns the solutions' forces.
std::vector<Eigen::VectorXd> enumerate_coulomb(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, int cn,
                                               const std::vector<FrictionCone>& cones) {
  const int R = static_cast<int>(b.size());
  std::vector<int> cone_of(cn, -1);
  for (std::size_t k = 0; k < cones.size(); ++k) cone_of[cones[k].normal_row] = static_cast<int>(k);
  std::vector<Eigen::VectorXd> solutions;
  int total = 1;
  for (int i = 0; i < cn; ++i) total *= cone_of[i] >= 0 ? 4 : 2;
  for (int code = 0; code < total; ++code) {
    // Modes: 0 off, 1 stick (or on, without a cone), 2 slide +t, 3 slide -t.
    std::vector<int> mode(cn);
    int rest = code;
    for (int i = 0; i < cn; ++i) {
      const int options = cone_of[i] >= 0 ? 4 : 2;
      mode[i] = rest % options;
      rest /= options;
    }
    // Unknowns f (R); equations: off -> f_n = 0 and f_t = 0; stick -> w_n = 0, w_t = 0;
    // slide +-t -> w_n = 0 and f_t = -+mu f_n. Rows without a cone: off/on.
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(R, R);
    Eigen::VectorXd e = Eigen::VectorXd::Zero(R);
    for (int i = 0; i < cn; ++i) {
      const int k = cone_of[i];
      const int t = k >= 0 ? cones[k].tangent_row : -1;
      if (mode[i] == 0) {
        E(i, i) = 1;
        if (t >= 0) E(t, t) = 1;
        continue;
      }
      E.row(i) = A.row(i);
      e[i] = -b[i];
      if (t < 0) continue;
      if (mode[i] == 1) {
        E.row(t) = A.row(t);
        e[t] = -b[t];
      } else {
        E(t, t) = 1;
        E(t, i) = (mode[i] == 2 ? 1 : -1) * cones[k].mu;
      }
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(E);
    if (lu.rank() < R) continue;
    const Eigen::VectorXd f = lu.solve(e);
    const Eigen::VectorXd w = A * f + b;
    bool valid = true;
    const double tol = 1e-9;
    for (int i = 0; i < cn && valid; ++i) {
      valid = f[i] >= -tol && w[i] >= -tol;
      const int k = cone_of[i];
      if (k < 0 || mode[i] == 0 || !valid) continue;
      const double wt = w[cones[k].tangent_row];
      if (mode[i] == 1) valid = std::abs(f[cones[k].tangent_row]) <= cones[k].mu * f[i] + tol;
      if (mode[i] == 2) valid = wt >= -tol;  // slides toward +t: force -mu f_n
      if (mode[i] == 3) valid = wt <= tol;
    }
    if (valid) solutions.push_back(f);
  }
  return solutions;
}

}  // namespace

TEST_CASE("friction LCP: a block on a plane sticks up to mu m g and slides beyond it") {
  Block block;
  const double limit = block.mu * block.m * g;
  for (const double share : {0.0, 0.3, 0.99, -0.7, 1.01, 1.5, -2.0}) {
    const double p = share * limit;
    CAPTURE(share);
    REQUIRE(block.solve(p));
    CHECK(approx(block.f[0], block.m * g, 1e-12));
    if (std::abs(share) <= 1) {
      CHECK(approx(block.f[1], -p, 1e-12));
      CHECK(std::abs(block.w[1]) < 1e-12);
      CHECK(block.sigma == 0);
    } else {
      // Slides along the push, friction mu m g against it; sigma its acceleration.
      const double sign = share > 0 ? 1 : -1;
      CHECK(approx(block.f[1], -sign * limit, 1e-12));
      CHECK(approx(block.w[1], (p - sign * limit) / block.m, 1e-12));
      CHECK(approx(block.sigma, std::abs(block.w[1]), 1e-12));
    }
  }
}

TEST_CASE("friction LCP: random planar systems obey Coulomb's law and match a mode enumeration") {
  // A = J W^-1 J^T for random J (rows: normals, then tangents of the contacts
  // with a cone) and a random SPD W on more joints than rows: positive definite,
  // as for independent rows. Every problem is solved; its forces are one of the
  // enumerated solutions (unique when A is, most often).
  std::mt19937 rng(17);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> mu_of(0.1, 1.0);
  int matched = 0, problems = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int cn = 1 + trial % 3;
    const int with_cones = 1 + (trial / 3) % cn;  // the first ones have cones
    const int R = cn + with_cones, dofs = R + 1 + trial % 3;
    Eigen::MatrixXd J(R, dofs), B(dofs, dofs);
    for (auto& v : J.reshaped()) v = normal(rng);
    for (auto& v : B.reshaped()) v = normal(rng);
    const Eigen::MatrixXd W = B * B.transpose() + 0.5 * Eigen::MatrixXd::Identity(dofs, dofs);
    const Eigen::MatrixXd A = J * W.llt().solve(J.transpose());
    Eigen::VectorXd b(R);
    for (auto& v : b) v = normal(rng);
    b.head(cn).array() -= 1.0;  // pressed, mostly
    FrictionLcpScratch s(friction_lcp_size(cn, {}) + 3 * with_cones);
    for (int k = 0; k < with_cones; ++k) s.cones.push_back({k, cn + k, 1, mu_of(rng)});
    const std::vector<FrictionCone> cones = s.cones;
    Eigen::VectorXd f(R), sigma(with_cones);
    CAPTURE(trial);
    const FrictionLcpResult r = solve_friction_lcp(A, b, cn, s, f, sigma);
    const std::vector<Eigen::VectorXd> solutions = enumerate_coulomb(A, b, cn, cones);
    REQUIRE(!solutions.empty());
    REQUIRE(r.solved);
    const Eigen::VectorXd w = A * f + b;
    // Pivoting on O(1) data: rounding ~1e-14; 1e-9 leaves room for conditioning.
    check_coulomb(f, w, sigma, cn, cones, 1e-9);
    ++problems;
    for (const Eigen::VectorXd& e : solutions)
      if (approx(f, e, 1e-8)) {
        ++matched;
        break;
      }
  }
  MESSAGE(matched, " of ", problems, " LCP solutions found among the enumerated ones");
  CHECK(matched == problems);
}

TEST_CASE("friction LCP: the 8-facet cone holds up to mu f_n cos(pi/8) in every direction, dissipates beyond mu f_n") {
  // A point mass m (rows n, t1, t2; A = I / m) pushed by p at angle theta.
  const double m = 1.5, mu = 0.6, limit = mu * m * g;
  const double inscribed = limit * std::cos(std::numbers::pi / 8);
  FrictionLcpScratch s(16);
  const Eigen::Matrix3d A = Eigen::Matrix3d::Identity() / m;
  Eigen::VectorXd f(3), sigma(1);
  for (int i = 0; i < 16; ++i) {
    const double theta = i * std::numbers::pi / 8 + 0.05 * i;
    for (const double share : {0.0, 0.5, 0.999, 1.01, 2.0}) {
      // Up to the inscribed circle, or beyond the circumscribed one.
      const double p = share <= 1 ? share * inscribed : share * limit;
      const Eigen::Vector2d push = p * Eigen::Vector2d(std::cos(theta), std::sin(theta));
      const Eigen::Vector3d b(-g, push[0] / m, push[1] / m);
      s.cones = {{0, 1, 2, mu}};
      CAPTURE(theta);
      CAPTURE(share);
      REQUIRE(solve_friction_lcp(A, b, 1, s, f, sigma).solved);
      const Eigen::Vector3d w = A * f + b;
      const Eigen::Vector2d ft = f.tail(2), wt = w.tail(2);
      CHECK(approx(f[0], m * g, 1e-12));
      CHECK(ft.norm() <= limit * (1 + 1e-12));  // inside the circular cone
      if (share <= 1) {
        CHECK(approx(ft, Eigen::Vector2d(-push), 1e-12));
        CHECK(wt.norm() < 1e-12);
        CHECK(sigma[0] < 1e-12);  // rounding of the pivots on O(10) data
      } else {
        CHECK(ft.norm() >= inscribed * (1 - 1e-12));  // on the octagon's edge
        CHECK(ft.dot(wt) < 0);                        // against the slide
        CHECK(sigma[0] > 0);
        CHECK(wt.dot(push) > 0);                      // slides along the push
      }
    }
  }
}

TEST_CASE("friction LCP: dependent rows (two contacts at one point) are solved; the totals are the block's") {
  // The block of the first case on two coincident contacts: rows n1, n2, t1, t2
  // of rank 2. The split between them is indeterminate; the totals are not.
  const double m = 2.0, mu = 0.5, p = 0.6 * mu * m * g;
  Eigen::MatrixXd J(4, 2);
  J << 0, 1, 0, 1, 1, 0, 1, 0;  // (x, z) of the point mass
  const Eigen::MatrixXd A = J * J.transpose() / m;
  const Eigen::Vector4d b = J * Eigen::Vector2d(p / m, -g);
  FrictionLcpScratch s(16);
  s.cones = {{0, 2, 1, mu}, {1, 3, 1, mu}};
  Eigen::VectorXd f(4), sigma(2);
  REQUIRE(solve_friction_lcp(A, b, 2, s, f, sigma).solved);
  // A compliance of 1e-8 of the diagonal at most (friction_lcp.cpp): 1e-7 relative.
  CHECK(approx(f[0] + f[1], m * g, 1e-7 * m * g));
  CHECK(approx(f[2] + f[3], -p, 1e-7 * m * g));
  for (int k = 0; k < 2; ++k) {
    CHECK(f[k] >= 0);
    CHECK(std::abs(f[2 + k]) <= mu * f[k] * (1 + 1e-7) + 1e-9);
  }
  const Eigen::Vector4d w = A * f + b;
  CHECK(w.cwiseAbs().maxCoeff() < 1e-6);  // both stick, both press
}

TEST_CASE("friction LCP: no solution is reported, not returned; no allocation") {
  // A normal row whose force pulls it into the table (A_nn < 0, as sliding
  // friction can make it: Painleve): w = -f - 1 >= 0 has no f >= 0.
  FrictionLcpScratch s(8);
  Eigen::MatrixXd A(1, 1);
  A << -1.0;
  Eigen::VectorXd b(1), f(1), sigma(1);
  b << -1.0;
  CHECK_FALSE(solve_friction_lcp(A, b, 1, s, f, sigma).solved);

  // Too large for the scratch: refused.
  FrictionLcpScratch small(2);
  small.cones = {{0, 1, 1, 0.5}};
  const Eigen::Matrix2d A2 = Eigen::Matrix2d::Identity();
  const Eigen::Vector2d b2(-1, 0.1);
  Eigen::VectorXd f2(2), sigma2(1);
  CHECK_FALSE(solve_friction_lcp(A2, b2, 1, small, f2, sigma2).solved);

  FrictionLcpScratch big(16);
  big.cones = {{0, 1, 2, 0.5}};
  const Eigen::Matrix3d A3 = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d b3(-1, 0.7, 0.2);
  Eigen::VectorXd f3(3), sigma3(1);
  const long before = allocation_count();
  const bool solved = solve_friction_lcp(A3, b3, 1, big, f3, sigma3).solved;
  CHECK(allocation_count() == before);
  CHECK(solved);
}
