// Numbers as a reader wants them on a report's first screen: three
// significant digits with an SI prefix that keeps the mantissa in [1, 1000)
// ("14.1 µm", "1.81 J", "54.2 mJ"), for the units the reports quote.
#pragma once

#include <string>

namespace elbowsim::report {

// "14.1 µm"; units outside m, J, W, A, V, N, s, N s, m/s are printed as
// "%.3g unit". Zero is "0 <unit>", a non-finite value "—".
std::string quantity(double value, const std::string& unit, int digits = 3);

// A share in percent with 2 significant
// digits ("100 %", "12 %", "0.54 %"); below 0.01 % as "5.4e-05 %".
std::string percent(double fraction);

}  // namespace elbowsim::report
