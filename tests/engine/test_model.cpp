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
  CHECK(finalize_error(m).find("contact needs a table") != std::string::npos);
}

TEST_CASE("finalize: each invalid member is named in the error") {
  Model good = planar_arm({{0.4, 1.0, 0.2, 0.02}, {0.3, 0.8, 0.15, 0.01}});
  good.effects.motor = MotorModel::full;
  good.motors = {small_servo(), small_servo()};
  good.elbows = {Elbow{"e", 0, Eigen::Vector3d(0.4, 0, 0), 0.03}};
  good.table = {TableBox{}};
  REQUIRE(finalize_error(good).empty());
  struct Case {
    const char* member;  // what the message must name
    void (*spoil)(Model&);
  };
  const Case cases[] = {
      {"dof must be > 0", [](Model& m) { m.dof = 0; }},
      {"joints/links must have dof entries", [](Model& m) { m.links.pop_back(); }},
      {"motors must have dof entries", [](Model& m) { m.motors.pop_back(); }},
      {"damping must be empty or have dof entries", [](Model& m) { m.damping = Eigen::Vector3d(1, 1, 1); }},
      {"inputs must be empty or have dof entries", [](Model& m) { m.inputs.joints.resize(1); }},
      {"hand_link out of range", [](Model& m) { m.hand_link = 2; }},
      {"step and duration must be > 0", [](Model& m) { m.options.step = 0; }},
      {"links[1].mass must be > 0", [](Model& m) { m.links[1].mass = -1; }},
      {"links[0].inertia must be symmetric positive definite",
       [](Model& m) { m.links[0].inertia(0, 1) = 0.5; }},
      {"links[1].radius must be > 0", [](Model& m) { m.links[1].radius = 0; }},
      {"motors[0].resistance must be > 0", [](Model& m) { m.motors[0].resistance = 0; }},
      {"motors[1].inductance must be > 0 for the full motor model", [](Model& m) { m.motors[1].inductance = 0; }},
      {"motors[1].gear_ratio must be > 0", [](Model& m) { m.motors[1].gear_ratio = -2; }},
      {"motors[0].voltage_limit must be > 0", [](Model& m) { m.motors[0].voltage_limit = 0; }},
      {"motors[1]: rotor_inertia and gear_friction must be >= 0", [](Model& m) { m.motors[1].rotor_inertia = -1; }},
      {"elbows[0].radius must be > 0", [](Model& m) { m.elbows[0].radius = 0; }},
      {"table[0].size must be > 0", [](Model& m) { m.table[0].size.y() = 0; }},
      {"contact.restitution must be in [0, 1]", [](Model& m) { m.contact.restitution = 1.5; }},
      {"contact.friction.mu must be >= 0", [](Model& m) { m.contact.friction.mu = -0.1; }},
      {"contact.friction velocities must be > 0", [](Model& m) { m.contact.friction.stick_velocity = 0; }},
      {"contact.rank_tolerance must be in (0, 1)", [](Model& m) { m.contact.rank_tolerance = 0; }},
      {"contact tolerances must be > 0", [](Model& m) { m.contact.locate_tolerance = 0; }},
      {"hand_load.mass must be >= 0", [](Model& m) { m.hand_load.mass = -1; }},
  };
  for (const Case& c : cases) {
    Model m = good;
    c.spoil(m);
    const std::string error = finalize_error(m);
    CAPTURE(error);
    CHECK(error.find(std::string("invalid model: ") + c.member) != std::string::npos);
  }
  // A quasi-static motor needs no inductance.
  Model quasi = good;
  quasi.effects.motor = MotorModel::quasi_static;
  quasi.motors[1].inductance = 0;
  CHECK(finalize_error(quasi).empty());
}

TEST_CASE("finalize: a fresh id every time; Data remembers the one it was made for") {
  Model m = planar_arm({{0.4, 1.0, 0.2, 0.02}});
  const long first = m.id;
  finalize(m);
  const long second = m.id;
  CHECK(second != first);
  CHECK(second > first);
  const Model copy = m;  // a copy is the same model until it is finalized again
  CHECK(copy.id == second);
  Model other = m;
  finalize(other);
  CHECK(other.id != second);
  CHECK(other.id != m.id);
}

