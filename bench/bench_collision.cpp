// Contact detection per step (engine/contact/detection: the Bullet broad phase, then the
// closed-form narrow phase for every near slot of every link and elbow), against the
// declared-elbow-spheres-only query by Bullet's GJK that detection used before, for arms of
// s = 4, 7 and 30 links over three table boxes. Poses: the arm lying just above the table
// (links and elbows near it, some touching) or lifted 1 m above it (every pair far: the
// broad phase alone). Forward kinematics is timed on its own, since detection includes it.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "engine/contact/collision.hpp"
#include "engine/contact/detection.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

// s equal links of 0.6/s m (radius 0.012) lying along +x, their axes 13 mm over the top
// (z = 0) of a long table box; an elbow sphere (radius 0.015) at the end of link s/4; a
// step box and a side table as the other two boxes.
//
//   o--o--O--o--o--o--o   (O: elbow)              lifted: the same, 1 m higher
//   ====================== box 0 ========|box 1|
Model arm(int s, bool lifted) {
  std::vector<testing::PlanarLinkSpec> links(static_cast<std::size_t>(s),
                                             {0.6 / s, 0.3, 0.3 / s, 1e-4});
  Model m = testing::planar_arm(links);
  for (Link& link : m.links) link.radius = 0.012;
  m.base.translation() = Eigen::Vector3d(0, 0, 0.013 + (lifted ? 1.0 : 0.0));
  m.elbows.push_back(Elbow{"elbow", s / 4, m.links[s / 4].tip, 0.015});
  m.table = {TableBox{{0.3, 0, -0.025}, {1.2, 0.8, 0.05}, Eigen::Matrix3d::Identity()},
             TableBox{{1.0, 0, 0.02}, {0.2, 0.8, 0.04}, Eigen::Matrix3d::Identity()},
             TableBox{{-0.8, 0.9, -0.1}, {0.6, 0.6, 0.05}, Eigen::Matrix3d::Identity()}};
  m.effects.contact = true;
  finalize(m);
  return m;
}

// 64 states of a small wave of every joint, as x of a Data with its collision world.
struct Scene {
  Model model;
  std::unique_ptr<Data> data;
  std::vector<Eigen::VectorXd> q;
  Scene(int s, bool lifted) : model(arm(s, lifted)), data(std::make_unique<Data>(model)) {
    data->contact.world = std::make_shared<CollisionWorld>(model, data->contact.geometry);
    for (int k = 0; k < 64; ++k) {
      const double phase = 2 * std::numbers::pi * k / 64;
      Eigen::VectorXd angles(s);
      for (int j = 0; j < s; ++j) angles[j] = 0.01 * std::sin(phase + j) / (1 + j);
      q.push_back(angles);
    }
  }
  void set(std::size_t k) { data->x.head(model.dof) = q[k % q.size()]; }
};

void BM_Detection(benchmark::State& state) {
  Scene scene(static_cast<int>(state.range(0)), state.range(1) != 0);
  std::size_t k = 0;
  long near = 0;
  for (auto _ : state) {
    scene.set(k++);
    detect_contacts(scene.model, *scene.data);
    near += static_cast<long>(scene.data->contact.near_pairs.size());
  }
  state.counters["near_pairs"] = static_cast<double>(near) / static_cast<double>(k);
  state.counters["slots"] = scene.data->contact.slots();
}

void BM_ForwardKinematics(benchmark::State& state) {
  Scene scene(static_cast<int>(state.range(0)), state.range(1) != 0);
  std::size_t k = 0;
  for (auto _ : state) {
    scene.set(k++);
    scene.data->kinematics_model = 0;  // time the kinematics: no reuse of the last call's
    forward_kinematics(scene.model, *scene.data, scene.data->x.head(scene.model.dof));
    benchmark::DoNotOptimize(scene.data->origin.data());
  }
}

// The query detection used before: declared elbow spheres only, by GJK.
void BM_ElbowSpheresGjk(benchmark::State& state) {
  Scene scene(static_cast<int>(state.range(0)), state.range(1) != 0);
  CollisionWorld world(scene.model);
  std::vector<ElbowContact> out(scene.model.elbows.size());
  std::size_t k = 0;
  for (auto _ : state) {
    scene.set(k++);
    scene.data->kinematics_model = 0;  // time the kinematics: no reuse of the last call's
    forward_kinematics(scene.model, *scene.data, scene.data->x.head(scene.model.dof));
    world.elbow_contacts(scene.model, *scene.data, out);
    benchmark::DoNotOptimize(out.data());
  }
}

void shapes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"s", "lifted"});
  for (int lifted : {0, 1})
    for (int s : {4, 7, 30}) b->Args({s, lifted});
}

}  // namespace

BENCHMARK(BM_Detection)->Apply(shapes);
BENCHMARK(BM_ForwardKinematics)->Apply(shapes);
BENCHMARK(BM_ElbowSpheresGjk)->Apply(shapes);

BENCHMARK_MAIN();
