#include "engine/contact/aba_contact.hpp"

#include "engine/contact/min_norm_solve.hpp"
#include "engine/dynamics/aba.hpp"

namespace elbowsim {

void aba_contact_terms(const Model& model, Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  c.a_free = tau - data.bias;
  aba_response(model, data, c.a_free, c.a_free);
  // One response per row; the row is copied first (a row of Jf is strided,
  // and a strided Ref<const VectorXd> would be a heap copy).
  for (Eigen::Index k = 0; k < c.Jf.rows(); ++k) {
    data.tau = c.Jf.row(k).transpose();
    aba_response(model, data, data.tau, c.Y.col(k));
  }
  c.A.noalias() = c.Jc * c.Y;
  c.rhs = c.gamma;
  c.rhs.noalias() -= c.Jc * c.a_free;
}

void aba_contact_solve(const Model& model, Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  aba_contact_terms(model, data, tau);
  rank_revealing_solve(model, c);
  data.qdd = c.a_free;
  data.qdd.noalias() += c.Y * c.fn;
}

}  // namespace elbowsim
