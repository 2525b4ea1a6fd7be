#include "engine/contact/contact_data.hpp"

#include <limits>

namespace elbowsim {

ContactRows::ContactRows(int p, int n)
    : Jc(Eigen::MatrixXd::Zero(p, n)), Jf(Jc), gamma(Eigen::VectorXd::Zero(p)), C(gamma),
      Cd(gamma), fn(gamma), slide(gamma), Jf_qd(gamma), Y(Eigen::MatrixXd::Zero(n, p)), Z(Y),
      A(Eigen::MatrixXd::Zero(p, p)), rhs(gamma), lcp_b(gamma), lcp_f(gamma), lcp_w(gamma) {}

void ContactRows::swap(ContactRows& o) {
  Jc.swap(o.Jc), Jf.swap(o.Jf), gamma.swap(o.gamma), C.swap(o.C), Cd.swap(o.Cd);
  fn.swap(o.fn), slide.swap(o.slide), Jf_qd.swap(o.Jf_qd);
  Y.swap(o.Y), Z.swap(o.Z), A.swap(o.A), rhs.swap(o.rhs), lcp_b.swap(o.lcp_b), lcp_f.swap(o.lcp_f), lcp_w.swap(o.lcp_w);
}

SolverWorkspace::SolverWorkspace(int m, int n)
    : llt(m), lu(m), cod(m, m), rows_rank(m, n), block(Eigen::MatrixXd::Zero(m, m)),
      rhs(Eigen::VectorXd::Zero(m)), x(rhs), work(rhs), work_cols(rhs),
      Jc(Eigen::MatrixXd::Zero(m, n)), MinvJt(Eigen::MatrixXd::Zero(n, m)),
      dx(Eigen::VectorXd::Zero(n)), A(block), b(rhs), impulse(rhs), speed_before(rhs), speed_after(rhs),
      energy_lost(rhs), w(rhs) {}

ContactData::ContactData(ContactGeometry g, int boxes, int n, int capacity, int cone_capacity)
    : geometry(std::move(g)), cones(cone_capacity), lemke(capacity) {
  const auto slots = geometry.slots.size();
  const auto cap = static_cast<std::size_t>(capacity);
  resting.assign(slots, 0);
  active.reserve(cap);
  detected.assign(slots, SlotContact{false, std::numeric_limits<double>::infinity()});
  start_distance.assign(slots, std::numeric_limits<double>::infinity());
  // Until detected, a slot's ball sits where its part is (a segment's interior: at its start).
  for (std::size_t k = 0; k < slots; ++k) {
    const ContactSlot& s = geometry.slots[k];
    const Primitive& p = geometry.primitives[static_cast<std::size_t>(s.primitive)];
    detected[k].local = s.part == ContactSlot::Part::end_b ? p.b : p.a;
  }
  detected_q = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  normal.assign(slots, Eigen::Vector3d::UnitZ());
  surface.assign(slots, Eigen::Vector3d::Zero());
  feature.assign(slots, BoxFeature::face);
  edge.assign(slots, Eigen::Vector3d::Zero());
  sticking.assign(slots, 0);
  slip.assign(slots, Eigen::Vector3d::Zero());
  slip_stopped.assign(slots, 0);
  pad_release_depth.assign(slots, 0.0);
  pad_release_time.assign(slots, 0.0);
  may_stick.assign(slots, 0);
  was_sticking.assign(slots, 0);
  tangent_rows.reserve(cap);
  cone_slip = Eigen::VectorXd::Zero(cone_capacity);
  near_pairs.reserve(geometry.primitives.size() * static_cast<std::size_t>(boxes));
  a_free = Eigen::VectorXd::Zero(n);
  qd_before_impact = Eigen::VectorXd::Zero(n);
  J3 = link_omega = link_omega_dot = link_acc = Matrix3Xd::Zero(3, n);
  row_normal = row_friction = Matrix3Xd::Zero(3, capacity);
  for (auto* list : {&candidates, &landing, &impact_rows}) list->reserve(slots);
  events_found.reserve(slots);
  lcp_index.reserve(cap);
  lcp_active.reserve(slots);
  solvers.reserve(cap + 1);  // built in place: copying a factorisation reads its unset status
  spare_.reserve(cap + 1);
  for (int m = 0; m <= capacity; ++m) {
    solvers.emplace_back(m, n);
    spare_.emplace_back(m, n);
  }
  use_rows(0);
}

void ContactData::swap_rows(ContactRows& set) {
  Jc.swap(set.Jc), Jf.swap(set.Jf), gamma.swap(set.gamma), C.swap(set.C), Cd.swap(set.Cd);
  fn.swap(set.fn), slide.swap(set.slide), Jf_qd.swap(set.Jf_qd);
  Y.swap(set.Y), Z.swap(set.Z);
  A.swap(set.A), rhs.swap(set.rhs), lcp_b.swap(set.lcp_b), lcp_f.swap(set.lcp_f);
  lcp_w.swap(set.lcp_w);
}

void ContactData::use_rows(int p) {
  if (p == rows_in_use_) return;
  if (rows_in_use_ >= 0) swap_rows(spare_[static_cast<std::size_t>(rows_in_use_)]);  // give back
  swap_rows(spare_[static_cast<std::size_t>(p)]);  // take the set of size p
  rows_in_use_ = p;
  fn.setZero();
}

}  // namespace elbowsim
