#include "report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace elbowsim::report {

namespace {

// The q-quantile of sorted values, linear between order statistics.
double quantile(const std::vector<double>& sorted, double q) {
  const double pos = q * static_cast<double>(sorted.size() - 1);
  const auto k = static_cast<std::size_t>(pos);
  const std::size_t k1 = std::min(k + 1, sorted.size() - 1);
  return sorted[k] + (pos - static_cast<double>(k)) * (sorted[k1] - sorted[k]);
}

// The standard error of a mean from the sums of n deviations from a centre
// (no cancellation when the spread is small against the values: hand errors
// of 1e-5 m that differ by 1e-8).
double standard_error(std::size_t n, double sum, double sum2) {
  const double mu = sum / static_cast<double>(n);
  const double var = std::max(0.0, sum2 / static_cast<double>(n) - mu * mu);
  return std::sqrt(var / static_cast<double>(n - 1));  // sample sd / sqrt(n)
}

// The bootstrap-t interval of the mean, studentized on a linear or a log
// scale: t* = (g(mean*) - g(mean)) / (g'(mean*) se*), g the identity or log.
Interval studentized(const std::vector<double>& x, double level, int resamples, std::uint64_t seed,
                     Scale scale) {
  if (x.size() < 2) throw std::invalid_argument("bootstrap: needs at least 2 values");
  const std::size_t n = x.size();
  const double m = mean(x);
  double sum = 0, sum2 = 0;
  for (double v : x) sum += v - m, sum2 += (v - m) * (v - m);
  const double se = standard_error(n, sum, sum2);
  if (!(se > 0)) return {m, m};  // all values equal
  std::mt19937_64 gen(seed);
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(resamples));
  for (int r = 0; r < resamples; ++r) {
    double s = 0, s2 = 0;
    // Modulo bias is 2^-64 relative: nothing next to the bootstrap's own error.
    for (std::size_t i = 0; i < n; ++i) {
      const double d = x[gen() % n] - m;
      s += d, s2 += d * d;
    }
    // A resample of one value repeated has no spread (its rounding residue
    // would make t huge): it is left out, as are all with a spread below
    // 1e-9 of the sample's.
    const double se_r = standard_error(n, s, s2);
    if (!(se_r > 1e-9 * se)) continue;
    const double shift = s / static_cast<double>(n);  // mean* - mean
    t.push_back(scale == Scale::linear ? shift / se_r : std::log1p(shift / m) * (m + shift) / se_r);
  }
  if (t.empty()) return {m, m};
  std::sort(t.begin(), t.end());
  const double t_high = quantile(t, (1 + level) / 2), t_low = quantile(t, (1 - level) / 2);
  if (scale == Scale::linear) return {m - t_high * se, m - t_low * se};
  return {m * std::exp(-t_high * se / m), m * std::exp(-t_low * se / m)};
}

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Why no interval is given for n values; "" when n is enough.
std::string too_few(std::size_t n, const char* one, const char* many) {
  if (n >= kMinIntervalValues) return "";
  return count(n, one, many) + "; an interval needs at least " + std::to_string(kMinIntervalValues);
}

bool finite(const Interval& i) { return std::isfinite(i.low) && std::isfinite(i.high); }

}  // namespace

double mean(const std::vector<double>& x) {
  double sum = 0;
  for (double v : x) sum += v;
  return x.empty() ? std::nan("") : sum / static_cast<double>(x.size());
}

double median(std::vector<double> x) {
  if (x.empty()) return std::nan("");
  std::sort(x.begin(), x.end());
  return quantile(x, 0.5);
}

Interval bootstrap_mean(const std::vector<double>& x, double level, int resamples,
                        std::uint64_t seed) {
  return studentized(x, level, resamples, seed, Scale::linear);
}

Interval bootstrap_mean_log(const std::vector<double>& x, double level, int resamples,
                            std::uint64_t seed) {
  for (double v : x)
    if (!(v > 0)) throw std::invalid_argument("bootstrap_mean_log: values must be > 0");
  return studentized(x, level, resamples, seed, Scale::log);
}

