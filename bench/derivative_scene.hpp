// The scene of bench_derivative and count_derivative: a random s-joint chain
// with full motor models and p elbows spread along it, at a fixed random
// state with every elbow resting on a random plane (one place, so the timed
// and the counted evaluation are the same).
#pragma once

#include <string>

#include "engine/state_layout.hpp"
#include "support/models.hpp"

namespace elbowsim::bench {

// solver: a ConstraintSolver, or -1 for the scene's default (auto).
inline Model derivative_chain(int n, int p, int solver) {
  Model m = testing::random_chain(n, 4000 + n);
  for (int k = 0; k < p; ++k)
    m.elbows.push_back(
        {'e' + std::to_string(k), (k + 1) * (n - 1) / p, Eigen::Vector3d(0.1, 0, 0), 0.03});
  m.table = {TableBox{}};
  m.effects.contact = true;
  if (solver >= 0) m.contact.solver = static_cast<ConstraintSolver>(solver);
  finalize(m);
  return m;
}

struct DerivativeFixture {
  DerivativeFixture(int n, int p, int solver) : model(derivative_chain(n, p, solver)), data(model) {
    const StateLayout s(model);
    x = Eigen::VectorXd::Zero(s.size);
    out = Eigen::VectorXd::Zero(s.size);
    x.segment(s.q(), n) = Eigen::VectorXd::Random(n);
    x.segment(s.qd(), n) = Eigen::VectorXd::Random(n);
    if (s.current >= 0) x.segment(s.current, n) = Eigen::VectorXd::Random(n);
    for (int k = 0; k < p; ++k) {
      data.contact.active.push_back(k);
      data.contact.resting[static_cast<std::size_t>(k)] = 1;
      data.contact.normal[static_cast<std::size_t>(k)] = Eigen::Vector3d::Random().normalized();
    }
  }
  Model model;
  Data data;
  Eigen::VectorXd x, out;
};

}  // namespace elbowsim::bench
