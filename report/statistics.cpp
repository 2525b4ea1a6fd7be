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
  if (x.size() < 2) throw std::invalid_argument("bootstrap_mean: needs at least 2 values");
  const std::size_t n = x.size();
  const double m = mean(x);
  // Sums of deviations from m: no cancellation when the spread is small
  // against the values (hand errors of 1e-5 m that differ by 1e-8).
  auto standard_error = [n](double sum, double sum2) {
    const double mu = sum / static_cast<double>(n);
    const double var = std::max(0.0, sum2 / static_cast<double>(n) - mu * mu);
    return std::sqrt(var / static_cast<double>(n - 1));  // sample sd / sqrt(n)
  };
  double sum = 0, sum2 = 0;
  for (double v : x) sum += v - m, sum2 += (v - m) * (v - m);
  const double se = standard_error(sum, sum2);
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
    const double se_r = standard_error(s, s2);
    if (se_r > 1e-9 * se) t.push_back((s / static_cast<double>(n)) / se_r);
  }
  std::sort(t.begin(), t.end());
  return {m - quantile(t, (1 + level) / 2) * se, m - quantile(t, (1 - level) / 2) * se};
}

PairedRatio paired_ratio(const std::vector<double>& a, const std::vector<double>& b, double level,
                         int resamples, std::uint64_t seed) {
  if (a.size() != b.size()) throw std::invalid_argument("paired_ratio: unpaired values");
  PairedRatio out;
  out.pairs = static_cast<long>(a.size());
  std::vector<double> logs;
  long wins = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(a[i] > 0 && b[i] > 0)) throw std::invalid_argument("paired_ratio: values must be > 0");
    logs.push_back(std::log(a[i] / b[i]));
    wins += a[i] < b[i];
  }
  if (logs.empty()) return out;
  out.ratio = std::exp(mean(logs));
  out.win_rate = static_cast<double>(wins) / static_cast<double>(logs.size());
  if (logs.size() < 2) {
    out.ci = {out.ratio, out.ratio};
    return out;
  }
  const Interval l = bootstrap_mean(logs, level, resamples, seed);
  out.ci = {std::exp(l.low), std::exp(l.high)};
  return out;
}

}  // namespace elbowsim::report
