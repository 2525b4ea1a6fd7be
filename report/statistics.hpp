// Statistics of a Monte Carlo study's metrics: mean, median, bootstrap
// confidence intervals, and the paired comparison of two variants over the
// same draws. Nothing here throws on data: a statistic that cannot be
// computed (a log of a value <= 0, too few values for an interval) comes back
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
// given for, and so a verdict. Measured (1000-2000 samples of n from each of
// a normal and an exponential, linear scale, and an exponential, lognormals
// of sigma 0.5 and 1 and a normal, log scale; tests/test_statistics.cpp
// checks the main points): at n = 3 the nominal 95 % bootstrap-t interval covers the true mean in
// 77-84 % of samples and is infinite in up to 22 % of them (resamples of 3
// values repeat one value often and have almost no spread); at 4-8 it covers
// 88-95 % but only by being absurdly wide now and then: the widest 1 % of the
// intervals of a lognormal of sigma 0.5 span a factor (high / low) of 1e67 at
// n = 4, 6.6e4 at 5, 385 at 6, 18 at 8. At n = 10 coverage is 90-95 % in all
// six (within 5 points of 95 %) and that widest 1 % spans a factor 9.
constexpr std::size_t kMinIntervalValues = 10;

double mean(const std::vector<double>& x);
double median(std::vector<double> x);

// The bootstrap-t (studentized) interval of the mean at `level` (0.95):
// t* = (mean* - mean) / se* over `resamples` resamples with replacement, the
// interval mean - t*_{(1+level)/2} se .. mean - t*_{(1-level)/2} se. Unlike
// the percentile interval it keeps its coverage for skewed metrics at small
// samples (hand errors are; tested: exponential, n = 30). Needs at least 2
// values (throws otherwise); equal values give [mean, mean]. For values that
// may have either sign (a net energy, a paired difference).
Interval bootstrap_mean(const std::vector<double>& x, double level, int resamples,
                        std::uint64_t seed);

// The same on a log scale, for strictly positive values (throws otherwise):
// the studentized statistic is log(mean* / mean) / (se* / mean*), so the
// interval is mean x exp(-t* se / mean): never reaches 0 or below (an RMS
// error's interval stays positive) and is as skewed as the data.
Interval bootstrap_mean_log(const std::vector<double>& x, double level, int resamples,
                            std::uint64_t seed);

// Whether a quantity can change sign (linear) or is strictly positive (log).
enum class Scale { linear, log };

// The mean of one metric over the valid draws, with its interval when one
// can be given: at least kMinIntervalValues values, all finite, all > 0 on a
// log scale unless all are equal (then [value, value], 0 included), a finite
// result. Otherwise `no_interval` says why and `involved` holds the positions
// of the values that prevent it (values <= 0 or not finite).
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
// quantities): the geometric mean of a_i / b_i with the bootstrap-t interval
// of the mean log ratio, exponentiated. A difference (of quantities that may
// change sign): the mean of a_i - b_i with its bootstrap-t interval. `value`
// is NaN when the statistic cannot be computed (a ratio with a value <= 0, a
// value not finite, no pairs); `ci` is empty below kMinIntervalValues pairs
// too. `problem` says why, `involved` holds the positions of the pairs behind
// it. win_rate: the share of pairs with a_i < b_i. Throws only when a and b
// differ in length (a caller's error, not data).
struct PairedStatistic {
  std::size_t pairs = 0;
  double value = NAN;
  std::optional<Interval> ci;
  double win_rate = NAN;
  std::string problem;
  std::vector<std::size_t> involved;
  bool computed() const { return std::isfinite(value); }
};
PairedStatistic paired_ratio(const std::vector<double>& a, const std::vector<double>& b,
                             double level, int resamples, std::uint64_t seed);
PairedStatistic paired_difference(const std::vector<double>& a, const std::vector<double>& b,
                                  double level, int resamples, std::uint64_t seed);

}  // namespace elbowsim::report
