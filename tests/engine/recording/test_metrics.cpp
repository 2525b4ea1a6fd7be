// engine/recording/metrics.cpp: the metrics of a recording against analytic values
// (RMS of constants and sines, sample-and-hold contact times) and their vocabulary.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/recording/metrics.hpp"
#include "support/approx.hpp"
#include "support/recordings.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::set;
using elbowsim::testing::zero_recording;

namespace {

// `rows` samples at t = k dt.
Recording timed(TrajectoryLayout::Groups groups, std::size_t rows, double dt) {
  Recording rec = zero_recording(std::move(groups), rows);
  for (std::size_t r = 0; r < rows; ++r) set(rec, r, rec.layout.time(), double(r) * dt);
  return rec;
}

}  // namespace

TEST_CASE("metrics: a constant hand error e has RMS e, max e and final e") {
  Recording rec = timed({2, false, true, false, {}}, 101, 0.01);
  for (std::size_t r = 0; r < rec.rows(); ++r) set(rec, r, rec.layout.hand_error(), 0.003);
  const Metrics m = compute_metrics(rec);
  // sqrt(sum of dt e^2 / T): rounding of the sum of 100 steps, 1e-14 relative.
  CHECK(approx(m["hand_error_rms"], 0.003, 0, 1e-14));
  CHECK(m["hand_error_max"] == 0.003);
  CHECK(m["hand_error_final"] == 0.003);
  CHECK(m["samples"] == 101);
}

TEST_CASE("metrics: current_rms of a sine over whole periods is A / sqrt(2)") {
  // The trapezoid rule is exact for sin^2 sampled evenly over whole periods (its error
  // term cos(4 pi f t) sums to zero with more than two samples per period): rounding only,
  // 1e-13 relative. 3 periods of 0.5 s, 40 samples per period.
  const double A = 1.7, f = 2.0, B = 0.6;
  Recording rec = timed({2, true, false, false, {}}, 121, 0.5 / 40);
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t r = 0; r < rec.rows(); ++r) {
    const double t = rec.at(r, 0);
    set(rec, r, L.current(0), A * std::sin(2 * std::numbers::pi * f * t));
    set(rec, r, L.current(1), B);  // a constant: RMS B
    set(rec, r, L.voltage(0), 4.0 * A * std::sin(2 * std::numbers::pi * f * t));  // R = 4 ohm
  }
  const Metrics m = compute_metrics(rec);
  const Metric* rms = m.find("current_rms");
  REQUIRE(rms != nullptr);
  CHECK(rms->shape == Metric::Shape::per_joint);
  CHECK(approx(rms->values[0], A / std::sqrt(2.0), 0, 1e-13));
  CHECK(approx(rms->values[1], B, 0, 1e-13));
  CHECK(approx(m.find("current_peak")->values[0], A, 0, 1e-15));  // t = 1/(4f) is a sample
  // Energy into a resistor: integral of R i^2 = R A^2 T / 2, exact for the same reason.
  CHECK(approx(m.find("energy_in_per_joint")->values[0], 4.0 * A * A * 1.5 / 2, 0, 1e-13));
  CHECK(approx(m["power_peak"], 4.0 * A * A, 0, 1e-15));
}

TEST_CASE("metrics: rest_fraction and time_in_contact hold each sample until the next") {
  // 11 samples at 0, 0.1, ..., 1.0 s. Elbow a rests on samples 0-4, b on 3-7 and on the
  // last sample (which holds for no time). Held: a 0.5 s, b 0.5 s; some elbow 0.8 s.
  Recording rec = timed({1, false, false, true, {"a", "b"}}, 11, 0.1);
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t r = 0; r < 11; ++r) {
    set(rec, r, L.elbow_resting(0), r <= 4 ? 1.0 : 0.0);
    set(rec, r, L.elbow_resting(1), (r >= 3 && r <= 7) || r == 10 ? 1.0 : 0.0);
    set(rec, r, L.elbow_force(0), r <= 4 ? 2.0 + double(r) : 0.0);  // 2..6 N while resting
    set(rec, r, L.elbow_force(1), r == 9 ? -9.0 : (r >= 3 && r <= 7) || r == 10 ? 1.0 : 0.0);
    set(rec, r, L.elbow_distance(0), r == 2 ? -3e-6 : (r == 8 ? 0.2 : 0.0));
  }
  const Metrics m = compute_metrics(rec);
  // Sums of ten 0.1 s steps: rounding, 1e-15 s.
  CHECK(approx(m["time_in_contact"], 0.8, 1e-15));
  const Metric* fraction = m.find("rest_fraction");
  REQUIRE(fraction != nullptr);
  CHECK(fraction->shape == Metric::Shape::per_elbow);
  CHECK(approx(fraction->values[0], 0.5, 1e-15));
  CHECK(approx(fraction->values[1], 0.5, 1e-15));
  CHECK(m.elbows == std::vector<std::string>{"a", "b"});
  // Forces over resting samples only (a: 2..6, b: six samples of 1).
  CHECK(m["elbow_force_min"] == 1.0);
  CHECK(m["elbow_force_max"] == 6.0);
  CHECK(approx(m["elbow_force_mean"], (2.0 + 3 + 4 + 5 + 6 + 6 * 1.0) / 11, 1e-15));
  CHECK(m.find("elbow_force_peak")->values == std::vector<double>{6.0, 9.0});  // all samples
  // Drift while resting only: 3e-6 m on sample 2; the 0.2 m of sample 8 is off the table.
  CHECK(m.find("elbow_drift_max")->values == std::vector<double>{3e-6, 0.0});
}

