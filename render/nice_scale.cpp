#include "render/nice_scale.hpp"

#include <cmath>

#include "engine/recording/number_text.hpp"

namespace elbowsim {

namespace {

// x = m 10^e with m in [1, 10).
void split(double x, double& mantissa, double& power) {
  power = std::pow(10.0, std::floor(std::log10(x)));
  mantissa = x / power;
  // log10 rounding can leave m a hair under 1 or at 10.
  if (mantissa < 1) mantissa *= 10, power /= 10;
  if (mantissa >= 10) mantissa /= 10, power *= 10;
}

}  // namespace

double nice_ceil(double x) {
  double m = 0, p = 0;
  split(x, m, p);
  for (double step : {1.0, 2.0, 5.0})
    if (m <= step * (1 + 1e-9)) return step * p;
  return 10 * p;
}

double nice_floor(double x) {
  double m = 0, p = 0;
  split(x, m, p);
  for (double step : {5.0, 2.0})
    if (m >= step * (1 - 1e-9)) return step * p;
  return p;
}

std::string length_label(double metres) {
  // The largest unit in which the length is at least 1 (to rounding); the centimetre too,
  // which an SI prefix ladder (quantity()) skips.
  static constexpr Unit units[] = {{"m", 1}, {"cm", 100}, {"mm", 1e3}, {"µm", 1e6}, {"nm", 1e9}};
  return in_units(metres, units, 3, 1e-9);
}

}  // namespace elbowsim
