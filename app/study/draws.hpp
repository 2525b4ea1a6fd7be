// Monte Carlo draws of the uncertain plant parameters (the scenario's
// uncertainty: section). Draw i depends only on the seed and i, not on how
// many draws a study takes or in which order they run; each draw is applied
// to every variant (a paired comparison), relative laws around each variant's
// own nominal value. Each case of a montecarlo study has a seed of its own
// (case_seed).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"

namespace elbowsim::study {

// One draw: per parameter, the relative deviation u (uniform, normal: the
// value is nominal x (1 + u)) or the absolute value (range).
struct Draw {
  long index = 0;
  std::vector<double> u;
};

Draw draw_parameters(const Uncertainty& uncertainty, std::uint64_t seed, long index);

// The seed of one Monte Carlo case's draws. A scenario without a study (one
// case, no name) draws from `seed` itself; a study case from a seed mixed
// from `seed` and the case's name, so that every case draws plants of its
// own (its verdict is evidence apart from the others') and a case run alone
// (--case), in any order or shard, draws the same ones.
std::uint64_t case_seed(std::uint64_t seed, const std::string& case_name);

// The value a draw gives parameter p.
double drawn_value(const UncertainParameter& p, double u);

// "key=value" overrides that set the draw's values, exact to the last bit
// (17 significant digits), around the nominal values of `uncertainty` (a
// variant's own).
std::vector<std::string> draw_overrides(const Uncertainty& uncertainty, const Draw& draw);

}  // namespace elbowsim::study
