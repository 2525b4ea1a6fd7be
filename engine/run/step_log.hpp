// What a step reports besides the new state: contact events and warnings of
// the last step (data.log, emptied when a step starts; simulate() collects
// them), and why a run must stop (data.failure). Plain records with reserved
// capacity, so a step allocates nothing; messages are written from them
// afterwards (describe()).
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace elbowsim {

struct Model;

// A row of M* switched on (landing) or off (release), or a resting slot's
// friction mode changed (stick: its slip stopped; slip: its force left the cone).
struct ContactEvent {
  enum class Kind { landing, release, stick, slip };
  double t = 0;         // [s]
  int slot = -1;        // the contact slot (contact/primitives.hpp; slot k < elbows x boxes: an elbow)
  Kind kind = Kind::landing;
  double speed = 0;     // [m/s] approach speed at landing (> 0); slip speed left at stick; else 0
  double impulse = 0;   // [N s] landing impulse
  double energy_lost = 0;  // [J] kinetic energy this elbow's impulse took
};

struct Warning {
  enum class Kind {
    dependent_rows,  // the touching slots' rows of M* are dependent: `count` rows of rank `rank`
    stiff,           // dopri5's steps held at its stability edge (`value`: h |lambda|, `step`: h)
  };
  Kind kind = Kind::dependent_rows;
  double t = 0;      // [s]
  int count = 0;     // rows of the touching slots (dependent_rows)
  int rank = 0;      // rank of their rows (dependent_rows)
  double value = 0;  // h |lambda| estimated (stiff)
  double step = 0;   // [s] the step it was estimated on (stiff)
};

// Why a run must stop, or why its numbers cannot be trusted (run/validity.hpp
// has the checks): the check, when, the quantity against its bound.
struct Failure {
  enum class Kind {
    none,
    painleve,             // friction makes a resting elbow's normal force push it into the table
    no_contact_solution,  // no active set has non-negative forces and accelerations
    diverged,             // the state became non-finite or exceeded 1e12
    current_bound,        // a motor current beyond validity.current_factor x its stall current
    speed_bound,          // a joint speed beyond validity.speed_factor x its free-running speed
    penetration,          // a link or an elbow deeper in a table box than contact.penetration_tolerance
    energy_balance,       // the energy account off by more than validity.energy_residual of the flow
    elbow_not_resting,    // an elbow the task rests on the table rested less than validity.rest_share
    too_many_contacts,    // more slots touch at once than contact.max_rows
    interrupted,          // stopped from outside (RunOptions::stop: SIGINT, SIGTERM)
    stalled,              // time no longer advances: kStallSteps steps covered under 1 % of theirs
    step_underflow,       // an adaptive step fell below rounding of t, or its error stayed non-finite
  };
  enum class Part { none, joint, link, elbow };
  Kind kind = Kind::none;
  double t = 0;          // [s]
  long step = 0;         // steps taken when it happened
  Part part = Part::none;
  int index = -1;        // the joint, link or elbow
  int box = -1;          // the table box (penetration)
  double value = 0;      // the quantity checked (A, rad/s, m, J, share)
  double limit = 0;      // its bound, same unit
  double flow = 0;       // [J] energy that flowed (energy_balance)
  double stable_step = 0;  // [s] estimated largest stable step at the failure; 0: not estimated
  bool diverging = false;  // the check is a divergence signature (the run blew up)
  double since = std::nan("");  // [s] energy_balance: when the residual first went beyond the bound
  int slot = -1;         // stalled: the contact slot with the most events in the stalled window
  long slot_events = 0;  // stalled: that slot's events in the window
  explicit operator bool() const { return kind != Kind::none; }
};

// A condition a warning reports that may explain a later failure (the plan's
// near-singular pose, a fixed step the linearised system makes unstable, a
// motor at its limit). A failure of one of the kinds in `explains` that began
// at or after `t` leads its message with `clause`, and keeps its own after it.
struct FailureCause {
  std::string clause;  // "the hand task passes near a singular pose at t = 1.2 s (...)"
  double t = 0;        // [s] from when it can act
  std::vector<Failure::Kind> explains;
};

// The events and warnings of one step. Their capacity is reserved when Data is
// built (a step emits at most a few per elbow and one per link-box pair).
struct StepLog {
  std::vector<ContactEvent> events;
  std::vector<Warning> warnings;
  void clear() {
    events.clear();
    warnings.clear();
  }
};

const char* to_string(ContactEvent::Kind kind);

// The messages users read in summary.json, on stderr and in reports.
std::string describe(const Model& model, const Warning& warning);
std::string describe(const Model& model, const Failure& failure);
// The same, led by the first of `causes` (in their order) that explains it:
// "<clause>; likely as a result, <the failure's message>".
std::string describe(const Model& model, const Failure& failure,
                     const std::vector<FailureCause>& causes);

}  // namespace elbowsim
