// engine/model.cpp: finalize(), the backstop checks for models built in code (errors name
// the member), the derived motor constants, a fresh id per call; the effects' names.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

std::string finalize_error(Model m) {
  try {
    finalize(m);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("finalize rejects impossible bodies, bad axes and inconsistent contact scenes") {
  const Model good = planar_arm({{0.4, 1.0, 0.2, 0.02}, {0.3, 0.8, 0.15, 0.01}});
  CHECK(finalize_error(good).empty());

  Model m = good;
  m.links[1].inertia = Eigen::Vector3d(0.01, 0.01, 0.05).asDiagonal();  // 0.01 + 0.01 < 0.05
  CHECK(finalize_error(m).find("links[1].inertia violates the triangle inequality") !=
        std::string::npos);

  m = good;
  m.joints[0].axis.setZero();
  CHECK(finalize_error(m).find("joints[0].axis") != std::string::npos);

  m = good;
  m.elbows = {Elbow{"e", 5, Eigen::Vector3d::Zero(), 0.03}};
  CHECK(finalize_error(m).find("elbows[0].link out of range") != std::string::npos);

  m = good;
  m.effects.friction = true;
  CHECK(finalize_error(m).find("friction needs contact") != std::string::npos);

  m = good;
  m.effects.contact = true;
  CHECK(finalize_error(m).find("contact needs elbows and a table") != std::string::npos);
}