TEST_CASE("metrics: every contact body, elbow or link, gets its rest share, forces and friction work") {
  // 11 samples at 0, 0.1, ..., 1.0 s; 3 links, one elbow. Link 2 rests on samples 2-6
  // (0.5 s) pushed by 4, 4, 8, 8, 8 N: time-weighted mean (0.2 x 4 + 0.3 x 8) / 0.5 = 6.4 N;
  // its friction loss grows to 1.5 J (the last sample's). Link 1 has no solid (its distance
  // infinite throughout): no body.
  Recording rec = timed({3, false, false, true, {"e"}, true}, 11, 0.1);
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t r = 0; r < 11; ++r) {
    const bool on = r >= 2 && r <= 6;
    set(rec, r, L.link_resting(2), on ? 1.0 : 0.0);
    set(rec, r, L.link_force(2), on ? (r <= 3 ? 4.0 : 8.0) : 0.0);
    set(rec, r, L.link_friction(2), r >= 6 ? 1.5 : on ? 0.3 * double(r - 2) : 0.0);
    set(rec, r, L.link_distance(1), INFINITY);
    set(rec, r, L.link_force(0), r == 9 ? 0.5 : 0.0);  // a touch between samples: no rest
  }
  const Metrics m = compute_metrics(rec);
  CHECK(m.bodies == std::vector<std::string>{"e", "link0", "link2"});
  CHECK(m.body_links == std::vector<int>{-1, 0, 2});
  const auto values = [&](const char* name) { return m.find(name)->values; };
  CHECK(approx(values("body_rest_fraction")[2], 0.5, 1e-15));
  CHECK(values("body_rest_fraction")[1] == 0.0);
  CHECK(approx(values("body_force_mean")[2], 6.4, 1e-14));
  CHECK(values("body_force_mean")[1] == 0.0);  // never rested
  CHECK(values("body_force_peak") == std::vector<double>{0.0, 0.5, 8.0});
  CHECK(approx(values("body_friction_work")[2], 1.5, 1e-14));
  CHECK(values("body_friction_work")[0] == 0.0);
}

TEST_CASE("metrics: hand path length, energy in and Joule loss of a recording") {
  Recording rec = timed({1, false, false, false, {}}, 5, 0.25);
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t r = 0; r < 5; ++r) {
    set(rec, r, L.hand(0), 0.03 * double(r));  // 3-4-5 steps: 5 cm each
    set(rec, r, L.hand(2), 0.04 * double(r));
    set(rec, r, L.energy(Energy::electrical_in), 2.0 * double(r));
    set(rec, r, L.energy(Energy::joule), 0.5 * double(r));
  }
  const Metrics m = compute_metrics(rec);
  CHECK(approx(m["hand_path_length"], 0.2, 1e-15));
  CHECK(m["energy_in"] == 8.0);  // E_in at the end
  CHECK(m["joule"] == 2.0);
  CHECK(m.find("hand_error_rms") == nullptr);  // no task, no hand error
  CHECK(m.find("current_rms") == nullptr);     // no motors
  CHECK(m.find("time_in_contact") == nullptr); // no contact
  CHECK_THROWS_AS(m["current_rms"], std::out_of_range);
}

TEST_CASE("metrics: a run with everything has the whole vocabulary, in its order, by its names") {
  Recording rec = timed({2, true, true, true, {"elbow"}, true}, 4, 0.1);
  const Metrics m = compute_metrics(rec);
  std::vector<std::string> vocabulary;
#define NAME(name, unit, shape, what) vocabulary.push_back(#name);
  ELBOWSIM_METRICS(NAME)
#undef NAME
  std::vector<std::string> names;
  for (const Metric& metric : m.list) names.push_back(metric.name);
  CHECK(names == vocabulary);
  CHECK(std::string(metric::hand_error_rms) == "hand_error_rms");  // the constants are the names
  CHECK(std::string(metric::body_friction_work) == "body_friction_work");
}

TEST_CASE("metrics: every metric's unit is the vocabulary's; only samples and rest shares have none") {
  Recording rec = timed({2, true, true, true, {"elbow"}, true}, 4, 0.1);
  const Metrics m = compute_metrics(rec);
  CHECK(m.list.size() == 24);  // the whole vocabulary, for a run with everything
  CHECK(m.bodies == std::vector<std::string>{"elbow", "link0", "link1"});
  for (const Metric& metric : m.list) {
    CAPTURE(metric.name);
    CHECK(metric.unit == metric_unit(metric.name));
    const bool unitless = metric.name == "samples" || metric.name == "rest_fraction" ||
                          metric.name == "body_rest_fraction";
    CHECK((metric_unit(metric.name) == "") == unitless);
    const std::size_t values = metric.shape == Metric::Shape::per_joint  ? 2u
                               : metric.shape == Metric::Shape::per_body ? 3u
                                                                         : 1u;  // 1 elbow
    CHECK(metric.values.size() == values);
  }
  CHECK(metric_unit("current_rms") == "A");
  CHECK(metric_unit("nonsense") == "");
  CHECK_THROWS_AS(m["current_rms"], std::out_of_range);  // a per-joint metric has no single value
  CHECK(compute_metrics(Recording(rec.layout)).list.empty());  // no rows, no metrics
}
