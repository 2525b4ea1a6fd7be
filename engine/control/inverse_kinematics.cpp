#include "engine/control/inverse_kinematics.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <limits>

#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

TablePlane table_plane_under(const Model& model, const Eigen::Vector3d& p) {
  int best = 0;
  double best_distance = 1e300;
  for (std::size_t b = 0; b < model.table.size(); ++b) {
    const TableBox& box = model.table[b];
    const Eigen::Vector3d local = box.rotation.transpose() * (p - box.center);
    const bool over =
        std::abs(local.x()) <= box.size.x() / 2 && std::abs(local.y()) <= box.size.y() / 2;
    const double d = over ? -1.0 : (p - box.center).norm();
    if (d < best_distance) best_distance = d, best = int(b);
  }
  TablePlane plane;
  if (model.table.empty()) return plane;
  plane.box = best;
  plane.over = best_distance < 0;
  const TableBox& box = model.table[best];
  plane.normal = box.rotation.col(2);
  plane.point = box.center + box.rotation * Eigen::Vector3d(0, 0, box.size.z() / 2);
  return plane;
}

namespace {

struct Rows {
  Eigen::MatrixXd J;
  Eigen::VectorXd e;
};

// Hand rows (3) then one row per elbow (its height over its plane), or three
// (its centre, when pinned): e = target - current.
void build_rows(const Model& model, Data& data, const IkProblem& problem, Rows& rows) {
  const int p = int(problem.elbows.size());
  const bool pinned = !problem.pins.empty();
  rows.J.resize(3 + p * (pinned ? 3 : 1), model.dof);
  rows.e.resize(rows.J.rows());
  Matrix3Xd J3(3, model.dof);
  point_jacobian(model, data, model.hand_link, model.hand_point, J3);
  rows.J.topRows(3) = J3;
  rows.e.head(3) = problem.hand - point_position(data, model.hand_link, model.hand_point);
  for (int k = 0; k < p; ++k) {
    const Elbow& elbow = model.elbows[problem.elbows[k]];
    const TablePlane& plane = problem.planes[k];
    point_jacobian(model, data, elbow.link, elbow.point, J3);
    const Eigen::Vector3d centre = point_position(data, elbow.link, elbow.point);
    if (pinned) {
      rows.J.middleRows(3 + 3 * k, 3) = J3;
      rows.e.segment(3 + 3 * k, 3) = problem.pins[k] - centre;
      continue;
    }
    rows.J.row(3 + k) = plane.normal.transpose() * J3;
    const double C = plane.normal.dot(centre - plane.point) - elbow.radius;
    rows.e[3 + k] = problem.clearance - C;
  }
}

// One iteration's two directions from the thin SVD of the rows J = U S V^T:
// the damped least-squares step on the error e, sum_i s_i / (s_i^2 + l_i^2)
// (u_i . e) v_i (l_i > 0 only below 1e-3 of the largest singular value, as
// near a stretched arm; none when undamped), and the posture error with its
// row-space part removed: its projection into the exact null space.
struct IkStep {
  Eigen::VectorXd rows;     // [n] toward meeting the rows
  Eigen::VectorXd to_null;  // [n] toward the posture, within the rows' null space
};

IkStep ik_step(const Rows& rows, const Eigen::VectorXd& to_posture, bool damp) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(rows.J, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double smax = s.size() ? s[0] : 0.0, eps = 1e-3 * smax, lambda_max = 1e-2 * smax;
  IkStep step{Eigen::VectorXd::Zero(rows.J.cols()), to_posture};
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s[i] <= 1e-12 * smax) continue;  // a row with no reach (e.g. y of a planar arm)
    double lambda2 = 0;
    if (damp && s[i] < eps) lambda2 = (1 - (s[i] / eps) * (s[i] / eps)) * lambda_max * lambda_max;
    const auto v = svd.matrixV().col(i);
    step.rows += s[i] / (s[i] * s[i] + lambda2) * svd.matrixU().col(i).dot(rows.e) * v;
    step.to_null -= v.dot(to_posture) * v;
  }
  return step;
}

// Joint limits as an active set: a joint at one of its limits that the step
// `dq` would push further out is held (its column of J and its posture error
// zeroed), so the step moves the others to do its part; a joint the step
// moves back inside is free. Without limits, or none held: `step` as it is.
IkStep limited_step(const Rows& rows, const Eigen::VectorXd& to_posture, bool damp, double gain,
                    const IkProblem& problem, const Eigen::VectorXd& q, IkStep step) {
  const bool low = problem.q_min.size() == q.size(), high = problem.q_max.size() == q.size();
  if (!low && !high) return step;
  const Eigen::VectorXd dq = step.rows + gain * step.to_null;
  Rows held = rows;
  Eigen::VectorXd posture = to_posture;
  bool any = false;
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    const bool out = (low && q[j] <= problem.q_min[j] && dq[j] < 0) ||
                     (high && q[j] >= problem.q_max[j] && dq[j] > 0);
    if (!out) continue;
    held.J.col(j).setZero();
    posture[j] = 0;
    any = true;
  }
  return any ? ik_step(held, posture, damp) : step;
}

void clamp_limits(const IkProblem& problem, Eigen::VectorXd& q) {
  if (problem.q_min.size() == q.size()) q = q.cwiseMax(problem.q_min);
  if (problem.q_max.size() == q.size()) q = q.cwiseMin(problem.q_max);
}

