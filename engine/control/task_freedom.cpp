#include "engine/control/task_freedom.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "engine/control/inverse_kinematics.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

namespace {

int rank_of(const Eigen::MatrixXd& rows) {
  if (rows.rows() == 0) return 0;
  return numerical_rank(Eigen::JacobiSVD<Eigen::MatrixXd>(rows).singularValues());
}

// The ranks at one pose: of the elbows' rows, of the hand's, of both.
struct Ranks {
  int elbows = 0, hand = 0, all = 0;
};

// The kept elbows' rows at the pose forward_kinematics last left in data:
// a point each (3 rows) when they stick, else the table's normal.
Eigen::MatrixXd elbow_rows(const Model& model, Data& data, const std::vector<int>& elbows,
                           bool sticks) {
  const int per_elbow = sticks ? 3 : 1;
  Eigen::MatrixXd rows(per_elbow * int(elbows.size()), model.dof);
  Matrix3Xd J(3, model.dof);
  for (std::size_t r = 0; r < elbows.size(); ++r) {
    const Elbow& e = model.elbows[std::size_t(elbows[r])];
    point_jacobian(model, data, e.link, e.point, J);
    if (sticks) {
      rows.middleRows(3 * int(r), 3) = J;
    } else {
      const Eigen::Vector3d n = table_plane_under(model, point_position(data, e.link, e.point)).normal;
      rows.row(int(r)) = n.transpose() * J;
    }
  }
  return rows;
}

Ranks ranks_at(const Model& model, Data& data, const std::vector<int>& elbows, bool sticks,
               const Eigen::VectorXd& q) {
  forward_kinematics(model, data, q);
  const Eigen::MatrixXd rows = elbow_rows(model, data, elbows, sticks);
  Matrix3Xd J(3, model.dof);
  point_jacobian(model, data, model.hand_link, model.hand_point, J);
  Eigen::MatrixXd all(rows.rows() + 3, model.dof);
  all << rows, Eigen::MatrixXd(J);
  return {rank_of(rows), rank_of(Eigen::MatrixXd(J)), rank_of(all)};
}

}  // namespace

TaskFreedom task_freedom(const Model& model, const Experiment& experiment, const Eigen::VectorXd& q) {
  const HandTask& task = experiment.task;
  TaskFreedom out;
  out.joints = model.dof;
  for (const std::string& name : task.elbows)
    for (int k = 0; k < int(model.elbows.size()); ++k)
      if (model.elbows[std::size_t(k)].name == name) out.elbows.push_back(k);
  // As make_plan: held above the table, elbows keep a clearance (a plane row);
  // resting with Coulomb friction, they stick where they landed.
  out.sticks = model.has_coulomb_friction() && task.elbow_clearance == 0 && !out.elbows.empty();
  // Generic ranks: each only falls at special poses, so the largest of a few.
  Ranks best;
  Data data(model);
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd moved = q;
    for (int j = 0; j < model.dof; ++j) moved[j] += k == 0 ? 0.0 : 0.3 * std::sin(1.7 * k + 2.3 * j);
    const Ranks r = ranks_at(model, data, out.elbows, out.sticks, moved);
    best.elbows = std::max(best.elbows, r.elbows);
    best.hand = std::max(best.hand, r.hand);
    best.all = std::max(best.all, r.all);
  }
  out.elbow_rank = best.elbows;
  out.hand_rank = best.hand;
  out.hand_free = best.all - best.elbows;
  return out;
}

std::vector<bool> joints_held_by_table(const Model& model, const Experiment& experiment,
                                       const Eigen::VectorXd& q) {
  std::vector<bool> held(std::size_t(model.dof), false);
  const HandTask& task = experiment.task;
  if (!model.effects.contact || task.elbow_clearance != 0) return held;
  std::vector<int> elbows;
  for (const std::string& name : task.elbows)
    for (int k = 0; k < int(model.elbows.size()); ++k)
      if (model.elbows[std::size_t(k)].name == name) elbows.push_back(k);
  if (elbows.empty()) return held;
  Data data(model);
  forward_kinematics(model, data, q);
  const Eigen::MatrixXd rows =
      elbow_rows(model, data, elbows, model.has_coulomb_friction());
  // The motions that leave every row at rest: the rows' null space (the
  // right singular vectors past the rank). A joint with no share in any of
  // them cannot move while the elbows stay put.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rows, Eigen::ComputeFullV);
  const int rank = numerical_rank(svd.singularValues());
  const Eigen::MatrixXd free_motions = svd.matrixV().rightCols(model.dof - rank);
  for (int j = 0; j < model.dof; ++j)
    held[std::size_t(j)] = free_motions.cols() == 0 || free_motions.row(j).norm() < 1e-9;
  return held;
}

}  // namespace elbowsim
