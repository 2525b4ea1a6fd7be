// The verdict of a paired Monte Carlo comparison of two variants A and B over
// the same draws, per compared quantity (kCompared): for strictly positive
// ones (electrical energy drawn from the supply, RMS hand error) the paired
// ratio A/B with its 95 % BCa bootstrap interval (of the mean log ratio); for the net
// electrical energy (drawn - regenerated, negative when the motors feed back
// more than they draw) the paired mean difference A - B in J with its
// interval. A sentence states a difference only when (1) the interval
// excludes 1 (a ratio) or 0 (a difference), (2) at least
// report::kMinIntervalValues draws have both runs valid, (3) at most 10 % of
// the draws had an invalid run, and (4) for the hand error, both medians
// exceed 10 x their accuracy floor (below it they measure the integrator).
// A quantity without a verdict says why, naming the draws behind it; nothing
// here throws on data.
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/recording/metrics.hpp"

namespace elbowsim::study {

constexpr double kConfidenceLevel = 0.95;
constexpr int kBootstrapResamples = 4000;
constexpr double kFloorFactor = 10;        // hand errors must exceed 10 x the floor
constexpr double kMaxInvalidShare = 0.10;  // more draws with an invalid run: no verdict

// A quantity the paired comparison states a verdict on.
struct ComparedQuantity {
  const char* metric;  // its name in the run's metrics
  const char* what;    // in a sentence
  bool ratio;  // a ratio of positive values, else a difference
  std::string unit() const { return metric_unit(metric); }  // the metric vocabulary's
};
inline constexpr ComparedQuantity kCompared[] = {
    {metric::energy_drawn, "electrical energy drawn from the supply", true},
    {metric::energy_in, "net electrical energy (drawn − regenerated)", false},
    {metric::hand_error_rms, "RMS hand error", true}};

struct PairedSamples {
  std::string a, b;  // variant names
  long draws = 0;    // all draws, valid or not
  long dropped = 0;  // draws where a run of the pair was invalid
  // Per metric (kCompared), the values of the draws where both runs were
  // valid and have the metric, in draw order (a[i] pairs with b[i]), and
  // those draws' indices.
  std::map<std::string, std::vector<double>> a_values, b_values;
  std::map<std::string, std::vector<long>> draw_index;
  double floor_a = 0, floor_b = 0;  // [m] accuracy floors of the hand error
};

// {a, b, pairs_with_an_invalid_run, per kCompared metric: {statistic
// ("ratio" or "difference"), unit (a difference's), pairs, ratio or
// difference, ci95, win_rate, outcome, reason, draws}, verdict: [sentences]}.
// outcome: "lower" or "higher" (a than b, the interval excludes 1 or 0), "no
// significant difference", or "no verdict" with its reason (and the draws
// behind it, when some are). The estimate is left out when it could not be
// computed, ci95 when no interval is given.
nlohmann::ordered_json paired_verdict(const PairedSamples& samples, std::uint64_t seed);

}  // namespace elbowsim::study