TEST_CASE("finalize: reflected motor constants Km = K k, Jm = Im k^2, D + Dm, and effects off") {
  Model m = planar_arm({{0.4, 1.0, 0.2, 0.02}, {0.3, 0.8, 0.15, 0.01}});
  m.effects.motor = MotorModel::full;
  m.effects.damping = true;
  m.motors = {small_servo(), small_servo()};  // K 0.03, k 50, Im 5e-7, dm 1e-6, R 2, L 0.5e-3
  m.motors[1].gear_ratio = 100;
  m.damping = Eigen::Vector2d(0.1, 0.2);
  finalize(m);
  CHECK(m.km == Eigen::Vector2d(0.03 * 50, 0.03 * 100));
  CHECK(m.armature == Eigen::Vector2d(5e-7 * 50 * 50, 5e-7 * 100 * 100));
  CHECK(m.viscous == Eigen::Vector2d(0.1 + 1e-6 * 50 * 50, 0.2 + 1e-6 * 100 * 100));
  CHECK(m.resistance == Eigen::Vector2d(2, 2));
  CHECK(m.inductance == Eigen::Vector2d(0.5e-3, 0.5e-3));
  CHECK(m.voltage_limit == Eigen::Vector2d(24, 24));
  m.effects.rotor_inertia = false;
  m.effects.damping = false;
  finalize(m);
  CHECK(m.armature.isZero());
  CHECK(m.viscous.isZero());
  m.effects.motor = MotorModel::none;
  m.effects.damping = true;
  finalize(m);
  CHECK(m.km.isZero());
  CHECK(m.viscous == Eigen::Vector2d(0.1, 0.2));  // no motor: D alone
}

TEST_CASE("finalize: a hand load is merged into the hand link once (parallel axes), however often") {
  // A 0.5 kg point at the tip (0.4, 0, 0) of a 1 kg link with its com at 0.2 m: the com
  // moves to (1 * 0.2 + 0.5 * 0.4) / 1.5, the inertia about it grows by the parallel-axis
  // terms of both masses about the new com (about y: m d^2).
  Model m = planar_arm({{0.4, 1.0, 0.2, 0.02}});
  m.hand_load.mass = 0.5;
  finalize(m);
  const double com = (1.0 * 0.2 + 0.5 * 0.4) / 1.5;
  const double Iyy = 0.02 + 1.0 * (0.2 - com) * (0.2 - com) + 0.5 * (0.4 - com) * (0.4 - com);
  for (int call = 0; call < 3; ++call) {
    CAPTURE(call);
    CHECK(m.links[0].mass == 1.5);
    CHECK(elbowsim::testing::approx(m.links[0].com, Eigen::Vector3d(com, 0, 0), 1e-15));
    CHECK(elbowsim::testing::approx(m.links[0].inertia(1, 1), Iyy, 1e-15));
    finalize(m);
  }
}

TEST_CASE("active_effects names the effects that are on; to_string names every enum value") {
  Model m = planar_arm({{0.4, 1.0, 0.2, 0.02}});
  m.effects.motor = MotorModel::quasi_static;
  m.motors = {small_servo()};
  m.effects.damping = true;
  m.elbows = {Elbow{"e", 0, Eigen::Vector3d(0.4, 0, 0), 0.03}};
  m.table = {TableBox{}};
  m.effects.contact = true;
  m.effects.friction = true;
  m.effects.stabilization = Stabilization::projection;
  finalize(m);
  CHECK(m.active_effects() == std::vector<std::string>{"gravity", "damping", "motor:quasi_static",
                                                       "rotor_inertia", "contact", "friction",
                                                       "impacts", "stabilization:projection"});
  CHECK(std::string(to_string(IntegratorKind::semi_implicit_euler)) == "semi_implicit_euler");
  CHECK(std::string(to_string(DynamicsMethod::walker_orin)) == "walker_orin");
  CHECK(std::string(to_string(EventTiming::locate)) == "locate");
  CHECK(std::string(to_string(Stabilization::baumgarte)) == "baumgarte");
  CHECK(std::string(to_string(MotorModel::full)) == "full");
}
