#include "engine/run/step_log.hpp"

#include <algorithm>
#include <sstream>

#include "engine/contact/primitives.hpp"
#include "engine/model.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/adaptive.hpp"

namespace elbowsim {

const char* to_string(ContactEvent::Kind kind) {
  switch (kind) {
    case ContactEvent::Kind::landing: return "landing";
    case ContactEvent::Kind::release: return "release";
    case ContactEvent::Kind::stick: return "stick";
    case ContactEvent::Kind::slip: return "slip";
  }
  return "?";
}

std::string describe(const Model& model, const Warning& w) {
  std::ostringstream msg;
  switch (w.kind) {
    case Warning::Kind::dependent_rows:
      msg << "dependent contact constraints at t = " << w.t << " s: " << w.count
          << " rows of M* of the touching contact points ("
          << (model.has_coulomb_friction() ? "normal and sticking tangent rows" : "normal rows")
          << ") have rank " << w.rank << " (threshold " << model.contact.rank_tolerance
          << " relative); how the force splits between them is not determined: the minimum-norm "
             "split of the rows kept on is used (a contact may carry nothing)";
      if (model.contact.solver != ConstraintSolver::schur)
        msg << " (by the schur solver in those steps: contact.solver: " << to_string(model.contact.solver)
            << " has no answer there, M* being singular)";
      return msg.str();
    case Warning::Kind::stiff:
      msg << "the equations are stiff for dopri5 from t = " << significant(w.t, 4) << " s: for "
          << kStiffSteps << " accepted steps in a row its step (" << significant(w.step, 3)
          << " s) sat at the edge of its stability region (h |lambda| about "
          << significant(w.value, 3) << ", estimated from its last two stages; the edge is 3.3), so stability, not "
             "the tolerance, sets its step, and rejected steps cost it more (the motors' L/R "
             "is the usual cause); ros34pw2 is implicit in the motor electrics "
             "(simulation.integrator: ros34pw2)";
      return msg.str();
  }
  return "?";
}

namespace {

std::string part_name(const Model& model, const Failure& f) {
  switch (f.part) {
    case Failure::Part::joint: return "joint " + std::to_string(f.index);
    case Failure::Part::link: return "link " + std::to_string(f.index);
    case Failure::Part::elbow: return "elbow '" + model.elbows[f.index].name + "'";
    case Failure::Part::none: return "";
  }
  return "";
}

// A fixed step above ten times some motor's L/R.
bool unresolved_electrics(const Model& model) {
  if (is_adaptive(model.options.integrator) || !model.has_current_state() ||
      model.inductance.size() != model.dof)
    return false;
  for (int j = 0; j < model.dof; ++j)
    if (model.inductance[j] / model.resistance[j] < 0.1 * model.options.step) return true;
  return false;
}

// What to change: the step, when the estimate says it is beyond stability.
std::string step_advice(const Model& model, const Failure& f) {
  std::ostringstream s;
  const double h = model.options.step;
  // Motor electrics far faster than a fixed step (warnings.hpp,
  // stiffness_warnings): a smaller step is the expensive fix, the implicit
  // integrator the cheap one.
  if (unresolved_electrics(model)) {
    s << "; a motor's L/R is under a tenth of the step: use simulation.integrator: ros34pw2 "
         "(implicit in the motor electrics; or a smaller simulation.step, now "
      << h << " s)";
    return s.str();
  }
  if (f.stable_step > 0 && h > 0.8 * f.stable_step)
    s << "; the step " << h << " s is too large for the arm's fastest rate with the "
      << to_string(model.options.integrator) << " integrator (stable up to about "
      << f.stable_step << " s): try simulation.step <= " << 0.5 * f.stable_step << " s";
  else
    s << "; try a smaller simulation.step (now " << h << " s)"
      << (model.options.integrator == IntegratorKind::rk4 ? "" : " or the rk4 integrator");
  return s.str();
}

}  // namespace

std::string describe(const Model& model, const Failure& f) {
  std::ostringstream msg;
  switch (f.kind) {
    case Failure::Kind::none: return "";
    case Failure::Kind::painleve:
      msg << "Painleve paradox at t = " << f.t << " s: with "
          << to_string(model.contact.friction.law) << " friction mu = " << model.contact.friction.mu
          << " a sliding contact's normal force would accelerate it into the table; no "
             "non-negative contact force exists (lower contact.friction.mu or change the pose)";
      return msg.str();
    case Failure::Kind::no_contact_solution:
      msg << (model.effects.friction ? "Painleve paradox" : "contact failure") << " at t = " << f.t
          << " s"
          << ": no set of resting contacts has non-negative forces and accelerations"
          << (model.has_coulomb_friction() ? " with their forces inside the friction cones" : "");
      return msg.str();
    case Failure::Kind::diverged:
      msg << "simulation diverged at t = " << f.t << " s (step " << f.step
          << "): the state became non-finite or exceeded 1e12" << step_advice(model, f);
      return msg.str();
    case Failure::Kind::current_bound:
      msg << "simulation diverged at t = " << f.t << " s: motor " << f.index
          << "'s current reached " << f.value << " A"
          << " at t = " << f.t << " s, beyond " << f.limit << " A"
          << " (validity.current_factor x its stall current)" << step_advice(model, f);
      return msg.str();
    case Failure::Kind::speed_bound:
      msg << "simulation diverged at t = " << f.t << " s: " << part_name(model, f) << " turned at "
          << f.value << " rad/s"
          << " at t = " << f.t << " s, beyond " << f.limit << " rad/s"
          << " (validity.speed_factor x the motor's free-running speed)" << step_advice(model, f);
      return msg.str();
    case Failure::Kind::penetration: {
      const Pad* pad = f.part == Failure::Part::elbow && model.effects.contact
                           ? &model.elbows[static_cast<std::size_t>(f.index)].pad
                           : nullptr;
      if (pad && !pad->on()) pad = nullptr;
      msg << "invalid run: " << part_name(model, f) << " is " << f.value << " m"
          << " inside table box " << f.box << " at t = " << f.t << " s";
      if (pad) {
        msg << " (its pad's thickness " << pad->thickness << " m + contact.penetration_tolerance "
            << model.contact.penetration_tolerance << " m): the pad bottomed out: the arm presses "
               "it harder than its stiffness (" << pad->stiffness << " N/m) can carry within its "
               "thickness; give a stiffer or thicker pad";
        return msg.str();
      }
      msg << " (contact.penetration_tolerance " << f.limit << " m): ";
      if (!model.effects.contact)
        msg << "effects.contact is false, so the physics ignores the table and nothing holds the "
               "arm up; turn contact on, or keep the arm above the table";
      else if (model.contact.events == EventTiming::step)
        msg << "with contact.events: step a landing is found at the end of the step it happens "
               "in, up to (approach speed x step) deep; use contact.events: locate or a smaller "
               "simulation.step (now " << model.options.step << " s)";
      else if (f.t <= model.options.step)
        msg << "in the first step, so the pose the run starts from puts it there, not the "
               "integration: check initial.q and, with a task, where it rests the elbows (the "
               "plan's start pose)";
      else if (f.part == Failure::Part::link &&
               model.links[static_cast<std::size_t>(f.index)].collision.kind == LinkCollision::Kind::none)
        msg << "the link has no solid (collision: none), so the table does not hold it; give it "
               "one or keep it above the table";
      else
        msg << "its contact rows did not hold it: the integration is not accurate enough to keep "
               "the contact" << step_advice(model, f);
      return msg.str();
    }
    case Failure::Kind::energy_balance:
      msg << "invalid run: the energy balance is off by " << f.value << " J at "
          << "t = " << f.t << " s, " << 100 * f.value / std::max(f.flow, 1e-300) << " % of the "
          << f.flow << " J that flowed or was held (limit " << 100 * model.validity.energy_residual
          << " %, validity.energy_residual)";
      if (!std::isnan(f.since)) msg << "; beyond the limit since t = " << f.since << " s";
      msg << ": the integration is not accurate" << step_advice(model, f);
      return msg.str();
    case Failure::Kind::too_many_contacts:
      msg << "contact failure at t = " << f.t << " s: " << f.value
          << " contact points touch the table at once, more than the " << f.limit
          << " rows the run made room for (contact.max_rows)";
      return msg.str();
    case Failure::Kind::stalled:
      msg << "the run stalled at t = " << f.t << " s: its last " << f.limit << " steps advanced "
          << f.value << " s in all, under "
          << (is_adaptive(model.options.integrator) ? "0.01" : "1")
          << " % of simulation.step each on average; located events keep cutting the steps ";
      if (f.slot >= 0 && f.slot_events > 0)
        msg << "(" << slot_name(model, contact_geometry(model), f.slot) << ": " << f.slot_events
            << " landings, releases, sticks or slips in those steps: grazing or chattering on the "
               "table)";
      else if (f.slot >= 0)
        msg << "(at " << slot_name(model, contact_geometry(model), f.slot)
            << ", where the last event was located: grazing the table)";
      else
        msg << "(a point grazing or chattering on the table?)";
      msg << ": try contact.events: step, or a larger contact.locate_tolerance";
      return msg.str();
    case Failure::Kind::step_underflow:
      msg << "the " << to_string(model.options.integrator) << " integrator could not go on at "
          << "t = " << f.t << " s: its error control cut the step to " << f.value << " s"
          << " without meeting simulation.rtol " << model.options.rtol << " / atol "
          << model.options.atol
          << " (the solution blows up, or the equations jump where no event stops the step)";
      return msg.str();
    case Failure::Kind::interrupted:
      msg << "interrupted at t = " << f.t << " s (a signal asked the run to stop): "
          << "what it recorded up to then is kept";
      return msg.str();
    case Failure::Kind::elbow_not_resting:
      msg << "invalid run: " << part_name(model, f) << " rested " << 100 * f.value
          << " % of the run; the task keeps it on the table throughout (validity.rest_share "
          << 100 * f.limit << " %): the table did not carry it as planned (is the elbow over a "
             "box? does the controller lift it?)";
      return msg.str();
  }
  return "?";
}

namespace {

// When the failure began: an energy balance's residual when it first passed
// its bound, anything else when it was found.
double began(const Failure& f) { return std::isnan(f.since) ? f.t : f.since; }

}  // namespace

std::string describe(const Model& model, const Failure& f,
                     const std::vector<FailureCause>& causes) {
  std::string own = describe(model, f);
  if (!f) return own;
  for (const FailureCause& c : causes) {
    const bool explains =
        std::find(c.explains.begin(), c.explains.end(), f.kind) != c.explains.end();
    if (!explains || c.t > began(f)) continue;
    // "invalid run: the energy balance is off ..." reads on after the cause without its label.
    const std::string label = "invalid run: ";
    if (own.starts_with(label)) own.erase(0, label.size());
    return c.clause + "; likely as a result, " + own;
  }
  return own;
}

}  // namespace elbowsim
