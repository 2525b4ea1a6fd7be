// ABA's inward pass without velocities or torques (aba.hpp): the articulated
// inertias' projections U_i, D_i at the current q, for the response sweeps.
// A kernel written for SSE2's two-double registers: the accumulated 6 x 6 is
// symmetric, so only its upper 2 x 2 blocks are kept, as column pairs (12
// pairs, not 18), and every product, update and dot works on pairs.
#include "engine/dynamics/aba.hpp"

#include <cstring>

#include "engine/dynamics/spatial.hpp"

namespace elbowsim {

namespace {

// Two doubles in one register (GCC's and Clang's vector extension; SSE2 on
// x86-64): element-wise + - *, a double operand is broadcast. Not
// Eigen::Array2d: its constructor from two doubles goes through memory (two
// 8-byte stores, one 16-byte load), which stalls the load; Pair{a, b} is one
// register shuffle.
using Pair = double __attribute__((vector_size(16)));

// A 6-vector as three pairs: rows (0, 1), (2, 3), (4, 5).
struct Pairs {
  Pair p0 = {0, 0}, p1 = {0, 0}, p2 = {0, 0};
};

inline double sum(const Pair& v) { return v[0] + v[1]; }

inline double dot(const Pairs& a, const Pairs& b) {
  return sum(a.p0 * b.p0 + a.p1 * b.p1 + a.p2 * b.p2);
}

inline void store(const Pairs& v, Vector6d& out) {
  std::memcpy(out.data(), &v.p0, sizeof(Pair));
  std::memcpy(out.data() + 2, &v.p1, sizeof(Pair));
  std::memcpy(out.data() + 4, &v.p2, sizeof(Pair));
}

// A symmetric 6 x 6 in 2 x 2 blocks X_rk (rows 2r, 2r+1; columns 2k, 2k+1),
// the blocks with r <= k only (X_kr = X_rk^T), each as its two columns.
struct SymmetricBlocks {
  Pair x00[2] = {}, x01[2] = {}, x02[2] = {}, x11[2] = {}, x12[2] = {}, x22[2] = {};
};

// X^T s for a stored block X (the blocks below the diagonal): two dots.
inline Pair transposed_times(const Pair x[2], const Pair& s) {
  const Pair m0 = x[0] * s, m1 = x[1] * s;
  return Pair{m0[0], m1[0]} + Pair{m0[1], m1[1]};
}

// I += spatial_inertia(m, c, Ic) (spatial.hpp): [[A, m skew(c)], [m skew(c)^T,
// m 1]] with A = Ic + m ((c.c) 1 - c c^T), Ic's upper triangle (R Ic R^T is
// symmetric only up to rounding).
inline void add_body(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic,
                     SymmetricBlocks& I) {
  const double mx = m * c.x(), my = m * c.y(), mz = m * c.z();
  const double mcc = mx * c.x() + my * c.y() + mz * c.z();
  const double a00 = Ic(0, 0) + (mcc - mx * c.x()), a11 = Ic(1, 1) + (mcc - my * c.y());
  const double a22 = Ic(2, 2) + (mcc - mz * c.z());
  const double a01 = Ic(0, 1) - mx * c.y(), a02 = Ic(0, 2) - mx * c.z();
  const double a12 = Ic(1, 2) - my * c.z();
  I.x00[0] += Pair{a00, a01};
  I.x00[1] += Pair{a01, a11};
  I.x01[0] += Pair{a02, a12};
  I.x01[1] += Pair{0.0, mz};
  I.x02[0] += Pair{-mz, 0.0};
  I.x02[1] += Pair{my, -mx};
  I.x11[0] += Pair{a22, -my};
  I.x11[1] += Pair{-my, m};
  I.x12[0] += Pair{mx, 0.0};
  I.x22[0] += Pair{m, 0.0};
  I.x22[1] += Pair{0.0, m};
}

// W = I S; S's entries as doubles (broadcast) and as pairs.
inline Pairs times(const SymmetricBlocks& I, const double S[6], const Pairs& s) {
  Pairs W;
  W.p0 = (I.x00[0] * S[0] + I.x00[1] * S[1]) + (I.x01[0] * S[2] + I.x01[1] * S[3]) +
         (I.x02[0] * S[4] + I.x02[1] * S[5]);
  W.p1 = transposed_times(I.x01, s.p0) + (I.x11[0] * S[2] + I.x11[1] * S[3]) +
         (I.x12[0] * S[4] + I.x12[1] * S[5]);
  W.p2 = (transposed_times(I.x02, s.p0) + transposed_times(I.x12, s.p1)) +
         (I.x22[0] * S[4] + I.x22[1] * S[5]);
  return W;
}

// I -= U V^T for V = U / D (a symmetric rank-one term), upper blocks only.
inline void subtract_rank_one(const Pairs& U, const Pairs& V, SymmetricBlocks& I) {
  const double v[6] = {V.p0[0], V.p0[1], V.p1[0], V.p1[1], V.p2[0], V.p2[1]};
  for (int j = 0; j < 2; ++j) {
    I.x00[j] -= U.p0 * v[j];
    I.x01[j] -= U.p0 * v[2 + j];
    I.x02[j] -= U.p0 * v[4 + j];
    I.x11[j] -= U.p1 * v[2 + j];
    I.x12[j] -= U.p1 * v[4 + j];
    I.x22[j] -= U.p2 * v[4 + j];
  }
}

}  // namespace

// Featherstone's I^A_i: U_i = I^A_i S_i, D_i = S_i^T U_i + Jm_i,
// I^A_{i-1} = I_{i-1} + I^A_i - U_i U_i^T / D_i. The accumulator holds
// I_i + I^A_{i+1} before the child's projection, which is applied to U_i
// first: with a = U_{i+1}^T S_i and t = a / D_{i+1},
//   U_i = (I_i + I^A_{i+1}) S_i - U_{i+1} t,   D_i = S_i^T (I_i + I^A_{i+1}) S_i - a t + Jm_i.
// The chain from one joint to the next is then a 6-dot, a product and a
// division; the 6 x 6 product and update are off it. t is e_i
// (data.coupling), which the response sweeps use.
void articulated_inertias(const Model& model, Data& data) {
  SymmetricBlocks I;
  Pairs U_child, V_child;
  double D_inv_child = 0;
  for (int i = model.dof - 1; i >= 0; --i) {
    // S = [z; o x z] (revolute_subspace), built in registers.
    const Eigen::Vector3d& z = data.axis[i];
    const Eigen::Vector3d oz = data.origin[i].cross(z);
    const double S[6] = {z.x(), z.y(), z.z(), oz.x(), oz.y(), oz.z()};
    const Pairs s{Pair{S[0], S[1]}, Pair{S[2], S[3]}, Pair{S[4], S[5]}};
    store(s, data.motion_subspace[i]);
    add_body(model.links[i].mass, data.com[i], data.inertia[i], I);
    const Pairs W = times(I, S, s);
    const double a = dot(U_child, s);
    const double t = a * D_inv_child;
    const Pairs U{W.p0 - U_child.p0 * t, W.p1 - U_child.p1 * t, W.p2 - U_child.p2 * t};
    const double D = (dot(s, W) - a * t) + (model.has_armature() ? model.armature[i] : 0.0);
    // Now I^A_i; the last joint has no child to project, joint 0 no parent to pass it to.
    if (i > 0 && i < model.dof - 1) subtract_rank_one(U_child, V_child, I);
    const double D_inv = 1.0 / D;
    const Pairs V{U.p0 * D_inv, U.p1 * D_inv, U.p2 * D_inv};
    store(U, data.U[i]);
    store(V, data.U_over_D[i]);
    data.D[i] = D;
    data.D_inv[i] = D_inv;
    data.coupling[i] = t;
    U_child = U;
    V_child = V;
    D_inv_child = D_inv;
  }
}

}  // namespace elbowsim