Eigen::VectorXd moved_singular_values(const Eigen::MatrixXd& J) {
  const Eigen::VectorXd norms = J.rowwise().norm();
  const double largest = norms.size() ? norms.maxCoeff() : 0.0;
  if (!(largest > 0)) return Eigen::VectorXd();
  Eigen::MatrixXd moved(J.rows(), J.cols());
  Eigen::Index rows = 0;
  for (Eigen::Index i = 0; i < J.rows(); ++i)
    if (norms[i] > 1e-12 * largest) moved.row(rows++) = J.row(i);
  return Eigen::JacobiSVD<Eigen::MatrixXd>(moved.topRows(rows)).singularValues();
}

// q += the largest of dq, dq/2, ... dq/2^10 that lowers |e| (rows: at q on
// entry); false, q unchanged: none does.
bool polish(const Model& model, Data& data, const IkProblem& problem, const Eigen::VectorXd& dq,
            Rows& rows, Eigen::VectorXd& q) {
  const double before = rows.e.norm();
  double scale = 1.0;
  for (int halving = 0; halving <= 10; ++halving, scale *= 0.5) {
    Eigen::VectorXd trial = q + scale * dq;
    clamp_limits(problem, trial);
    forward_kinematics(model, data, trial);
    build_rows(model, data, problem, rows);
    if (rows.e.norm() < before) {
      q = trial;
      return true;
    }
  }
  return false;
}

}  // namespace

int numerical_rank(const Eigen::VectorXd& s) {
  int rank = 0;
  while (rank < s.size() && s[rank] > 1e-9 * s[0]) ++rank;
  return rank;
}

double conditioning(const Eigen::VectorXd& s, int rank) {
  if (rank <= 0 || s.size() == 0 || !(s[0] > 0)) return 1;
  return s[std::min<Eigen::Index>(rank, s.size()) - 1] / s[0];
}

double arm_size(const Model& model) {
  double size = model.hand_point.norm();
  for (const Joint& joint : model.joints) size += joint.origin_position.norm();
  for (const Elbow& elbow : model.elbows) size = std::max(size, elbow.point.norm());
  return size > 0 ? size : 1.0;
}

namespace {

// Phase 1: rows and posture together. The posture step takes the scenario's
// gain while far from the nearest solution; once it is within 1e-3 rad and
// shrinking, the gain doubles each iteration up to 1 (in that linear regime
// the flow's end is a few steps away, and steps that small cannot jump to
// another branch of the self-motion). It ends when the rows are met to
// rounding and the posture step vanishes (the stationary point the small
// steps lead to), or after 200 iterations.
void follow_posture(const Model& model, Data& data, const IkProblem& problem, IkResult& result,
                    Rows& rows) {
  double gain = problem.posture_gain, last_null = std::numeric_limits<double>::infinity();
  const bool posture = problem.posture.size() == result.q.size() && problem.posture_gain > 0;
  for (int it = 0; it < 200; ++it, ++result.iterations) {
    forward_kinematics(model, data, result.q);
    build_rows(model, data, problem, rows);
    const Eigen::VectorXd to_posture =
        posture ? Eigen::VectorXd(problem.posture - result.q) : Eigen::VectorXd::Zero(result.q.size());
    const IkStep step = limited_step(rows, to_posture, true, posture ? gain : 0.0, problem, result.q,
                                     ik_step(rows, to_posture, true));
    const double null = step.to_null.norm();
    if (rows.e.norm() < 1e-13 && step.rows.norm() < 1e-12 && null < 1e-12) break;
    gain = null < 1e-3 && null < last_null ? std::min(1.0, 2 * gain) : problem.posture_gain;
    last_null = null;
    result.q += step.rows;
    if (posture) result.q += gain * step.to_null;
    clamp_limits(problem, result.q);
  }
}

}  // namespace

IkResult solve_ik(const Model& model, Data& data, const IkProblem& problem,
                  const Eigen::VectorXd& q0) {
  IkResult result;
  result.q = q0;
  Rows rows;
  follow_posture(model, data, problem, result, rows);
  // Phase 2: polish the rows alone, undamped. It inverts every singular value
  // above 1e-12 of the largest: near a singular pose (a straight chain) a
  // rounding-level error along a direction of singular value ~1e-11 asks for
  // a step of radians. Take a step only where it lowers the residual (halving
  // it up to 10 times); none does: the rows are met as well as they can be
  // (stationary: the residual's local minimum).
  result.stationary = false;
  for (int it = 0; it < 50; ++it, ++result.iterations) {
    forward_kinematics(model, data, result.q);
    build_rows(model, data, problem, rows);
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(result.q.size());
    const IkStep step =
        limited_step(rows, none, false, 0.0, problem, result.q, ik_step(rows, none, false));
    if (rows.e.norm() < 1e-13 && step.rows.norm() < 1e-12) break;
    if (!polish(model, data, problem, step.rows, rows, result.q) || step.rows.norm() < 1e-14) {
      result.stationary = true;
      break;
    }
  }
  forward_kinematics(model, data, result.q);
  build_rows(model, data, problem, rows);
  result.singular_values = moved_singular_values(rows.J);
  result.hand_residual = rows.e.head(3).norm();
  result.elbow_residual =
      rows.e.size() > 3 ? rows.e.tail(rows.e.size() - 3).cwiseAbs().maxCoeff() : 0.0;
  result.tolerance = 1e-8 * arm_size(model);
  result.rows_met = result.hand_residual <= result.tolerance && result.elbow_residual <= result.tolerance;
  return result;
}

}  // namespace elbowsim
