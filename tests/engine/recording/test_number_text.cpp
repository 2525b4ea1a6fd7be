// engine/recording/number_text.cpp: each function writes exactly the format its header
// states (the strings below are what the functions it replaced wrote), round_trip reads
// back bit for bit, and what is meant for a reader shows "—" for a value that is not finite.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "engine/recording/number_text.hpp"

using namespace elbowsim;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::nan("");

std::string streamed(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

TEST_CASE("number_text: significant digits are printf's %.*g, 6 by default as std::ostream's") {
  CHECK(significant(0.00125, 3) == "0.00125");
  CHECK(significant(0.000125, 3) == "0.000125");
  CHECK(significant(0.0000125, 3) == "1.25e-05");  // exponent form below 1e-4
  CHECK(significant(12.5, 3) == "12.5");
  CHECK(significant(1250000, 3) == "1.25e+06");  // and from 10^digits
  CHECK(significant(12.0, 3) == "12");           // no trailing zeros
  CHECK(significant(1.0 / 3) == "0.333333");
  CHECK(significant(-8.333333333e-6) == "-8.33333e-06");
  CHECK(significant(12.5, 3, Sign::always) == "+12.5");
  CHECK(significant(-12.5, 3, Sign::always) == "-12.5");
  CHECK(significant(0.0, 3, Sign::always) == "+0");
  // A bad input shown as it was given, in the scenario loader's messages.
  CHECK(significant(kNaN) == "nan");
  CHECK(significant(kInf) == "inf");
  CHECK(significant(-kInf) == "-inf");
  // The messages written with << (engine/run/step_log.cpp) and with significant() agree.
  for (double x : {0.0, -0.0, 1e-3, 0.1, 1.0 / 3, 2.5e-7, 123456.0, 1234567.0, -9.81, 1e300})
    CHECK(significant(x) == streamed(x));
}

TEST_CASE("number_text: fixed decimals are printf's %.*f, and never cut") {
  CHECK(fixed(3.14159, 2) == "3.14");
  CHECK(fixed(12, 1) == "12.0");
  CHECK(fixed(-0.5, 2) == "-0.50");
  CHECK(fixed(2.5, 0) == "2");  // printf rounds an exact tie to even
  CHECK(fixed(3.5, 0) == "4");
  CHECK(fixed(1234.5678, 0) == "1235");
  // The largest doubles have 309 digits before the point.
  CHECK(fixed(DBL_MAX, 3).size() == 309 + 4);
  CHECK(fixed(-DBL_MAX, 0).size() == 310);
}

TEST_CASE("number_text: round_trip reads back as the same double") {
  CHECK(round_trip(0.1) == "0.10000000000000001");
  CHECK(round_trip(0.5) == "0.5");
  std::mt19937_64 bits(20240607);
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const std::uint64_t b = bits();
    double x;
    std::memcpy(&x, &b, sizeof x);
    if (!std::isfinite(x)) continue;
    const double back = std::strtod(round_trip(x).c_str(), nullptr);
    if (std::memcmp(&back, &x, sizeof x) != 0) FAIL_CHECK(round_trip(x) << " read back differs");
    ++checked;
  }
  for (double x : {DBL_MIN, DBL_MAX, DBL_TRUE_MIN, 1.0 / 3, 2.0 / 3, 1e-3, 299792458.0})
    CHECK(std::strtod(round_trip(x).c_str(), nullptr) == x);
  CHECK(checked > 19000);
}

TEST_CASE("number_text: listed numbers and counted nouns") {
  CHECK(listed({0.1, -0.2, 9.81}) == "0.1, -0.2, 9.81");
  CHECK(listed({1.23456, 0}, 3) == "1.23, 0");
  CHECK(listed({}) == "");
  CHECK(counted(1, "item") == "1 item");
  CHECK(counted(3, "item") == "3 items");
  CHECK(counted(0, "run") == "0 runs");
  CHECK(counted(1, "entry", "entries") == "1 entry");
  CHECK(counted(2, "entry", "entries") == "2 entries");
  CHECK(counted(2, "pair has", "pairs have") == "2 pairs have");
}

