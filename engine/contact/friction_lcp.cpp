#include "engine/contact/friction_lcp.hpp"

#include <cmath>
#include <numbers>

namespace elbowsim {

namespace {

int directions(const FrictionCone& cone) { return cone.tangents == 1 ? 2 : 8; }

// Component j of direction d of a cone, in its tangent basis.
double coefficient(const FrictionCone& cone, int d, int j) {
  if (cone.tangents == 1) return d == 0 ? 1.0 : -1.0;
  const double angle = d * std::numbers::pi / 4;
  return j == 0 ? std::cos(angle) : std::sin(angle);
}

// Row i of A along direction d of `cone`: sum_j c_dj A(t_j, col) for every column.
double direction_row(const Eigen::Ref<const Eigen::MatrixXd>& A, const FrictionCone& cone, int d,
                     Eigen::Index col) {
  double sum = 0;
  for (int j = 0; j < cone.tangents; ++j) sum += coefficient(cone, d, j) * A(cone.tangent_row + j, col);
  return sum;
}

}  // namespace

FrictionLcpScratch::FrictionLcpScratch(int capacity)
    : M(Eigen::MatrixXd::Zero(capacity, capacity)), q(Eigen::VectorXd::Zero(capacity)), z(q), w(q),
      lemke(capacity) {
  cones.reserve(static_cast<std::size_t>(capacity));
}

int friction_lcp_size(int cn, const std::vector<FrictionCone>& cones) {
  int size = cn;
  for (const FrictionCone& cone : cones) size += directions(cone) + 1;
  return size;
}

FrictionLcpResult solve_friction_lcp(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                     const Eigen::Ref<const Eigen::VectorXd>& b, int cn,
                                     FrictionLcpScratch& s, Eigen::Ref<Eigen::VectorXd> f,
                                     Eigen::Ref<Eigen::VectorXd> sigma) {
  const std::vector<FrictionCone>& cones = s.cones;
  const int N = friction_lcp_size(cn, cones);
  if (N > s.capacity()) return {};
  auto M = s.M.topLeftCorner(N, N);
  auto q = s.q.head(N);
  M.setZero();
  // Normal rows against normal rows.
  M.topLeftCorner(cn, cn) = A.topLeftCorner(cn, cn);
  q.head(cn) = b.head(cn);
  int total_directions = 0;
  for (const FrictionCone& cone : cones) total_directions += directions(cone);
  const int sigma0 = cn + total_directions;
  int row = cn;  // first direction variable of the cone
  for (std::size_t k = 0; k < cones.size(); ++k) {
    const FrictionCone& cone = cones[k];
    for (int d = 0; d < directions(cone); ++d) {
      const int var = row + d;
      // Direction rows against normal forces, and normal rows against direction forces.
      for (int i = 0; i < cn; ++i) {
        M(var, i) = direction_row(A, cone, d, i);
        double sum = 0;
        for (int j = 0; j < cone.tangents; ++j) sum += coefficient(cone, d, j) * A(i, cone.tangent_row + j);
        M(i, var) = sum;
      }
      // Direction rows against direction forces of every cone.
      int col = cn;
      for (const FrictionCone& other : cones) {
        for (int e = 0; e < directions(other); ++e, ++col) {
          double sum = 0;
          for (int j = 0; j < other.tangents; ++j)
            sum += coefficient(other, e, j) * direction_row(A, cone, d, other.tangent_row + j);
          M(var, col) = sum;
        }
      }
      double bd = 0;
      for (int j = 0; j < cone.tangents; ++j) bd += coefficient(cone, d, j) * b[cone.tangent_row + j];
      q[var] = bd;
      M(var, sigma0 + static_cast<int>(k)) = 1.0;          // w_d = d^T w_t + sigma
      M(sigma0 + static_cast<int>(k), var) = -1.0;         // w_sig = mu f_n - sum beta
    }
    M(sigma0 + static_cast<int>(k), cone.normal_row) = cone.mu;
    q[sigma0 + static_cast<int>(k)] = 0.0;
    row += directions(cone);
  }
  LemkeResult lemke = solve_lemke(M, q, s.z.head(N), s.w.head(N), s.lemke);
  int pivots = lemke.pivots;
  // Dependent rows (more sticking rows than the arm has joints: statically
  // indeterminate forces) make the problem degenerate, and rounding can end
  // Lemke's method on a ray although solutions exist. A compliance of 1e-10
  // (then 1e-8) of the largest diagonal entry on the force variables makes it
  // positive definite there; the forces move by as much, relative.
  const double scale = M.diagonal().head(sigma0).cwiseAbs().maxCoeff();
  for (double compliance : {1e-10, 1e-8}) {
    if (lemke.solved) break;
    M.diagonal().head(sigma0).array() += compliance * scale;
    lemke = solve_lemke(M, q, s.z.head(N), s.w.head(N), s.lemke);
    pivots += lemke.pivots;
    M.diagonal().head(sigma0).array() -= compliance * scale;
  }
  if (!lemke.solved) return {false, pivots};
  // Row forces: normal forces, and each cone's tangent force from its directions.
  f.setZero();
  f.head(cn) = s.z.head(cn);
  row = cn;
  for (std::size_t k = 0; k < cones.size(); ++k) {
    const FrictionCone& cone = cones[k];
    for (int d = 0; d < directions(cone); ++d)
      for (int j = 0; j < cone.tangents; ++j)
        f[cone.tangent_row + j] += coefficient(cone, d, j) * s.z[row + d];
    sigma[static_cast<Eigen::Index>(k)] = s.z[sigma0 + static_cast<int>(k)];
    row += directions(cone);
  }
  return {true, pivots};
}

}  // namespace elbowsim
