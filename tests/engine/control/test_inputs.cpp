// engine/control/inputs.cpp: the open-loop input profiles at chosen times.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "engine/control/inputs.hpp"

using namespace elbowsim;

namespace {

InputProfile listed(InputProfile::Kind kind) {
  InputProfile p;
  p.kind = kind;
  p.times = {0.5, 1.0, 2.0};
  p.values = {1.0, 3.0, -1.0};
  return p;
}

}  // namespace

TEST_CASE("inputs: zero and constant") {
  InputProfile p;
  CHECK(p.at(0.0) == 0.0);  // the default is zero
  CHECK(p.at(3.5) == 0.0);
  p.kind = InputProfile::Kind::constant;
  p.value = 2.5;
  for (double t : {-1.0, 0.0, 0.7, 100.0}) CHECK(p.at(t) == 2.5);
}

TEST_CASE("inputs: sine = offset + amplitude sin(2 pi f t + phase)") {
  InputProfile p;
  p.kind = InputProfile::Kind::sine;
  p.offset = 1.0, p.amplitude = 3.0, p.frequency = 2.0, p.phase = 0.0;
  // At t = 0, a quarter, a half and three quarters of a period (0.5 s): rounding of pi, 1e-15.
  CHECK(p.at(0.0) == 1.0);
  CHECK(p.at(0.125) == doctest::Approx(4.0).epsilon(1e-15));
  CHECK(std::abs(p.at(0.25) - 1.0) < 1e-15);
  CHECK(p.at(0.375) == doctest::Approx(-2.0).epsilon(1e-15));
  p.phase = std::numbers::pi / 2;  // a cosine
  CHECK(p.at(0.0) == doctest::Approx(4.0).epsilon(1e-15));
  CHECK(p.at(0.1) == doctest::Approx(1.0 + 3.0 * std::cos(2 * std::numbers::pi * 0.2)).epsilon(1e-15));
}

TEST_CASE("inputs: table interpolates linearly and holds its end values outside") {
  const InputProfile p = listed(InputProfile::Kind::table);
  CHECK(p.at(0.0) == 1.0);   // before the first time: the first value
  CHECK(p.at(0.5) == 1.0);   // on the points
  CHECK(p.at(1.0) == 3.0);
  CHECK(p.at(2.0) == -1.0);
  CHECK(p.at(0.75) == 2.0);  // half way (exact in binary)
  CHECK(p.at(1.5) == 1.0);
  CHECK(p.at(1.25) == 2.0);
  CHECK(p.at(0.6) == doctest::Approx(1.4).epsilon(1e-15));
  CHECK(p.at(5.0) == -1.0);  // after the last: the last value
}

TEST_CASE("inputs: steps hold each value from its time on, zero before the first") {
  const InputProfile p = listed(InputProfile::Kind::steps);
  CHECK(p.at(0.0) == 0.0);
  CHECK(p.at(0.4999) == 0.0);
  CHECK(p.at(0.5) == 1.0);   // from its time on
  CHECK(p.at(0.99) == 1.0);
  CHECK(p.at(1.0) == 3.0);
  CHECK(p.at(1.7) == 3.0);
  CHECK(p.at(2.0) == -1.0);
  CHECK(p.at(9.0) == -1.0);
}
