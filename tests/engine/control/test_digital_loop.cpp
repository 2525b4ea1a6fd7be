// engine/control/digital_loop.cpp: the sampled controller. Its sensors (an
// encoder's rounding, seeded noise), the zero-order hold with its delay, and
// the integrator stepping to every sample instant, checked on the writing arm
// (support/experiment_scenes.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "engine/control/digital_loop.hpp"
#include "engine/control/plan.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/allocations.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

ExperimentScene sampled_arm(double step, double period, int delay) {
  WritingArm arm;
  arm.elbow_on = false;
  arm.step = step;
  ExperimentScene scene = arm.scene();
  scene.experiment.controller.loop.sample_period = period;
  scene.experiment.controller.loop.delay = delay;
  return scene;
}

}  // namespace

TEST_CASE("measure_angles: rounded to the encoder's resolution (joint or motor side), plus seeded noise") {
  const ExperimentScene scene = WritingArm{}.scene();  // gear ratio 100
  const Model& m = scene.model;
  DigitalLoopSpec spec;
  DigitalLoopState state;
  const Eigen::Vector4d q(0.1234567, -1.0, 0.5, 2.0);
  Eigen::VectorXd out(4);

  spec.sensors.counts_per_rev = 4096;
  spec.sensors.side = SensorSpec::EncoderSide::joint;
  measure_angles(m, spec, state, q, out);
  const double joint_lsb = 2 * std::numbers::pi / 4096;
  for (int j = 0; j < 4; ++j) {
    CHECK(std::abs(out[j] - q[j]) <= 0.5 * joint_lsb);
    CHECK(std::abs(out[j] / joint_lsb - std::round(out[j] / joint_lsb)) < 1e-9);
  }
  spec.sensors.side = SensorSpec::EncoderSide::motor;  // 100 times finer at the joint
  measure_angles(m, spec, state, q, out);
  for (int j = 0; j < 4; ++j) CHECK(std::abs(out[j] - q[j]) <= 0.5 * joint_lsb / 100);
  CHECK(out[0] != q[0]);  // 0.1234567 is no multiple of the resolution

  // Noise: zero mean, the stated sigma; the same seed gives the same draws.
  spec.sensors.counts_per_rev = 0;
  spec.sensors.noise = 1e-3;
  state.noise.seed(7);
  double sum = 0, sum2 = 0;
  const int draws = 20000;
  for (int i = 0; i < draws / 4; ++i) {
    measure_angles(m, spec, state, q, out);
    sum += (out - q).sum();
    sum2 += (out - q).squaredNorm();
  }
  const double mean = sum / draws, sigma = std::sqrt(sum2 / draws - mean * mean);
  CHECK(std::abs(mean) < 4 * 1e-3 / std::sqrt(draws));  // 4 standard errors
  CHECK(sigma == doctest::Approx(1e-3).epsilon(0.03));  // standard error of sigma: 0.5 %
  DigitalLoopState a, b;
  a.noise.seed(3);
  b.noise.seed(3);
  Eigen::VectorXd out_a(4), out_b(4);
  measure_angles(m, spec, a, q, out_a);
  measure_angles(m, spec, b, q, out_b);
  CHECK(out_a == out_b);
  measure_angles(m, spec, b, q, out_b);
  CHECK(out_a != out_b);
}

TEST_CASE("sampled control: the voltage is held over each period and changes only at sample instants") {
  // 0.4 ms steps under a 1 ms period: the integrator cuts steps at the instants.
  for (const auto& [step, period] : {std::pair{1e-3, 1e-3}, std::pair{0.4e-3, 1e-3}}) {
    CAPTURE(step);
    ExperimentScene scene = sampled_arm(step, period, 0);
    scene.model.options.duration = 0.6;
    const RunResult r = simulate(scene.model, scene.experiment, RunOptions{1, {}});
    REQUIRE(r.valid);
    // Rows fall every `step` (0, 0.4, 0.8, 1.2 ms, ...): a row's voltage may
    // differ from the row before only when a sample instant lies between them.
    const Recording& rec = r.trajectory;
    const int v0 = rec.layout.voltage(0);
    int changes = 0, intervals_with_instant = 0;
    for (std::size_t row = 1; row < rec.rows(); ++row) {
      const double t = rec.at(row, 0), before = rec.at(row - 1, 0);
      const double next_instant = (std::floor(before / period + 1e-9) + 1) * period;
      const bool instant = next_instant <= t + 1e-12;
      intervals_with_instant += instant;
      CHECK(t - before == doctest::Approx(step).epsilon(1e-9));
      for (int j = 0; j < 4; ++j) {
        const bool changed = rec.at(row, v0 + j) != rec.at(row - 1, v0 + j);
        if (changed && !instant) FAIL_CHECK("voltage changed between instants at t = " << t);
        changes += changed;
      }
    }
    CHECK(intervals_with_instant == std::lround(0.6 / period));
    CHECK(changes > intervals_with_instant);  // the held voltage did change at the instants
  }
}

