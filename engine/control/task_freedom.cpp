#include "engine/control/task_freedom.hpp"

#include <Eigen/SVD>

#include "engine/control/inverse_kinematics.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

namespace {

int rank_of(const Eigen::MatrixXd& rows) {
  if (rows.rows() == 0) return 0;
  return numerical_rank(Eigen::JacobiSVD<Eigen::MatrixXd>(rows).singularValues());
}

}  // namespace

TaskFreedom task_freedom(const Model& model, const Experiment& experiment, const Eigen::VectorXd& q) {
  const HandTask& task = experiment.task;
  TaskFreedom out;
  out.joints = model.dof;
  Data data(model);
  forward_kinematics(model, data, q);
  // As make_plan: held above the table, elbows keep a clearance (a plane row);
  // resting with Coulomb friction, they stick where they landed.
  for (const std::string& name : task.elbows)
    for (int k = 0; k < int(model.elbows.size()); ++k)
      if (model.elbows[std::size_t(k)].name == name) out.elbows.push_back(k);
  out.sticks = model.has_coulomb_friction() && task.elbow_clearance == 0 && !out.elbows.empty();
  const int per_elbow = out.sticks ? 3 : 1;
  Eigen::MatrixXd rows(per_elbow * int(out.elbows.size()), model.dof);
  Matrix3Xd J(3, model.dof);
  for (std::size_t r = 0; r < out.elbows.size(); ++r) {
    const Elbow& e = model.elbows[std::size_t(out.elbows[r])];
    point_jacobian(model, data, e.link, e.point, J);
    if (out.sticks) {
      rows.middleRows(3 * int(r), 3) = J;
    } else {
      const Eigen::Vector3d n = table_plane_under(model, point_position(data, e.link, e.point)).normal;
      rows.row(int(r)) = n.transpose() * J;
    }
  }
  point_jacobian(model, data, model.hand_link, model.hand_point, J);
  Eigen::MatrixXd all(rows.rows() + 3, model.dof);
  all << rows, Eigen::MatrixXd(J);
  out.elbow_rank = rank_of(rows);
  out.hand_rank = rank_of(Eigen::MatrixXd(J));
  out.hand_free = rank_of(all) - out.elbow_rank;
  return out;
}

}  // namespace elbowsim
