// Constrained forward dynamics (the mechanical block of M*, eq. 32-38):
// Schur complement vs dense LU of M* vs the paper's explicit-inverse
// formula (48)-(49), for s joints and p resting elbows. Each call starts from
// M + Jm, B_J and the rows, as the simulator has them.
#include <benchmark/benchmark.h>

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

struct Fixture {
  Fixture(int n, int p) : model(make(n, p)), data(model), tau(Eigen::VectorXd::Random(n)) {
    const Eigen::VectorXd q = Eigen::VectorXd::Random(n), qd = Eigen::VectorXd::Random(n);
    forward_kinematics(model, data, q);
    for (int k = 0; k < p; ++k) {
      data.contact.active.push_back(k);
      data.contact.normal[k] = Eigen::Vector3d::Random().normalized();
    }
    mass_matrix_crba(model, data);
    bias_torques(model, data, qd);
    constraint_rows(model, data, qd);
  }
  static Model make(int n, int p) {
    Model m = testing::random_chain(n, 4000 + n);
    for (int k = 0; k < p; ++k)
      m.elbows.push_back({'e' + std::to_string(k), (k + 1) * (n - 1) / p, Eigen::Vector3d(0.1, 0, 0), 0.03});
    m.table = {TableBox{}};
    m.effects.contact = true;
    finalize(m);
    return m;
  }
  Model model;
  Data data;
  Eigen::VectorXd tau;
};

template <ConstraintSolver method>
void BM_Constrained(benchmark::State& state) {
  Fixture f(int(state.range(0)), int(state.range(1)));
  for (auto _ : state) {
    solve_constrained(f.model, f.data, f.tau, method);
    benchmark::DoNotOptimize(f.data.qdd.data());
  }
}

void shapes(benchmark::internal::Benchmark* b) {
  for (int n : {4, 7, 15, 30})
    for (int p : {1, 2, 4}) b->Args({n, p});
}

}  // namespace

BENCHMARK(BM_Constrained<ConstraintSolver::schur>)->Name("Schur")->Apply(shapes);
BENCHMARK(BM_Constrained<ConstraintSolver::dense_lu>)->Name("DenseLU")->Apply(shapes);
BENCHMARK(BM_Constrained<ConstraintSolver::explicit_inverse>)->Name("ExplicitInverse")->Apply(shapes);

BENCHMARK_MAIN();
