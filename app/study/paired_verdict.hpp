// The verdict of a paired Monte Carlo comparison of two variants A and B over
// the same draws: for electrical energy and RMS hand error, the paired ratio
// A/B with its 95 % bootstrap interval, and a sentence that states a
// difference only when (1) the interval excludes 1, (2) at most 10 % of the
// draws had an invalid run, and (3) for the hand error, both medians exceed
// 10 x their accuracy floor (below it they measure the integrator).
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace elbowsim::study {

constexpr double kConfidenceLevel = 0.95;
constexpr int kBootstrapResamples = 4000;
constexpr double kFloorFactor = 10;        // hand errors must exceed 10 x the floor
constexpr double kMaxInvalidShare = 0.10;  // more draws with an invalid run: no verdict

struct PairedSamples {
  std::string a, b;  // variant names
  long draws = 0;    // all draws, valid or not
  long dropped = 0;  // draws where a run of the pair was invalid
  // Per metric ("energy_in", "hand_error_rms"), the values of the draws where
  // both runs were valid, in draw order (a[i] pairs with b[i]).
  std::map<std::string, std::vector<double>> a_values, b_values;
  double floor_a = 0, floor_b = 0;  // [m] accuracy floors of the hand error
};

// {a, b, pairs_with_an_invalid_run, energy_in: {pairs, ratio, ci95, win_rate,
//  outcome}, hand_error_rms: {...}, verdict: [sentences]}. outcome: "lower" or
// "higher" (a than b, the interval excludes 1), "no significant difference",
// or "no verdict" (too few valid pairs, or errors below the floor).
nlohmann::ordered_json paired_verdict(const PairedSamples& samples, std::uint64_t seed);

}  // namespace elbowsim::study
