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
#include "derivative_scene.hpp"
#include "engine/state_layout.hpp"

using namespace elbowsim;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: count_derivative S P SOLVER REPS\n");
    return 2;
  }
  const int n = std::atoi(argv[1]), p = std::atoi(argv[2]), reps = std::atoi(argv[4]);
  const std::string solver = argv[3];
  const int kind = solver == "schur" ? int(ConstraintSolver::schur)
                   : solver == "aba"  ? int(ConstraintSolver::aba)
                                      : -1;
  bench::DerivativeFixture f(n, p, kind);
  const StateLayout s(f.model);
  double sum = 0;
  for (int r = 0; r < reps; ++r) {
    f.data.kinematics_model = 0;  // kinematics every time, as in an RK stage
    nonstiff_rates(f.model, f.data, 0.0, f.x, f.out);
    sum += f.out[s.qd()];
  }
  std::printf("%.17g\n", sum);
  return 0;
}
