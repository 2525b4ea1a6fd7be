// Numbers as text: the one place elbowsim turns a number into characters for its
// messages, warnings, reports, labels and the values it writes back for a program to read.
// Each function states its format; where printf's conversion is the rule it is named.
//
// significant, fixed and round_trip write what printf writes (NaN as "nan", infinity as
// "inf"), for messages that must show a bad input as it was given; quantity, in_units and
// percent are for a reader and write "—" for a value that is not finite.
//
// It sits in the recording, the lowest floor the engine, the renderer, the report and the
// application may all include (tests/layers.txt).
#pragma once

#include <initializer_list>
#include <span>
#include <string>

namespace elbowsim {

enum class Sign { if_negative, always };

// `digits` significant digits, printf's %.*g: trailing zeros dropped, exponent form below
// 1e-4 and from 10^digits ("0.00125", "12.5", "1.25e+06"). 6 digits is printf's %g and what
// std::ostream writes by default. Sign::always writes "+" before a positive value ("+12.5",
// printf's %+.*g).
std::string significant(double x, int digits = 6, Sign sign = Sign::if_negative);

// `decimals` digits after the point (up to 80), printf's %.*f ("3.14", "12.0", "-0.50").
std::string fixed(double x, int decimals);

// 17 significant digits, printf's %.17g: reads back as the same double. For values written
// for a program to read (overrides, CSV files), never for a reader.
std::string round_trip(double x);

// Numbers separated by ", ", each with `digits` significant digits: "0.1, -0.2, 9.81".
std::string listed(std::initializer_list<double> values, int digits = 6);

// A count with its noun, singular for one: "1 item", "3 items", "1 entry", "2 entries".
// `plural` defaults to `singular` + "s".
std::string counted(long long n, const std::string& singular, const std::string& plural = "");

// A quantity with an SI prefix that keeps the mantissa in [1, 1000), `digits` significant
// digits: "14.1 µm", "1.81 J", "54.2 mJ", "3 kW" (UTF-8 µ). The prefixes run from n to M;
// beyond them, and for a unit other than m, J, W, A, V, N, s, N s and m/s, the value is
// written unprefixed ("2.5e-10 m", "12.5 rad"). Zero is "0 <unit>", a value that is not
// finite "—". With an empty unit, the number alone.
std::string quantity(double value, const std::string& unit, int digits = 3);

// A unit of a ladder of units (in_units): its name and how many of it make one of the value's
// unit (1000 for "mm" of metres).
struct Unit {
  const char* name;
  double per;
};

// `value` in the first unit of `ladder` (largest first) that it is not below (not below
// 1 - slack of that unit), else in the last; `digits` significant digits. With the ladder
// {{"m", 1}, {"mm", 1e3}, {"um", 1e6}}: 0.0123 is "12.3 mm", 2e-5 is "20 um", 3 is "3 m".
// For a fixed choice of units (ASCII ones, or a centimetre), where quantity() would pick an
// SI prefix. "—" when `value` is not finite.
std::string in_units(double value, std::span<const Unit> ladder, int digits = 3, double slack = 0);

// How percent() rounds.
enum class PercentDigits {
  two,           // whole percents from 10 %, 2 significant digits below: "100 %", "12 %",
                 // "5.4 %", "0.54 %", "5.4e-05 %"
  tenths,        // whole percents from 9.95 %, one decimal below: "38 %", "5.4 %", "0.5 %"
  three,         // 3 significant digits: "100 %", "12.3 %", "0.543 %"
  three_signed,  // 3 significant digits with the sign: "+12.3 %", "-0.543 %", "+0 %"
};

// A fraction as a percentage: percent(0.054) is "5.4 %". "—" when not finite.
std::string percent(double fraction, PercentDigits digits = PercentDigits::two);

}  // namespace elbowsim