TEST_CASE("sampled control with a delay: the command computed at k T acts from (k + d) T") {
  // Gains 0: the command is the plan's feed-forward v_ff(k T), whatever the
  // state, so what the amplifier holds can be checked against the plan.
  for (int delay : {0, 2}) {
    CAPTURE(delay);
    ExperimentScene scene = sampled_arm(1e-3, 1e-3, delay);
    scene.experiment.controller.kp.setZero();
    scene.experiment.controller.kd.setZero();
    scene.model.options.duration = 0.3;
    const RunResult r = simulate(scene.model, scene.experiment, RunOptions{1, {}});
    REQUIRE(r.completed);
    const auto plan = make_plan(scene.model, scene.experiment);
    const Recording& rec = r.trajectory;
    for (std::size_t row = 0; row < rec.rows(); ++row) {
      const double t = rec.at(row, 0);
      const long k = std::lround(t / 1e-3);
      const long computed = std::max(0L, k - delay);  // before k = d: the first command
      Eigen::VectorXd v(4);
      plan->at(plan->v_ff, static_cast<double>(computed) * 1e-3, v);
      // To the rounding of t (sums of steps, not k T exactly): 1e-9 V.
      for (int j = 0; j < 4; ++j) CHECK(std::abs(rec.at(row, rec.layout.voltage(j)) - v[j]) < 1e-9);
    }
  }
}

TEST_CASE("encoder quantisation: a hold's steady hand error is of the order of the resolution") {
  // The hand held still; the PD loop sees only encoder counts at the joints.
  auto hold_error = [](long counts) {
    WritingArm arm;
    arm.elbow_on = false;
    arm.path = HandTask::Path::hold;
    arm.run_duration = 1.0;
    ExperimentScene scene = arm.scene();
    DigitalLoopSpec& loop = scene.experiment.controller.loop;
    loop.sample_period = 1e-3;
    loop.sensors.counts_per_rev = counts;
    loop.sensors.side = SensorSpec::EncoderSide::joint;
    // A count is 1.5 rad/s in one sample's difference: filtered, as a drive would.
    loop.sensors.velocity_cutoff = 20;
    const RunResult r = simulate(scene.model, scene.experiment, RunOptions{10, {}});
    INFO(r.failure);
    REQUIRE(r.valid);
    return r.metrics["hand_error_rms"];
  };
  const double exact = hold_error(0);
  MESSAGE("RMS hand error of a hold, exact angles: ", exact, " m");
  double previous = 0;
  for (long counts : {4096L, 1024L}) {
    const double lsb = 2 * std::numbers::pi / static_cast<double>(counts);
    const double error = hold_error(counts);
    MESSAGE(counts, " counts per revolution (", lsb, " rad): RMS hand error ", error, " m");
    // The hand is 0.5-0.85 m from the joints: an angle off by a fraction of
    // a count moves it by that fraction of lsb x 0.5 m.
    CHECK(error > 0.01 * lsb * 0.5);
    CHECK(error > 10 * exact);
    CHECK(error > previous);  // coarser counts, larger error
    previous = error;
  }
}

TEST_CASE("a sampled step allocates nothing: encoder, noise, filter, delay line and PWM") {
  ExperimentScene scene = sampled_arm(0.4e-3, 1e-3, 2);
  DigitalLoopSpec& loop = scene.experiment.controller.loop;
  loop.pwm_bits = 12;
  loop.sensors = {4096, SensorSpec::EncoderSide::motor, 1e-5, 100.0, 5};
  Data data(scene.model);
  data.controller = make_controller(scene.model, scene.experiment);
  reset(scene.model, data);  // sizes the loop's vectors and its delay line
  const long news = allocation_count();
  Eigen::internal::set_is_malloc_allowed(false);
  long samples = data.loop.next_sample;
  for (int i = 0; i < 500 && !data.failure; ++i) step(scene.model, data);
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK_FALSE(data.failure);
  CHECK(allocation_count() == news);
  samples = data.loop.next_sample - samples;
  // 0.4, 0.4 and 0.2 ms (cut at the instant): 3 steps a period, 500 steps 166 samples.
  CHECK(samples == 166);
  CHECK(data.t == doctest::Approx(0.1668));
}

TEST_CASE("PWM resolution: every applied voltage is a whole number of voltage_limit / 2^(bits-1)") {
  ExperimentScene scene = sampled_arm(1e-3, 1e-3, 0);
  scene.experiment.controller.loop.pwm_bits = 6;  // 32 steps per polarity
  scene.model.options.duration = 0.3;
  const RunResult r = simulate(scene.model, scene.experiment, RunOptions{1, {}});
  REQUIRE(r.completed);
  const double lsb = scene.model.motors[0].voltage_limit / 32;
  const Recording& rec = r.trajectory;
  int nonzero = 0;
  for (std::size_t row = 0; row < rec.rows(); ++row)
    for (int j = 0; j < 4; ++j) {
      const double v = rec.at(row, rec.layout.voltage(j));
      CHECK(std::abs(v / lsb - std::round(v / lsb)) < 1e-9);
      nonzero += v != 0;
    }
  CHECK(nonzero > 0);
}
