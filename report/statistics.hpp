// Statistics of a Monte Carlo study's metrics: mean, median, bootstrap
// confidence intervals (BCa), and the paired comparison of two variants over
// the same draws. Nothing here throws on data: a statistic that cannot be
// computed (a ratio of a value <= 0, too few values for an interval) comes back
// with its reason and the positions of the values behind it. Bootstraps use
// their own seeded generator: the same numbers in, the same interval out.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim::report {

struct Interval {
  double low = 0, high = 0;
  bool contains(double x) const { return low <= x && x <= high; }
};

// The fewest values (valid draws, or pairs of valid draws) an interval is
// given for, and so a verdict. Measured over 2000 samples of n values each
// (the table: scenarios/README.md, uncertainty; tests/test_statistics.cpp,
// "coverage at small n", checks its main points): the nominal 95 % BCa
// interval of the mean covers the true mean of a normal, an exponential and
// a lognormal (sigma 0.5) in 66-72 % of samples at n = 3, 81-84 % at 5,
// 87-90 % at 10, and 90-93 % from 15 to 30 (within 5 points of 95 %). A
// lognormal of sigma 1 stays below (82 % at 10, 85-88 % from 15).
constexpr std::size_t kMinIntervalValues = 15;

double mean(const std::vector<double>& x);
double median(std::vector<double> x);

// The distribution-free interval of the median at `level` (0.95): order
// statistics x_(k+1) and x_(n-k) of the sorted values, k the most left out on
// each side with binomial coverage 1 - 2 P(B <= k) >= level, B ~ Bin(n, 1/2).
// False (interval untouched) below the n that reaches `level` (6 at 0.95).
bool median_interval(std::vector<double> x, double level, Interval& out);

// The BCa bootstrap interval of the mean at `level` (0.95): percentiles of
// `resamples` means of resamples with replacement, corrected for the bias
// (the share of them below the mean) and the acceleration (the skewness of
// the jackknife means) (Efron 1987). A percentile interval, it lies within
// the range of the bootstrap means: never below 0 for values that never are,
// never wider than the values' range. (The bootstrap-t interval used before
// covered a little more often at 10 values, but divides by the spread of
// each resample: when a few draws lie far from the rest, the resamples that
// miss them have almost none, and its upper bound exceeded 46 x the true
// mean (4.7e8 x on a log scale) in 5 % of 1000 samples of 30 with 10 % of
// the draws 30 x the rest; BCa's stays below 3.2 x, with 94 % coverage.) Needs
// at least 2 values (throws otherwise); equal values give [mean, mean].
Interval bootstrap_mean(const std::vector<double>& x, double level, int resamples,
                        std::uint64_t seed);

// The same for values that are never negative (throws on a negative one),
// its acceleration taken on a log scale (of the jackknife means), as suits a
// positive quantity whose spread grows with its size.
Interval bootstrap_mean_log(const std::vector<double>& x, double level, int resamples,
                            std::uint64_t seed);

// Whether a quantity can change sign (linear) or never is negative (log).
enum class Scale { linear, log };

// The mean of one metric over the valid draws, with its interval when one
// can be given: at least kMinIntervalValues values, all finite, none
// negative on a log scale, a finite result. Otherwise `no_interval` says why
// and `involved` holds the positions of the values that prevent it.
struct Estimate {
  std::size_t n = 0;
  double mean = NAN, median = NAN;
  std::optional<Interval> ci;
  std::string no_interval;
  std::vector<std::size_t> involved;
};
Estimate estimate_mean(const std::vector<double>& x, Scale scale, double level, int resamples,
                       std::uint64_t seed);

// a_i against b_i over the same draws. A ratio (of strictly positive
// quantities): the geometric mean of a_i / b_i with the BCa interval of the
// mean log ratio, exponentiated. A difference (of quantities that may change
// sign): the mean of a_i - b_i with its BCa interval. `value` is NaN when the
// statistic cannot be computed (a ratio with a value <= 0, a value not
// finite, no pairs); `ci` is empty below kMinIntervalValues pairs too.
// `problem` says why, `involved` holds the positions of the pairs behind it.
// win_rate: the share of pairs with a_i < b_i. Throws only when a and b
// differ in length (a caller's error, not data).
struct PairedStatistic {
  std::size_t pairs = 0;
  double value = NAN;
  std::optional<Interval> ci;
  double win_rate = NAN;
  std::size_t a_lower = 0, b_lower = 0;  // pairs with a_i < b_i, with b_i < a_i (ties in neither)
  double sign_test_p = NAN;              // sign_test_p(a_lower, a_lower + b_lower)
  std::string problem;
  std::vector<std::size_t> involved;
  bool computed() const { return std::isfinite(value); }
};
// The exact two-sided sign test: the probability, were a and b equally
// likely to be the lower in each pair, of a split at least as uneven as
// `lower` of `n` (ties left out). 1 when n is 0. It needs no assumption on
// the values' distribution, only independent pairs.
double sign_test_p(std::size_t lower, std::size_t n);

// Holm's step-down correction for a family of tests with p-values `p`: which
// are rejected with the family-wise error kept at `alpha` (the smallest p at
// alpha / m, the next at alpha / (m - 1), ..., stopping at the first kept).
std::vector<bool> holm_rejects(const std::vector<double>& p, double alpha);

PairedStatistic paired_ratio(const std::vector<double>& a, const std::vector<double>& b,
                             double level, int resamples, std::uint64_t seed);
PairedStatistic paired_difference(const std::vector<double>& a, const std::vector<double>& b,
                                  double level, int resamples, std::uint64_t seed);

}  // namespace elbowsim::report
