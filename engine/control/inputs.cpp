#include "engine/control/inputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace elbowsim {

namespace {

// Index of the last table time <= t (times are strictly increasing, t inside).
std::size_t segment(const std::vector<double>& times, double t) {
  auto it = std::upper_bound(times.begin(), times.end(), t);
  return static_cast<std::size_t>(it - times.begin()) - 1;
}

double linear_table(const InputProfile& p, double t) {
  if (t <= p.times.front()) return p.values.front();
  if (t >= p.times.back()) return p.values.back();
  std::size_t k = segment(p.times, t);
  double s = (t - p.times[k]) / (p.times[k + 1] - p.times[k]);
  return p.values[k] + s * (p.values[k + 1] - p.values[k]);
}

double step_table(const InputProfile& p, double t) {
  if (t < p.times.front()) return 0.0;
  if (t >= p.times.back()) return p.values.back();
  return p.values[segment(p.times, t)];
}

}  // namespace

double InputProfile::at(double t) const {
  switch (kind) {
    case Kind::zero: return 0.0;
    case Kind::constant: return value;
    case Kind::sine:
      return offset + amplitude * std::sin(2.0 * std::numbers::pi * frequency * t + phase);
    case Kind::table: return linear_table(*this, t);
    case Kind::steps: return step_table(*this, t);
  }
  return 0.0;
}

}  // namespace elbowsim
