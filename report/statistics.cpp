#include "report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "engine/recording/number_text.hpp"

namespace elbowsim::report {

namespace {

// The q-quantile of sorted values, linear between order statistics.
double quantile(const std::vector<double>& sorted, double q) {
  const double pos = q * static_cast<double>(sorted.size() - 1);
  const auto k = static_cast<std::size_t>(pos);
  const std::size_t k1 = std::min(k + 1, sorted.size() - 1);
  return sorted[k] + (pos - static_cast<double>(k)) * (sorted[k1] - sorted[k]);
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// Its inverse by bisection: 100 halvings of [-40, 40] leave nothing to
// refine, and it runs three times per interval.
double normal_quantile(double p) {
  double low = -40, high = 40;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (normal_cdf(mid) < p ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

// The BCa (bias-corrected and accelerated percentile, Efron 1987) interval of
// the mean: percentiles of `resamples` bootstrap means, shifted by the bias
// z0 (the share of bootstrap means below the mean) and the acceleration a
// (the skewness of the jackknife means, of their logs on a log scale).
// Bootstrap means lie within the values' range, so the interval does too: a
// mean of values that are never negative gets an interval that never is.
Interval bca(const std::vector<double>& x, double level, int resamples, std::uint64_t seed,
             Scale scale) {
  if (x.size() < 2) throw std::invalid_argument("bootstrap: needs at least 2 values");
  const std::size_t n = x.size();
  const double m = mean(x);
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); })) return {m, m};
  std::mt19937_64 gen(seed);
  std::vector<double> means(static_cast<std::size_t>(resamples));
  double below = 0;
  for (double& b : means) {
    double s = 0;
    // Modulo bias is 2^-64 relative: nothing next to the bootstrap's own error.
    for (std::size_t i = 0; i < n; ++i) s += x[gen() % n] - m;
    b = m + s / static_cast<double>(n);  // deviations: no rounding of m itself
    below += b < m ? 1.0 : b == m ? 0.5 : 0.0;
  }
  std::sort(means.begin(), means.end());
  const double r = static_cast<double>(resamples);
  const double z0 = normal_quantile(std::clamp(below / r, 0.5 / r, 1 - 0.5 / r));
  // The jackknife: the mean without value i, on the scale of the interval.
  double sum = 0;
  for (double v : x) sum += v - m;
  std::vector<double> jack(n);
  bool positive = true;
  for (std::size_t i = 0; i < n; ++i) {
    jack[i] = m + (sum - (x[i] - m)) / static_cast<double>(n - 1);
    positive = positive && jack[i] > 0;
  }
  if (scale == Scale::log && positive)
    for (double& j : jack) j = std::log(j);
  const double centre = mean(jack);
  double num = 0, den = 0;
  for (double j : jack) num += std::pow(centre - j, 3), den += std::pow(centre - j, 2);
  const double a = den > 0 ? num / (6 * std::pow(den, 1.5)) : 0;
  auto adjusted = [&](double alpha) {
    const double w = z0 + normal_quantile(alpha);
    const double d = 1 - a * w;
    return d > 0 ? normal_cdf(z0 + w / d) : (w > 0 ? 1.0 : 0.0);
  };
  return {quantile(means, adjusted((1 - level) / 2)), quantile(means, adjusted((1 + level) / 2))};
}

// Why no interval is given for n values; "" when n is enough.
std::string too_few(std::size_t n, const char* one, const char* many) {
  if (n >= kMinIntervalValues) return "";
  return counted(static_cast<long long>(n), one, many) + "; an interval needs at least " +
         std::to_string(kMinIntervalValues);
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

bool median_interval(std::vector<double> x, double level, Interval& out) {
  const std::size_t n = x.size();
  // 1 - sign_test_p(k, n) is the coverage with k values left out on each side.
  if (n == 0 || 1 - sign_test_p(0, n) < level) return false;
  std::size_t k = 0;
  while (2 * (k + 1) < n && 1 - sign_test_p(k + 1, n) >= level) ++k;
  std::sort(x.begin(), x.end());
  out.low = x[k];
  out.high = x[n - 1 - k];
  return true;
}

Interval bootstrap_mean(const std::vector<double>& x, double level, int resamples,
                        std::uint64_t seed) {
  return bca(x, level, resamples, seed, Scale::linear);
}

Interval bootstrap_mean_log(const std::vector<double>& x, double level, int resamples,
                            std::uint64_t seed) {
  for (double v : x)
    if (!(v >= 0)) throw std::invalid_argument("bootstrap_mean_log: values must be >= 0");
  return bca(x, level, resamples, seed, Scale::log);
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
    e.no_interval = counted(static_cast<long long>(e.involved.size()), "value is", "values are") +
                    " not finite";
    return e;
  }
  e.no_interval = too_few(x.size(), "value", "values");
  if (!e.no_interval.empty()) return e;
  if (scale == Scale::log) {
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!(x[i] >= 0)) e.involved.push_back(i);
    if (!e.involved.empty()) {
      e.no_interval = counted(static_cast<long long>(e.involved.size()), "value is", "values are") +
                      " negative, for a quantity that never is";
      return e;
    }
  }
  const Interval ci = bca(x, level, resamples, seed, scale);
  if (finite(ci))
    e.ci = ci;
  else
    e.no_interval = "the bootstrap interval is not finite";
  return e;
}

double sign_test_p(std::size_t lower, std::size_t n) {
  if (n == 0) return 1.0;
  const std::size_t tail = std::min(lower, n - lower);
  // 2 x P(X <= tail), X ~ Binomial(n, 1/2), term by term in logs (n may be large).
  const double nd = static_cast<double>(n);
  double sum = 0;
  for (std::size_t i = 0; i <= tail; ++i) {
    const double id = static_cast<double>(i);
    sum += std::exp(std::lgamma(nd + 1) - std::lgamma(id + 1) - std::lgamma(nd - id + 1) -
                    nd * std::log(2.0));
  }
  return std::min(1.0, 2 * sum);
}

std::vector<bool> holm_rejects(const std::vector<double>& p, double alpha) {
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return p[x] < p[y]; });
  std::vector<bool> rejected(p.size(), false);
  const double m = static_cast<double>(p.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (!(p[order[k]] <= alpha / (m - static_cast<double>(k)))) break;
    rejected[order[k]] = true;
  }
  return rejected;
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
  for (std::size_t i = 0; i < y.size(); ++i) {
    out.a_lower += a[i] < b[i];
    out.b_lower += b[i] < a[i];
  }
  out.value = back(mean(y));
  out.win_rate = static_cast<double>(out.a_lower) / static_cast<double>(y.size());
  out.sign_test_p = sign_test_p(out.a_lower, out.a_lower + out.b_lower);
  out.problem = too_few(y.size(), "pair", "pairs");
  if (!out.problem.empty()) return out;
  const Interval l = bca(y, level, resamples, seed, Scale::linear);
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
    out.problem = "a ratio needs values > 0; " +
                  counted(static_cast<long long>(bad.size()), "pair has", "pairs have") +
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
    out.problem = counted(static_cast<long long>(bad.size()), "pair has", "pairs have") +
                  " a value that is not finite";
    return out;
  }
  return paired(d, a, b, level, resamples, seed, [](double y) { return y; });
}

}  // namespace elbowsim::report
