#include "render/nice_scale.hpp"

#include <cmath>
#include <cstdio>

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

std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

std::string length_label(double metres) {
  struct Unit {
    double size;
    const char* name;
  };
  // The largest unit in which the length is at least 1.
  for (const Unit& u : {Unit{1, "m"}, Unit{0.01, "cm"}, Unit{1e-3, "mm"}, Unit{1e-6, "µm"}})
    if (metres >= u.size * (1 - 1e-9)) return short_number(metres / u.size) + " " + u.name;
  return short_number(metres * 1e9) + " nm";
}

}  // namespace elbowsim
