#include "engine/recording/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <set>

namespace elbowsim {

namespace {

constexpr const char* kNotFinite = "—";

}  // namespace

std::string significant(double x, int digits, Sign sign) {
  char text[48];
  std::snprintf(text, sizeof text, sign == Sign::always ? "%+.*g" : "%.*g", digits, x);
  return text;
}

std::string fixed(double x, int decimals) {
  // The largest double has 309 digits before the point; room for 80 decimals after it.
  char text[400];
  std::snprintf(text, sizeof text, "%.*f", decimals, x);
  return text;
}

std::string round_trip(double x) { return significant(x, 17); }

std::string listed(std::initializer_list<double> values, int digits) {
  std::string out;
  for (double x : values) out += (out.empty() ? "" : ", ") + significant(x, digits);
  return out;
}

std::string counted(long long n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural.empty() ? singular + "s" : plural);
}

std::string quantity(double value, const std::string& unit, int digits) {
  static const std::set<std::string> prefixable{"m", "J", "W", "A", "V", "N", "s", "N s", "m/s"};
  if (!std::isfinite(value)) return kNotFinite;
  const std::string space = unit.empty() ? "" : " ";
  if (value == 0) return "0" + space + unit;
  if (!prefixable.count(unit)) return significant(value, digits) + space + unit;
  // Prefixes from nano to mega; beyond them, scientific notation.
  static const char* prefixes[] = {"n", "µ", "m", "", "k", "M"};
  const double magnitude = std::abs(value);
  int k = static_cast<int>(std::floor(std::log10(magnitude) / 3)) + 3;
  if (k < 0 || k > 5) return significant(value, digits) + space + unit;
  double scaled = value / std::pow(1000.0, k - 3);
  // 999.7 µm rounds to "1e+03 µm" at 3 digits: move up a prefix first.
  if (std::abs(std::stod(significant(scaled, digits))) >= 1000 && k < 5) scaled /= 1000, ++k;
  return significant(scaled, digits) + " " + prefixes[k] + unit;
}

std::string in_units(double value, std::span<const Unit> ladder, int digits, double slack) {
  if (!std::isfinite(value) || ladder.empty()) return kNotFinite;
  for (std::size_t k = 0; k + 1 < ladder.size(); ++k)
    // The threshold 1/per is the unit's size exactly as a literal writes it (1/1e3 == 1e-3).
    if (value >= 1 / ladder[k].per * (1 - slack))
      return significant(ladder[k].per * value, digits) + " " + ladder[k].name;
  return significant(ladder.back().per * value, digits) + " " + ladder.back().name;
}

std::string percent(double fraction, PercentDigits digits) {
  const double p = 100 * fraction;
  if (!std::isfinite(p)) return kNotFinite;
  switch (digits) {
    case PercentDigits::two:
      if (std::abs(p) >= 10) return significant(std::round(p), 4) + " %";
      return significant(p, 2) + " %";
    case PercentDigits::tenths:
      return fixed(p, p >= 9.95 ? 0 : 1) + " %";
    case PercentDigits::three:
      return significant(p, 3) + " %";
    case PercentDigits::three_signed:
      return significant(p, 3, Sign::always) + " %";
  }
  return kNotFinite;
}

}  // namespace elbowsim
