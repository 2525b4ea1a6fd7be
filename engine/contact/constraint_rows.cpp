#include "engine/contact/constraint_rows.hpp"

#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

namespace {

// Friction part of row r: -mu t^T J_p at the contact point under the ball
// (centre `local` on `link`, radius r).
void friction_row(const Model& model, Data& data, int r, int link, const Eigen::Vector3d& local,
                  double radius, const Eigen::Vector3d& n, ConstVec qd) {
  ContactData& c = data.contact;
  const Eigen::Vector3d centre = point_position(data, link, local);
  const Eigen::Vector3d contact_world = centre - radius * n;
  const Eigen::Vector3d contact_local =
      data.rotation[link].transpose() * (contact_world - data.origin[link]);
  point_jacobian(model, data, link, contact_local, c.J3);
  const Eigen::Vector3d v = c.J3 * qd;
  const Eigen::Vector3d v_t = v - n * n.dot(v);
  const double speed = v_t.norm();
  c.slide[r] = speed;
  const Eigen::Vector3d t = v_t / std::max(speed, model.contact.slip_velocity);
  // Column by column: a dynamic row times J3 would evaluate into a heap temporary.
  for (Eigen::Index j = 0; j < c.J3.cols(); ++j)
    c.Jf(r, j) -= model.contact.friction * t.dot(c.J3.col(j));
}

}  // namespace

void constraint_rows(const Model& model, Data& data, ConstVec qd) {
  ContactData& c = data.contact;
  const int p = static_cast<int>(c.active.size());
  c.use_rows(p);  // p changes only between steps
  const double T = model.contact.baumgarte_time;
  for (int r = 0; r < p; ++r) {
    const int k = c.active[r];
    const Primitive& ball = c.primitive_of(k);
    const Eigen::Vector3d& local = c.detected[k].local;
    const Eigen::Vector3d& n = c.normal[k];
    point_jacobian(model, data, ball.link, local, c.J3);
    for (Eigen::Index j = 0; j < c.J3.cols(); ++j) c.Jc(r, j) = n.dot(c.J3.col(j));
    const Eigen::Vector3d centre = point_position(data, ball.link, local);
    c.C[r] = n.dot(centre - c.surface[k]) - ball.radius;
    c.Cd[r] = c.Jc.row(r).dot(qd);
    c.gamma[r] = -n.dot(point_jacobian_dot_qd(data, ball.link, local, qd));
    if (model.effects.stabilization == Stabilization::baumgarte)
      c.gamma[r] -= 2.0 / T * c.Cd[r] + c.C[r] / (T * T);
    c.Jf.row(r) = c.Jc.row(r);
    if (model.effects.friction) friction_row(model, data, r, ball.link, local, ball.radius, n, qd);
  }
}

}  // namespace elbowsim
