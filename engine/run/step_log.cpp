#include "engine/run/step_log.hpp"

#include <sstream>

#include "engine/model.hpp"

namespace elbowsim {

namespace {

std::string at_time(double t) {
  std::ostringstream s;
  s << "t = " << t << " s";
  return s.str();
}

}  // namespace

std::string describe(const Model& model, const Warning& w) {
  std::ostringstream msg;
  switch (w.kind) {
    case Warning::Kind::dependent_rows:
      return "dependent elbow constraints at " + at_time(w.t) + ": " + std::to_string(w.count) +
             " touching elbows give rows of M* of rank " + std::to_string(w.rank) +
             " (threshold " + std::to_string(model.contact.rank_tolerance) +
             " relative); minimum-norm elbow forces are used";
    case Warning::Kind::link_in_table:
      msg << "link " << w.index << " passes through table box " << w.box << " at " << at_time(w.t)
          << " (depth " << w.value << " m); only elbow spheres have contact forces";
      return msg.str();
  }
  return "?";
}

std::string describe(const Model& model, const Failure& f) {
  std::ostringstream msg;
  switch (f.kind) {
    case Failure::Kind::none: return "";
    case Failure::Kind::painleve:
      return "Painleve paradox at " + at_time(f.t) + ": with friction mu = " +
             std::to_string(model.contact.friction) +
             " a normal force on a resting elbow would accelerate it into the table; no "
             "non-negative elbow force exists (lower contact.friction or change the pose)";
    case Failure::Kind::no_contact_solution:
      return std::string(model.effects.friction ? "Painleve paradox" : "contact failure") + " at " +
             at_time(f.t) + ": no set of resting elbows has non-negative forces and accelerations";
    case Failure::Kind::diverged:
      msg << "simulation diverged at t = " << f.t << " s (step " << f.step
          << "): the state became non-finite or exceeded 1e12; try a smaller simulation.step"
          << " (now " << model.options.step << " s) or the rk4 integrator";
      return msg.str();
  }
  return "?";
}

}  // namespace elbowsim
