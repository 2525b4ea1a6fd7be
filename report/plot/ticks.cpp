#include "report/plot/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>
#include <utility>

#include "engine/recording/number_text.hpp"

namespace elbowsim::plot {

namespace {

// A range narrower than this, relative to its magnitude, is a constant: its
// ticks could not be told apart in 15 significant digits.
constexpr double kRelativeResolution = 1e-12;

// Exact powers of ten for small exponents (std::pow(10, -3) is not 1e-3).
double power_of_ten(int e) {
  char text[16];
  std::snprintf(text, sizeof text, "1e%d", e);
  return std::strtod(text, nullptr);
}

// [lo, hi] in order, finite, and wide enough to tick.
std::pair<double, double> usable_range(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (lo > hi) std::swap(lo, hi);
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo > kRelativeResolution * magnitude && hi > lo) return {lo, hi};
  // A constant: +-10 % of its value, or +-1 around zero.
  const double mid = 0.5 * (lo + hi);
  const double half = mid == 0 ? 1.0 : 0.1 * std::abs(mid);
  return {mid - half, mid + half};
}

// "⁻¹²" for -12.
std::string superscript(int n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = n < 0 ? "⁻" : "";
  const std::string plain = std::to_string(std::abs(n));
  for (char c : plain) text += digits[c - '0'];
  return text;
}

}  // namespace

double nice_step(double range, int target) {
  // The smallest of 1, 2, 5 x 10^k that makes at most `target` intervals.
  const double raw = range / std::max(target, 1);
  const int e = static_cast<int>(std::floor(std::log10(raw)));
  for (int k = e; k <= e + 1; ++k)
    for (double mantissa : {1.0, 2.0, 5.0})
      if (mantissa * power_of_ten(k) >= raw * (1 - 1e-12)) return mantissa * power_of_ten(k);
  return power_of_ten(e + 2);
}

std::string format_power_of_ten(int exponent) { return "10" + superscript(exponent); }

std::string format_linear(double value, double step, double magnitude) {
  if (std::abs(value) < 1e-9 * step) value = 0;  // no "-0.0"
  const int step_exponent = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  magnitude = std::max(magnitude, step);
  // Fixed point for everyday magnitudes: as many decimals as the step needs.
  if (magnitude >= 1e-3 && magnitude < 1e5) return fixed(value, std::max(0, -step_exponent));
  // Otherwise m×10^e with the axis' exponent e, m as precise as the step.
  if (value == 0) return "0";
  const int e = static_cast<int>(std::floor(std::log10(magnitude) + 1e-9));
  return fixed(value / power_of_ten(e), std::max(0, e - step_exponent)) + "×" +
         format_power_of_ten(e);
}

Ticks linear_ticks(double lo, double hi, int target, bool loose) {
  std::tie(lo, hi) = usable_range(lo, hi);
  const double step = nice_step(hi - lo, target);
  const double slack = 1e-9 * step;  // lo = 0.30000000000000004 still ticks 0.3
  Ticks ticks;
  ticks.lo = loose ? std::floor(lo / step + 1e-9) * step : lo;
  ticks.hi = loose ? std::ceil(hi / step - 1e-9) * step : hi;
  // Ticks as integer multiples of the step: no drift from repeated addition.
  const long first = static_cast<long>(std::ceil((ticks.lo - slack) / step));
  const long last = static_cast<long>(std::floor((ticks.hi + slack) / step));
  const double magnitude = std::max(std::abs(ticks.lo), std::abs(ticks.hi));
  for (long k = first; k <= last; ++k) {
    ticks.major.push_back(k * step);
    ticks.labels.push_back(format_linear(k * step, step, magnitude));
  }
  return ticks;
}

Ticks log_ticks(double lo, double hi, int target) {
  if (!(lo > 0) || !(hi > 0) || !std::isfinite(lo) || !std::isfinite(hi)) lo = 1, hi = 10;
  if (lo > hi) std::swap(lo, hi);
  int e_lo = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int e_hi = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (e_lo == e_hi) --e_lo, ++e_hi;  // one power of ten: a decade either side
  // Label every 1, 2, 5, 10, ... decades: the least that shows at most
  // `target` + 1 labels once the limits snap out to multiples of it.
  int every = 1;
  for (int step : {1, 2, 5, 10, 20, 50, 100, 200}) {
    every = step;
    const int first = static_cast<int>(std::floor(static_cast<double>(e_lo) / step));
    const int last = static_cast<int>(std::ceil(static_cast<double>(e_hi) / step));
    if (last - first <= target) break;
  }
  e_lo = static_cast<int>(std::floor(static_cast<double>(e_lo) / every)) * every;
  e_hi = static_cast<int>(std::ceil(static_cast<double>(e_hi) / every)) * every;
  Ticks ticks;
  ticks.lo = power_of_ten(e_lo);
  ticks.hi = power_of_ten(e_hi);
  for (int e = e_lo; e <= e_hi; e += every) {
    ticks.major.push_back(power_of_ten(e));
    ticks.labels.push_back(format_power_of_ten(e));
  }
  // Minor ticks: 2..9 x 10^e when every decade is labelled, else the unlabelled
  // decades. Over one or two decades 2 x 10^e and 5 x 10^e get labels too.
  for (int e = e_lo; e < e_hi; ++e) {
    if (every == 1)
      for (int m = 2; m <= 9; ++m) ticks.minor.push_back(m * power_of_ten(e));
    else if ((e - e_lo) % every != 0)
      ticks.minor.push_back(power_of_ten(e));
  }
  if (e_hi - e_lo > 2) return ticks;
  Ticks labelled = ticks;
  labelled.major.clear(), labelled.labels.clear();
  for (int e = e_lo; e <= e_hi; ++e)
    for (int m : {1, 2, 5}) {
      if (e == e_hi && m > 1) break;
      labelled.major.push_back(m * power_of_ten(e));
      labelled.labels.push_back(m == 1 ? format_power_of_ten(e)
                                       : std::to_string(m) + "×" + format_power_of_ten(e));
    }
  return labelled;
}

}  // namespace elbowsim::plot
