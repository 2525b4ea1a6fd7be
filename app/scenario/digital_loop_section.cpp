// controller: sample_rate, delay, pwm_bits, sensors — the digital control
// loop (engine/control/digital_loop.hpp). Without sample_rate the control is
// continuous and the other keys are refused (they would do nothing).
#include <cmath>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/step_grid.hpp"

namespace elbowsim::loader {

namespace {

// A whole number in [lo, hi].
long whole_in(const Value& v, long lo, long hi) {
  const long x = v.integer();
  if (x < lo || x > hi)
    v.fail("must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
           " (got " + std::to_string(x) + ")");
  return x;
}

SensorSpec read_sensors(const Value& sensors) {
  SensorSpec out;
  if (!sensors.present()) return out;
  sensors.allow_keys({"encoder", "noise", "velocity_cutoff", "seed"});
  if (const Value encoder = sensors.get("encoder"); encoder.present()) {
    encoder.allow_keys({"counts_per_rev", "side"});
    out.counts_per_rev = whole_in(encoder.require("counts_per_rev"), 1, 1L << 40);
    using Side = SensorSpec::EncoderSide;
    if (const Value side = encoder.get("side"); side.present())
      out.side = choose(side, std::vector<std::pair<Side, std::string_view>>{
                                  {Side::motor, "motor"}, {Side::joint, "joint"}});
  }
  out.noise = value_or(sensors.get("noise"), out.noise, non_negative);
  out.velocity_cutoff = value_or(sensors.get("velocity_cutoff"), out.velocity_cutoff, non_negative);
  if (const Value seed = sensors.get("seed"); seed.present())
    out.seed = static_cast<std::uint64_t>(whole_in(seed, 0, (1L << 62)));
  return out;
}

}  // namespace

DigitalLoopSpec read_digital_loop(const Value& controller, double step) {
  DigitalLoopSpec out;
  if (!controller.present()) return out;
  const Value rate = controller.get("sample_rate");
  if (!rate.present()) {
    for (const char* key : {"delay", "pwm_bits", "sensors"})
      if (const Value v = controller.get(key); v.present())
        v.fail("needs controller.sample_rate (without it the control is continuous, on the "
               "true state)");
    return out;
  }
  const double hz = positive(rate);
  out.sample_period = 1.0 / hz;
  // The integrator steps to each instant; a period shorter than the step
  // would make every step a fraction of the scene's.
  if (step_grid::shorter_than_step(out.sample_period, step))
    rate.fail("a sample period of " + significant(out.sample_period) +
              " s is shorter than simulation.step (" + significant(step) +
              " s): lower the rate or the step");
  out.delay = static_cast<int>(value_or(controller.get("delay"), 0L,
                                        [](const Value& v) { return whole_in(v, 0, 1000); }));
  out.pwm_bits = static_cast<int>(value_or(controller.get("pwm_bits"), 0L,
                                           [](const Value& v) { return whole_in(v, 1, 32); }));
  out.sensors = read_sensors(controller.get("sensors"));
  return out;
}

}  // namespace elbowsim::loader
