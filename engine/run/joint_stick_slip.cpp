#include "engine/run/joint_stick_slip.hpp"

#include <cmath>

#include "engine/dynamics/joint_friction.hpp"
#include "engine/run/derivative.hpp"
#include "engine/run/event_location.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

constexpr double kHoldTolerance = 1e-12;  // relative: a holding torque at breakaway still holds

std::size_t at(int j) { return static_cast<std::size_t>(j); }

// A joint without dry friction never sticks: it "slides" (with zero
// friction) at any speed, so locking it could only make rows dependent.
bool frictionless(const Model& model, int j) { return model.joint_friction[at(j)].breakaway == 0; }

// Breakaway margin of a stuck joint (>= 0 holds), or the signed speed along
// the slide of a sliding one (>= 0 goes on), at the state in data.x.
double event_value(const Model& model, Data& data, int j) {
  if (frictionless(model, j)) return 1.0;  // slides either way: no event
  const StateLayout s(model);
  if (data.joint_mode[at(j)] != 0) return data.joint_mode[at(j)] * data.x[s.qd() + j];
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  return model.joint_friction[at(j)].breakaway * (1 + kHoldTolerance) -
         std::abs(data.joint_friction_torque[j]);
}

}  // namespace

void decide_joint_modes(const Model& model, Data& data) {
  if (!model.effects.joint_friction) return;
  const StateLayout s(model);
  for (int j = 0; j < model.dof; ++j) {
    double& speed = data.x[s.qd() + j];
    if (frictionless(model, j)) {
      data.joint_mode[at(j)] = speed < 0 ? -1 : 1;
    } else if (std::abs(speed) > kJointStickSpeed) {
      data.joint_mode[at(j)] = speed > 0 ? 1 : -1;
    } else {
      data.joint_mode[at(j)] = 0;
      speed = 0.0;
    }
  }
  // Release the stuck joint that most exceeds its breakaway, until all hold
  // (each pass frees one joint: at most n passes). All sliding: nothing to check.
  if (!any_joint_stuck(model, data)) return;
  for (int pass = 0; pass < model.dof; ++pass) {
    nonstiff_rates(model, data, data.t, data.x, data.k1);
    int worst = -1;
    double excess = 0;
    for (int j = 0; j < model.dof; ++j) {
      if (data.joint_mode[at(j)] != 0) continue;
      const double hold = std::abs(data.joint_friction_torque[j]);
      const double limit = model.joint_friction[at(j)].breakaway * (1 + kHoldTolerance);
      if (hold > limit && hold - limit > excess) worst = j, excess = hold - limit;
    }
    if (worst < 0) return;
    // The holding torque points against the way the joint would go.
    data.joint_mode[at(worst)] = data.joint_friction_torque[worst] > 0 ? -1 : 1;
  }
}

void locate_joint_event(const Model& model, Data& data, double t0) {
  if (!model.effects.joint_friction) return;
  const double h = data.t - t0;
  int first = -1;
  double first_time = h;
  bool cut = false;  // data ends a shortened step (a previous joint's search)
  const StateLayout s(model);
  for (int j = 0; j < model.dof; ++j) {
    // A joint released from rest at this step's start: its speed may stay at
    // rounding level (a resting elbow can block it), where its sign means
    // nothing; whether it moved is decided at the next step's start. Locating
    // such "stops" would shrink the steps toward zero (Zeno).
    const bool released = data.joint_mode[at(j)] != 0 && data.x_start[s.qd() + j] == 0.0;
    if (released) continue;
    if (cut) redo_step(model, data, t0, h);  // back to the whole step
    cut = false;
    if (event_value(model, data, j) >= 0) continue;
    const double tau = locate_crossing(model, data, t0, h, model.contact.locate_tolerance,
                                       [j](const Model& m, Data& d) { return event_value(m, d, j); });
    cut = true;
    if (first < 0 || tau < first_time) first = j, first_time = tau;
  }
  if (first >= 0) redo_step(model, data, t0, first_time);
}

}  // namespace elbowsim
