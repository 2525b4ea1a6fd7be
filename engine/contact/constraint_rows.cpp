#include "engine/contact/constraint_rows.hpp"

#include <algorithm>

#include "engine/contact/friction.hpp"
#include "engine/contact/pad.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

namespace {

// Slot k's ball centre x (velocity v) against the feature of its frame: the
// unit normal n from the feature to x, the distance rho of x from it, and the
// curvature term dn/dt . v. A face's normal is fixed; on an edge's line or at
// a corner point n turns as x moves across it.
struct FeatureDistance {
  Eigen::Vector3d n;
  double rho = 0;
  double curvature = 0;  // [m/s^2]
};

FeatureDistance feature_distance(const ContactData& c, int k, const Eigen::Vector3d& x,
                                 const Eigen::Vector3d& v) {
  FeatureDistance f;
  Eigen::Vector3d d = x - c.surface[k], dv = v;
  if (c.feature[k] == BoxFeature::edge) {
    const Eigen::Vector3d& e = c.edge[k];
    d -= e * e.dot(d);
    dv -= e * e.dot(v);
  }
  const double rho = d.norm();
  // A ball of radius 0 on an edge or a corner has no direction of its own: the
  // frame's normal holds it (then a plane through the feature, like a face).
  if (c.feature[k] == BoxFeature::face || rho < 1e-12) {
    f.n = c.normal[k];
    f.rho = f.n.dot(x - c.surface[k]);
    return f;
  }
  f.n = d / rho;
  f.rho = rho;
  const double along = f.n.dot(dv);
  f.curvature = (dv.squaredNorm() - along * along) / rho;
  return f;
}

// The rates of links 0 .. last with qdd = 0 (outward_rates, kinematics.hpp),
// once per call: every row then reads
// its point's Jdot qd in O(1) instead of sweeping the chain again. When
// bias_torques() has just run at this state (the constrained step: it needs
// the bias anyway), its outward pass holds the same rates and none is swept.
void link_rates(Data& data, int last, ConstVec qd) {
  ContactData& c = data.contact;
  c.rates_in_data = data.bias_rates_serial == data.kinematics_serial &&
                    same_bits(qd, data.bias_rates_qd);
  if (c.rates_in_data) return;
  outward_rates(data, last, qd, c.link_omega, c.link_omega_dot, c.link_acc);
}

// Jdot qd of the point x (world) of `link`, from link_rates(). Rates from
// bias_torques() carry gravity in the origin's acceleration (-g at the base).
Eigen::Vector3d rates_jacobian_dot_qd(const Model& model, const Data& data, int link,
                                      const Eigen::Vector3d& x) {
  const ContactData& c = data.contact;
  const Eigen::Vector3d d = x - data.origin[link];
  if (c.rates_in_data) {
    const Eigen::Vector3d& omega = data.omega[link];
    Eigen::Vector3d acc = data.origin_acc[link];
    if (model.effects.gravity) acc += model.gravity;
    return acc + data.omega_dot[link].cross(d) + omega.cross(omega.cross(d));
  }
  const Eigen::Vector3d omega = c.link_omega.col(link);
  return c.link_acc.col(link) + c.link_omega_dot.col(link).cross(d) + omega.cross(omega.cross(d));
}

// Row r of Jc = t^T J(x) for the point x (world) of `link`: joint j moves x by
// z_j x (x - o_j) for j <= link, not at all beyond (no 3 x n Jacobian formed).
void project_row(const Model& model, const Data& data, int r, int link, const Eigen::Vector3d& x,
                 const Eigen::Vector3d& t, ContactData& c) {
  for (int j = 0; j <= link; ++j) c.Jc(r, j) = t.dot(data.axis[j].cross(x - data.origin[j]));
  for (int j = link + 1; j < model.dof; ++j) c.Jc(r, j) = 0.0;
}

// Sliding friction on normal row r of slot k (normal n): Jf -= mu s^T J_p,
// with s the slip direction scaled by the law.
void sliding_friction(const Model& model, Data& data, int r, int k, const Eigen::Vector3d& n, ConstVec qd) {
  ContactData& c = data.contact;
  const FrictionOptions& friction = model.contact.friction;
  const int link = c.primitive_of(k).link;
  point_jacobian(model, data, link, contact_point_local(data, k, n), c.J3);
  const Eigen::Vector3d v = c.J3 * qd;
  const Eigen::Vector3d v_t = v - n * n.dot(v);
  const double speed = v_t.norm();
  c.slide[r] = speed;
  Eigen::Vector3d s = speed > 0 ? Eigen::Vector3d(v_t / speed) : Eigen::Vector3d::Zero();
  if (friction.law == FrictionLaw::coulomb) {
    // Against the slip, in the direction the slip was given when it began (a
    // planar arm's single tangent, with the slip's sign), or as it is once it
    // is faster than stick_velocity.
    Eigen::Vector3d t1, t2;
    if (tangent_basis(model, n, t1, t2) == 1)
      s = c.slip[k].dot(t1) >= 0 ? t1 : Eigen::Vector3d(-t1);
    else if (speed <= friction.stick_velocity)
      s = c.slip[k];
  }
  s *= friction.mu * friction_scale(friction, speed);
  c.row_friction.col(r) = -s;
  for (Eigen::Index j = 0; j < c.J3.cols(); ++j) c.Jf(r, j) -= s.dot(c.J3.col(j));
}

void normal_row(const Model& model, Data& data, int r, ConstVec qd) {
  ContactData& c = data.contact;
  const double T = model.contact.baumgarte_time;
  const int k = c.active[r];
  const Primitive& ball = c.primitive_of(k);
  const Eigen::Vector3d& local = c.detected[k].local;
  const Eigen::Vector3d centre = point_position(data, ball.link, local);
  // The centre's velocity matters only where the normal turns (edge, corner).
  const Eigen::Vector3d v = c.feature[k] == BoxFeature::face
                                ? Eigen::Vector3d::Zero()
                                : point_velocity(data, ball.link, local, qd);
  const FeatureDistance f = feature_distance(c, k, centre, v);
  c.row_normal.col(r) = f.n;
  project_row(model, data, r, ball.link, centre, f.n, c);
  c.C[r] = f.rho - ball.radius;
  c.Cd[r] = c.Jc.row(r).dot(qd);
  if (const Pad* pad = slot_pad(model, c, k)) {
    c.gamma[r] = pad_force(*pad, c.C[r], c.Cd[r]);  // the row's prescribed force (pad.hpp)
  } else {
    c.gamma[r] = -f.n.dot(rates_jacobian_dot_qd(model, data, ball.link, centre)) - f.curvature;
    if (model.effects.stabilization == Stabilization::baumgarte)
      c.gamma[r] -= 2.0 / T * c.Cd[r] + c.C[r] / (T * T);
  }
  c.Jf.row(r) = c.Jc.row(r);
  c.slide[r] = 0;
  c.row_friction.col(r).setZero();
  const bool slides = model.effects.friction && model.contact.friction.mu > 0 &&
                      (model.contact.friction.law != FrictionLaw::coulomb || !c.sticking[k]);
  if (slides) sliding_friction(model, data, r, k, f.n, qd);
}

// Tangent row r of a sticking slot: its contact point must not slip.
void tangent_row(const Model& model, Data& data, int r, ConstVec qd) {
  ContactData& c = data.contact;
  const TangentRow& row = c.tangent_rows[static_cast<std::size_t>(r - c.normal_rows())];
  const Eigen::Vector3d n = c.row_normal.col(row.normal_row);
  Eigen::Vector3d t[2];
  tangent_basis(model, n, t[0], t[1]);
  const Eigen::Vector3d& tangent = t[row.axis];
  const int link = c.primitive_of(row.slot).link;
  const Eigen::Vector3d point = point_position(data, link, contact_point_local(data, row.slot, n));
  project_row(model, data, r, link, point, tangent, c);
  c.C[r] = 0;
  c.Cd[r] = c.Jc.row(r).dot(qd);
  c.gamma[r] = -tangent.dot(rates_jacobian_dot_qd(model, data, link, point));
  if (model.effects.stabilization == Stabilization::baumgarte)
    c.gamma[r] -= c.Cd[r] / model.contact.baumgarte_time;
  c.Jf.row(r) = c.Jc.row(r);
  c.slide[r] = 0;
}

}  // namespace

void constraint_rows(const Model& model, Data& data, ConstVec qd) {
  ContactData& c = data.contact;
  const int pn = c.normal_rows();
  const int p = pn + static_cast<int>(c.tangent_rows.size());
  c.use_rows(p);  // p changes only between steps
  int last = -1;
  for (int r = 0; r < pn; ++r) last = std::max(last, c.primitive_of(c.active[r]).link);
  for (const TangentRow& row : c.tangent_rows) last = std::max(last, c.primitive_of(row.slot).link);
  link_rates(data, last, qd);
  for (int r = 0; r < pn; ++r) normal_row(model, data, r, qd);
  for (int r = pn; r < p; ++r) tangent_row(model, data, r, qd);
}

}  // namespace elbowsim
