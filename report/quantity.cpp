#include "report/quantity.hpp"

#include <cmath>
#include <cstdio>
#include <set>

namespace elbowsim::report {

namespace {

bool prefixable(const std::string& unit) {
  static const std::set<std::string> units{"m", "J", "W", "A", "V", "N", "s", "N s", "m/s"};
  return units.count(unit) > 0;
}

std::string digits_of(double value, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace

std::string quantity(double value, const std::string& unit, int digits) {
  if (!std::isfinite(value)) return "—";
  const std::string space = unit.empty() ? "" : " ";
  if (value == 0) return "0" + space + unit;
  if (!prefixable(unit)) return digits_of(value, digits) + space + unit;
  // Prefixes from nano to mega; beyond them, scientific notation.
  static const char* prefixes[] = {"n", "µ", "m", "", "k", "M"};
  const double magnitude = std::abs(value);
  int k = static_cast<int>(std::floor(std::log10(magnitude) / 3)) + 3;
  if (k < 0 || k > 5) return digits_of(value, digits) + space + unit;
  double scaled = value / std::pow(1000.0, k - 3);
  // 999.7 µm rounds to "1e+03 µm" at 3 digits: move up a prefix first.
  if (std::abs(std::stod(digits_of(scaled, digits))) >= 1000 && k < 5) scaled /= 1000, ++k;
  return digits_of(scaled, digits) + " " + prefixes[k] + unit;
}

std::string percent(double fraction) {
  const double p = 100 * fraction;
  if (!std::isfinite(p)) return "—";
  if (p != 0 && std::abs(p) < 0.01) return digits_of(p, 2) + " %";
  if (std::abs(p) >= 10) return digits_of(std::round(p), 4) + " %";
  return digits_of(p, 2) + " %";
}

}  // namespace elbowsim::report