TEST_CASE("number_text: quantity keeps the mantissa in [1, 1000) with an SI prefix") {
  CHECK(quantity(14.1e-6, "m") == "14.1 µm");
  CHECK(quantity(1.8149, "J") == "1.81 J");
  CHECK(quantity(0.05423, "J") == "54.2 mJ");
  CHECK(quantity(-0.05423, "J") == "-54.2 mJ");
  CHECK(quantity(3000, "W") == "3 kW");
  CHECK(quantity(2.5e-3, "N s") == "2.5 mN s");
  CHECK(quantity(1.23456e-3, "s", 5) == "1.2346 ms");
  // 999.7 µm would be "1e+03 µm" at 3 digits: it moves up a prefix.
  CHECK(quantity(999.7e-6, "m") == "1 mm");
  CHECK(quantity(999.4e-6, "m") == "999 µm");
  // Beyond nano and mega, and units without prefixes: unprefixed.
  CHECK(quantity(2.5e-10, "m") == "2.5e-10 m");
  CHECK(quantity(2.5e9, "W") == "2.5e+09 W");
  CHECK(quantity(12.5, "rad") == "12.5 rad");
  CHECK(quantity(0.00125, "kg") == "0.00125 kg");
  CHECK(quantity(0.123, "") == "0.123");
  CHECK(quantity(0, "J") == "0 J");
  CHECK(quantity(0, "") == "0");
  CHECK(quantity(kNaN, "J") == "—");
  CHECK(quantity(kInf, "m") == "—");
}

TEST_CASE("number_text: in_units takes the first unit of the ladder the value reaches") {
  // The warnings' ladder (engine/run/warnings.cpp), ASCII.
  const Unit warnings[] = {{"m", 1}, {"mm", 1e3}, {"um", 1e6}};
  CHECK(in_units(0.0123, warnings) == "12.3 mm");
  CHECK(in_units(2e-5, warnings) == "20 um");
  CHECK(in_units(3, warnings) == "3 m");
  CHECK(in_units(1e-3, warnings) == "1 mm");  // a unit's size is in it
  CHECK(in_units(1, warnings) == "1 m");
  CHECK(in_units(0, warnings) == "0 um");  // below every unit: the last
  CHECK(in_units(2e-8, warnings) == "0.02 um");
  CHECK(in_units(12.3e-3, warnings, 2) == "12 mm");
  // The scale bar's ladder (render/nice_scale.cpp): a slack lets a rounded 1 cm be 1 cm.
  const Unit bar[] = {{"m", 1}, {"cm", 100}, {"mm", 1e3}, {"µm", 1e6}, {"nm", 1e9}};
  CHECK(in_units(0.2, bar, 3, 1e-9) == "20 cm");
  CHECK(in_units(0.01 * (1 - 1e-10), bar, 3, 1e-9) == "1 cm");
  CHECK(in_units(0.01 * (1 - 1e-10), bar, 3, 0) == "10 mm");
  CHECK(in_units(5e-10, bar, 3, 1e-9) == "0.5 nm");
  CHECK(in_units(kNaN, warnings) == "—");
  CHECK(in_units(kInf, bar, 3, 1e-9) == "—");
}

TEST_CASE("number_text: percent takes a fraction; its four roundings") {
  // two: the reports'.
  CHECK(percent(1) == "100 %");
  CHECK(percent(0.123) == "12 %");
  CHECK(percent(0.0996) == "10 %");
  CHECK(percent(0.054) == "5.4 %");
  CHECK(percent(0.0054) == "0.54 %");
  CHECK(percent(5.4e-7) == "5.4e-05 %");
  CHECK(percent(0) == "0 %");
  CHECK(percent(-0.123) == "-12 %");
  // tenths: the comparison's verdict.
  CHECK(percent(0.384, PercentDigits::tenths) == "38 %");
  CHECK(percent(0.0996, PercentDigits::tenths) == "10 %");  // not "10.0 %"
  CHECK(percent(0.0994, PercentDigits::tenths) == "9.9 %");
  CHECK(percent(0.054, PercentDigits::tenths) == "5.4 %");
  CHECK(percent(0.0054, PercentDigits::tenths) == "0.5 %");
  // three: the warnings'; three_signed: the comparison table's change.
  CHECK(percent(0.123456, PercentDigits::three) == "12.3 %");
  CHECK(percent(1, PercentDigits::three) == "100 %");
  CHECK(percent(0.00543, PercentDigits::three) == "0.543 %");
  CHECK(percent(0.123, PercentDigits::three_signed) == "+12.3 %");
  CHECK(percent(-0.00543, PercentDigits::three_signed) == "-0.543 %");
  CHECK(percent(0, PercentDigits::three_signed) == "+0 %");
  for (PercentDigits d : {PercentDigits::two, PercentDigits::tenths, PercentDigits::three,
                          PercentDigits::three_signed}) {
    CHECK(percent(kNaN, d) == "—");
    CHECK(percent(-kInf, d) == "—");
  }
}
