// Runs one derivative evaluation of bench_derivative's scene (random s-joint
// chain, full motors, p resting elbows) a given number of times, for
// instruction counting under callgrind (bench/callgrind.sh): counts do not
// move with the machine's load, so a regression shows on a noisy machine.
//
//   count_derivative S P SOLVER REPS     SOLVER: auto, schur or aba
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/run/derivative.hpp"
#include "engine/run/state_layout.hpp"
#include "support/models.hpp"

using namespace elbowsim;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: count_derivative S P SOLVER REPS\n");
    return 2;
  }
  const int n = std::atoi(argv[1]), p = std::atoi(argv[2]), reps = std::atoi(argv[4]);
  const std::string solver = argv[3];
  Model m = testing::random_chain(n, 4000 + n);
  for (int k = 0; k < p; ++k)
    m.elbows.push_back(
        {"e" + std::to_string(k), (k + 1) * (n - 1) / p, Eigen::Vector3d(0.1, 0, 0), 0.03});
  m.table = {TableBox{}};
  m.effects.contact = true;
  if (solver == "schur")
    m.contact.solver = ConstraintSolver::schur;
  else if (solver == "aba")
    m.contact.solver = ConstraintSolver::aba;
  finalize(m);
  Data data(m);
  const StateLayout s(m);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(s.size), out = Eigen::VectorXd::Zero(s.size);
  x.segment(s.q(), n) = Eigen::VectorXd::Random(n);
  x.segment(s.qd(), n) = Eigen::VectorXd::Random(n);
  if (s.current >= 0) x.segment(s.current, n) = Eigen::VectorXd::Random(n);
  for (int k = 0; k < p; ++k) {
    data.contact.active.push_back(k);
    data.contact.resting[static_cast<std::size_t>(k)] = 1;
    data.contact.normal[static_cast<std::size_t>(k)] = Eigen::Vector3d::Random().normalized();
  }
  double sum = 0;
  for (int r = 0; r < reps; ++r) {
    data.kinematics_model = 0;  // kinematics every time, as in an RK stage
    nonstiff_rates(m, data, 0.0, x, out);
    sum += out[s.qd()];
  }
  std::printf("%.17g\n", sum);
  return 0;
}
