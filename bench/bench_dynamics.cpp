// Time per call of inverse dynamics, the mass matrix by Walker-Orin (the
// paper's method) and by CRBA, and forward dynamics three ways, on random
// spatial chains of s = 2 ... 60 joints with every effect on.
#include <benchmark/benchmark.h>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

// One fixed random state per size; every iteration starts from it.
struct Fixture {
  explicit Fixture(int n)
      : model(testing::random_chain(n, 1000 + n)), data(model),
        q(Eigen::VectorXd::Random(n)), qd(Eigen::VectorXd::Random(n)),
        qdd(Eigen::VectorXd::Random(n)), tau(Eigen::VectorXd::Random(n)), out(n) {
    forward_kinematics(model, data, q);
  }
  Model model;
  Data data;
  Eigen::VectorXd q, qd, qdd, tau, out;
};

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {2, 4, 7, 15, 30, 60}) b->Arg(n);
}

void BM_InverseDynamics(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    f.data.kinematics_model = 0;  // time the kinematics: no reuse of the last call's
    forward_kinematics(f.model, f.data, f.q);
    inverse_dynamics(f.model, f.data, f.qd, f.qdd, {}, f.out);
    benchmark::DoNotOptimize(f.out.data());
  }
}

void BM_MassMatrixWalkerOrin(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    f.data.kinematics_model = 0;  // time the kinematics: no reuse of the last call's
    forward_kinematics(f.model, f.data, f.q);
    mass_matrix_walker_orin(f.model, f.data);
    benchmark::DoNotOptimize(f.data.mass_matrix.data());
  }
}

void BM_MassMatrixCrba(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    f.data.kinematics_model = 0;  // time the kinematics: no reuse of the last call's
    forward_kinematics(f.model, f.data, f.q);
    mass_matrix_crba(f.model, f.data);
    benchmark::DoNotOptimize(f.data.mass_matrix.data());
  }
}

template <DynamicsMethod method>
void BM_ForwardDynamics(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    f.data.kinematics_model = 0;  // time the kinematics: no reuse of the last call's
    forward_kinematics(f.model, f.data, f.q);
    forward_dynamics(f.model, f.data, method, f.qd, f.tau, f.out);
    benchmark::DoNotOptimize(f.out.data());
  }
}

}  // namespace

BENCHMARK(BM_InverseDynamics)->Apply(sizes);
BENCHMARK(BM_MassMatrixWalkerOrin)->Apply(sizes);
BENCHMARK(BM_MassMatrixCrba)->Apply(sizes);
BENCHMARK(BM_ForwardDynamics<DynamicsMethod::walker_orin>)->Name("BM_ForwardWalkerOrinCholesky")->Apply(sizes);
BENCHMARK(BM_ForwardDynamics<DynamicsMethod::crba>)->Name("BM_ForwardCrbaCholesky")->Apply(sizes);
BENCHMARK(BM_ForwardDynamics<DynamicsMethod::aba>)->Name("BM_ForwardAba")->Apply(sizes);

BENCHMARK_MAIN();
