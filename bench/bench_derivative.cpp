// One derivative evaluation (run/derivative.hpp: kinematics, motor, applied
// torques, the constrained solve, energy powers) of a random s-joint chain
// with full motor models and p resting elbows, next to the engine's own RNEA
// (forward kinematics + inverse dynamics) on the same chain in the same run:
// the ratio of the two is what the speed targets are stated in.
//
//   Rnea/s                     forward_kinematics + inverse_dynamics
//   Derivative/s/p             nonstiff_rates with the scene's solver (contact.solver auto)
//   DerivativeSchur/s/p        ... with contact.solver schur (Cholesky of M, Schur complement)
//   DerivativeAba/s/p          ... with contact.solver aba (articulated inertias, O(n p))
//
// p = 0 is free motion (forward dynamics by CRBA + Cholesky, the scene's
// default). Where DerivativeAba overtakes DerivativeSchur is the crossover
// (kAbaCrossover in contact/constrained_dynamics.hpp).
#include <benchmark/benchmark.h>

#include <string>

#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/run/derivative.hpp"
#include "derivative_scene.hpp"

using namespace elbowsim;

namespace {

using Fixture = bench::DerivativeFixture;

void derivative(benchmark::State& state, int solver) {
  Fixture f(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), solver);
  for (auto _ : state) {
    // Every call from the kinematics on (an RK stage's q is new; the reuse of
    // an unchanged q is for the step, not for this count).
    f.data.kinematics_model = 0;
    nonstiff_rates(f.model, f.data, 0.0, f.x, f.out);
    benchmark::DoNotOptimize(f.out.data());
  }
}

void BM_Rnea(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Fixture f(n, 0, -1);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(n), qd = Eigen::VectorXd::Random(n),
                        qdd = Eigen::VectorXd::Random(n);
  Eigen::VectorXd tau(n);
  for (auto _ : state) {
    f.data.kinematics_model = 0;
    forward_kinematics(f.model, f.data, q);
    inverse_dynamics(f.model, f.data, qd, qdd, {}, tau);
    benchmark::DoNotOptimize(tau.data());
  }
}

void BM_Derivative(benchmark::State& state) { derivative(state, -1); }
void BM_DerivativeSchur(benchmark::State& state) {
  derivative(state, static_cast<int>(ConstraintSolver::schur));
}
void BM_DerivativeAba(benchmark::State& state) {
  derivative(state, static_cast<int>(ConstraintSolver::aba));
}

void all_rows(benchmark::internal::Benchmark* b) {
  for (int n : {2, 7, 15, 30, 60})
    for (int p : {0, 1, 2, 4}) b->Args({n, p});
}
void contact_rows(benchmark::internal::Benchmark* b) {
  for (int n : {2, 4, 7, 10, 12, 15, 30, 60})
    for (int p : {1, 2, 4}) b->Args({n, p});
}

}  // namespace

BENCHMARK(BM_Rnea)->Name("Rnea")->Arg(2)->Arg(7)->Arg(15)->Arg(30)->Arg(60);
BENCHMARK(BM_Derivative)->Name("Derivative")->Apply(all_rows);
BENCHMARK(BM_DerivativeSchur)->Name("DerivativeSchur")->Apply(contact_rows);
BENCHMARK(BM_DerivativeAba)->Name("DerivativeAba")->Apply(contact_rows);

BENCHMARK_MAIN();
