#include "engine/contact/aba_contact.hpp"

#include <algorithm>
#include <array>

#include "engine/contact/min_norm_solve.hpp"
#include "engine/dynamics/aba.hpp"

namespace elbowsim {

void aba_contact_terms(const Model& model, Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  c.a_free = tau - data.bias;
  // Column 0: the free acceleration (in place); column 1 + k: the response to
  // row k of Jf (read in place with the row's stride) into Y.col(k). Swept in
  // batches (aba_responses), no copies.
  const int m = 1 + static_cast<int>(c.Jf.rows());
  std::array<ResponseColumn, kResponseBatch> batch;
  for (int first = 0; first < m; first += kResponseBatch) {
    const int count = std::min(kResponseBatch, m - first);
    for (int b = 0; b < count; ++b) {
      const int j = first + b;
      batch[static_cast<std::size_t>(b)] =
          j == 0 ? ResponseColumn{c.a_free.data(), 1, c.a_free.data()}
                 : ResponseColumn{c.Jf.data() + (j - 1), c.Jf.outerStride(), c.Y.col(j - 1).data()};
    }
    aba_responses(model, data, batch.data(), count);
  }
  // p x p and p-sized products coefficient by coefficient (lazyProduct): at
  // these sizes the blocked product's packing costs more than the sums.
  c.A.noalias() = c.Jc.lazyProduct(c.Y);
  c.rhs = c.gamma;
  c.rhs.noalias() -= c.Jc.lazyProduct(c.a_free);
}

void aba_contact_solve(const Model& model, Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  aba_contact_terms(model, data, tau);
  rank_revealing_solve(model, c);
  data.qdd = c.a_free;
  data.qdd.noalias() += c.Y.lazyProduct(c.fn);
}

}  // namespace elbowsim
