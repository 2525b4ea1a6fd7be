// What flips a paired verdict: one uncertain parameter at a time held at
// each end of its range while the others are drawn as usual (elbowsim
// sensitivity). For each compared ratio (kCompared: energy drawn, RMS hand
// error) the factors that change the verdict come first, then the rest by
// their swing (how far the ratio moves between the two ends, on a log scale:
// a tornado chart's order); a factor that takes the ratio across 1 is named
// with the value where it crosses. Plain data in, JSON out; the runs are montecarlo's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/scenario/scenario.hpp"

namespace elbowsim::study {

// One uncertain parameter as the file gives it (a [*] entry is one factor: its
// keys move together) and the two values it is held at: a relative law's
// deviation (uniform: ±spread; normal: ±2 spread, about 95 % of its draws) or
// a range's ends. `centre` is where its draws centre (0 for a relative law).
struct SensitivityFactor {
  std::string given;
  std::string law;  // "uniform ±10 %", "normal, 2σ = ±4 %", "range [a, b]"
  bool relative = true;
  double low = 0, high = 0, centre = 0;
};

// The factors of an uncertainty: section, in the file's order.
std::vector<SensitivityFactor> sensitivity_factors(const Uncertainty& uncertainty);

// A deviation or value as a sentence writes it: "+10 %", "−0.1001".
std::string factor_value(const SensitivityFactor& f, double u);

// The paired comparison at one point: the ratio A/B, its interval, the outcome
// (paired_verdict's: "lower", "higher", "no significant difference", "no verdict").
struct RatioAt {
  std::optional<double> ratio;
  std::optional<double> ci_low, ci_high;
  std::string outcome = "no verdict";
};

// The pair's entry for `metric` in a montecarlo.json's pairs[0].
RatioAt ratio_at(const nlohmann::ordered_json& pair, const std::string& metric);

struct FactorPoints {
  SensitivityFactor factor;
  RatioAt low, high;  // held at factor.low, factor.high
};

// For one ratio metric: {metric, what, a, b, nominal: {ratio, ci95, outcome},
// factors: [ranked by effect (flips first, then removes or decides), then by
// swing, largest first: {given, law, low: {value, ratio,
// ci95, outcome}, high: {...}, swing, monotone, effect ("flips", "removes",
// "decides", "no verdict", "none"), crosses: {end, at} when the ratio crosses
// 1 between the centre and an end}], sentences: [...]}. `swing` is the extent
// of ln ratio over the centre and both ends (0 when an end has no estimate):
// a factor whose two ends both lie beyond the centre's interval on one side
// (monotone false, said in a sentence) swings as far as its farther end. The
// crossing is linear interpolation of ln ratio between the centre (every
// factor drawn) and the end: an estimate, said so.
nlohmann::ordered_json sensitivity_of(const std::string& metric, const std::string& what,
                                      const std::string& a, const std::string& b,
                                      const RatioAt& nominal, const std::vector<FactorPoints>& factors);

}  // namespace elbowsim::study
