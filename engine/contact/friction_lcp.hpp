// Normal forces, sticking and slipping together (Coulomb friction, law
// coulomb): Stewart and Trinkle's linear complementarity problem.
//
// Rows of the contact system: normal rows [0, cn), then tangent rows; A is
// their Delassus matrix (row accelerations w = A f + b for row forces f; at
// an impact, velocities and impulses). Every normal row i is unilateral:
//   f_i >= 0,  w_i >= 0,  f_i w_i = 0.
// A contact with a cone (its normal row, 1 or 2 tangent rows, mu) replaces
// its tangent force by forces beta_d >= 0 along directions d that span the
// cone's facets: +-t for one tangent (the cone of a planar arm is exact: a
// box |f_t| <= mu f_n), 8 directions at 45 degrees for two (a polyhedral cone
// with 8 facets, inscribed in the circular one). With sigma >= 0, the slip
// acceleration (or speed) of the contact,
//   w_d   = d^T w_t + sigma >= 0,              beta_d w_d = 0,
//   w_sig = mu f_n - sum_d beta_d >= 0,        sigma w_sig = 0:
// a sticking contact (sigma = 0) has w_t = 0 and its force inside the cone; a
// slipping one (sigma > 0) slips along the direction d whose force is at the
// cone's edge, against it. Solved by Lemke's method (lemke.hpp): the matrix is
// not symmetric, and no other pivoting is finite on it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "engine/contact/lemke.hpp"

namespace elbowsim {

struct FrictionCone {
  int normal_row = 0;   // < cn
  int tangent_row = 0;  // its first tangent row (>= cn)
  int tangents = 1;     // 1 or 2
  double mu = 0;
};

// Scratch for problems of up to `capacity` LCP variables (normal rows plus 3
// per one-tangent cone, 9 per two-tangent cone), sized once.
struct FrictionLcpScratch {
  explicit FrictionLcpScratch(int capacity = 0);
  Eigen::MatrixXd M;          // [capacity x capacity]
  Eigen::VectorXd q, z, w;    // [capacity]
  LemkeScratch lemke;
  std::vector<FrictionCone> cones;  // the problem's cones (reserved)
  int capacity() const { return static_cast<int>(q.size()); }
};

struct FrictionLcpResult {
  bool solved = false;  // false: Lemke's method ended on a ray (no solution: Painleve) or the problem is too large
  int pivots = 0;
};

// LCP variables of the problem with cn normal rows and these cones.
int friction_lcp_size(int cn, const std::vector<FrictionCone>& cones);

// Solves the problem for A [R x R], b [R] (R = cn + tangent rows) and the
// cones in scratch.cones. Writes the row forces f [R] (normal forces; tangent
// forces along the tangent rows) and each cone's slip sigma [cones]; returns
// false (f, sigma unset) when there is no solution. Allocates nothing.
FrictionLcpResult solve_friction_lcp(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                     const Eigen::Ref<const Eigen::VectorXd>& b, int cn,
                                     FrictionLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> f,
                                     Eigen::Ref<Eigen::VectorXd> sigma);

}  // namespace elbowsim
