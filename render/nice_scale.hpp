// Round numbers for what a frame states about its scale (the inset's scale
// bar, the force arrows' newtons per centimetre): the 1-2-5 series.
#pragma once

#include <string>

namespace elbowsim {

// The smallest number of the series ..., 0.1, 0.2, 0.5, 1, 2, 5, 10, ... that
// is >= x (x > 0).
double nice_ceil(double x);
// The largest number of the series that is <= x (x > 0).
double nice_floor(double x);
// A length in the unit that makes it a small whole number: "500 µm", "2 mm",
// "1 cm", "20 cm", "1 m" (UTF-8).
std::string length_label(double metres);

}  // namespace elbowsim