Estimate estimate_mean(const std::vector<double>& x, Scale scale, double level, int resamples,
                       std::uint64_t seed) {
  Estimate e;
  e.n = x.size();
  e.mean = mean(x);
  e.median = median(x);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) e.involved.push_back(i);
  if (!e.involved.empty()) {
    e.no_interval = count(e.involved.size(), "value is", "values are") + " not finite";
    return e;
  }
  e.no_interval = too_few(x.size(), "value", "values");
  if (!e.no_interval.empty()) return e;
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); })) {
    e.ci = Interval{x.front(), x.front()};  // no spread (a zero in every draw included)
    return e;
  }
  if (scale == Scale::log) {
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!(x[i] > 0)) e.involved.push_back(i);
    if (!e.involved.empty()) {
      e.no_interval = count(e.involved.size(), "value is", "values are") +
                      " not > 0: no interval on a log scale";
      return e;
    }
  }
  const Interval ci = studentized(x, level, resamples, seed, scale);
  if (finite(ci))
    e.ci = ci;
  else
    e.no_interval = "the bootstrap interval is not finite";
  return e;
}

namespace {

// A paired statistic of per-pair values y_i (log ratios, or differences),
// `back` mapping the mean of y and its interval to the reported scale.
template <class Back>
PairedStatistic paired(const std::vector<double>& y, const std::vector<double>& a,
                       const std::vector<double>& b, double level, int resamples,
                       std::uint64_t seed, const Back& back) {
  PairedStatistic out;
  out.pairs = y.size();
  if (y.empty()) {
    out.problem = "no pairs of valid runs";
    return out;
  }
  std::size_t wins = 0;
  for (std::size_t i = 0; i < y.size(); ++i) wins += a[i] < b[i];
  out.value = back(mean(y));
  out.win_rate = static_cast<double>(wins) / static_cast<double>(y.size());
  out.problem = too_few(y.size(), "pair", "pairs");
  if (!out.problem.empty()) return out;
  const Interval l = studentized(y, level, resamples, seed, Scale::linear);
  const Interval ci{back(l.low), back(l.high)};
  if (finite(ci))
    out.ci = ci;
  else
    out.problem = "the bootstrap interval is not finite";
  return out;
}

void check_paired(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("paired statistic: unpaired values");
}

}  // namespace

PairedStatistic paired_ratio(const std::vector<double>& a, const std::vector<double>& b,
                             double level, int resamples, std::uint64_t seed) {
  check_paired(a, b);
  std::vector<double> logs;
  std::vector<std::size_t> bad;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(a[i] > 0 && b[i] > 0 && std::isfinite(a[i]) && std::isfinite(b[i])))
      bad.push_back(i);
    else
      logs.push_back(std::log(a[i] / b[i]));
  }
  if (!bad.empty()) {
    PairedStatistic out;
    out.pairs = a.size();
    out.involved = bad;
    out.problem = "a ratio needs values > 0; " + count(bad.size(), "pair has", "pairs have") +
                  " a value <= 0 or not finite";
    return out;
  }
  return paired(logs, a, b, level, resamples, seed, [](double y) { return std::exp(y); });
}

PairedStatistic paired_difference(const std::vector<double>& a, const std::vector<double>& b,
                                  double level, int resamples, std::uint64_t seed) {
  check_paired(a, b);
  std::vector<double> d;
  std::vector<std::size_t> bad;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(std::isfinite(a[i]) && std::isfinite(b[i])))
      bad.push_back(i);
    else
      d.push_back(a[i] - b[i]);
  }
  if (!bad.empty()) {
    PairedStatistic out;
    out.pairs = a.size();
    out.involved = bad;
    out.problem = count(bad.size(), "pair has", "pairs have") + " a value that is not finite";
    return out;
  }
  return paired(d, a, b, level, resamples, seed, [](double y) { return y; });
}

}  // namespace elbowsim::report
