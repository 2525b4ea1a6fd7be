// Time per call of the collision queries (engine/collision_bullet.cpp) for a 4-link planar
// arm with 1, 2 or 4 elbows over a table of 1 or 3 boxes. Each iteration takes the next of
// 64 precomputed poses (forward kinematics done outside the timing), so the cost is averaged
// over touching, resting-near and lifted elbows and over links in and out of the table.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/contact/collision.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

// The arm lies almost flat, elbow spheres (radius 0.03) at the middle of links, link axes
// about 0.036 above the table top; the poses wave it so that elbows go from 19 mm into the
// table to 24 mm above it and a link capsule reaches into it now and then (0.2 per call).
//
//   o--- link 0 ---o--- link 1 ---o-- link 2 --o- link 3 -o
//   =================== box 0, top z = 0 ==================|[box 1: step]   (x = 1.0 ... 1.2)
//   [box 2: side table, out of reach at (-0.8, 0.9)]
Model arm(int elbows, int boxes) {
  Model m = testing::planar_arm({{0.30, 1.2, 0.15, 0.01},
                                 {0.25, 1.0, 0.12, 0.008},
                                 {0.20, 0.7, 0.1, 0.004},
                                 {0.15, 0.4, 0.07, 0.002}});
  m.base.translation() = Eigen::Vector3d(0, 0, 0.036);
  const int on_link[3][4] = {{1}, {1, 2}, {0, 1, 2, 3}};  // for 1, 2, 4 elbows
  for (int k = 0; k < elbows; ++k) {
    const int link = on_link[elbows == 1 ? 0 : elbows == 2 ? 1 : 2][k];
    m.elbows.push_back(Elbow{"elbow", link, 0.5 * m.links[link].tip, 0.03});
  }
  m.table.push_back(TableBox{{0.4, 0, -0.025}, {1.2, 0.8, 0.05}, Eigen::Matrix3d::Identity()});
  if (boxes == 3) {
    m.table.push_back(TableBox{{1.1, 0, 0.02}, {0.2, 0.8, 0.04}, Eigen::Matrix3d::Identity()});
    m.table.push_back(TableBox{{-0.8, 0.9, -0.1}, {0.6, 0.6, 0.05}, Eigen::Matrix3d::Identity()});
  }
  m.effects.contact = true;
  finalize(m);
  return m;
}

// 64 poses of one slow wave of every joint.
std::vector<Data> poses(const Model& model) {
  std::vector<Data> out;
  for (int k = 0; k < 64; ++k) {
    const double phase = 2 * std::numbers::pi * k / 64;
    const Eigen::Vector4d q(0.015 * std::sin(phase), -0.02 * std::sin(2 * phase),
                            0.02 * std::cos(phase), 0.04 * std::sin(phase));
    Data data(model);
    forward_kinematics(model, data, q);
    out.push_back(std::move(data));
  }
  return out;
}

void BM_ElbowContacts(benchmark::State& state) {
  const Model model = arm(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const std::vector<Data> data = poses(model);
  CollisionWorld world(model);
  std::vector<ElbowContact> out(model.elbows.size());
  std::size_t k = 0;
  for (auto _ : state) {
    world.elbow_contacts(model, data[k++ % data.size()], out);
    benchmark::DoNotOptimize(out.data());
  }
}

void BM_LinkPenetrations(benchmark::State& state) {
  const Model model = arm(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const std::vector<Data> data = poses(model);
  CollisionWorld world(model);
  std::vector<LinkPenetration> out;
  std::size_t k = 0, found = 0;
  for (auto _ : state) {
    world.link_penetrations(model, data[k++ % data.size()], out);
    found += out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["penetrations_per_call"] =
      static_cast<double>(found) / static_cast<double>(std::max<std::size_t>(k, 1));
}

void shapes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"elbows", "boxes"});
  for (int boxes : {1, 3})
    for (int elbows : {1, 2, 4}) b->Args({elbows, boxes});
}

}  // namespace

BENCHMARK(BM_ElbowContacts)->Apply(shapes);
BENCHMARK(BM_LinkPenetrations)->Apply(shapes);

BENCHMARK_MAIN();
