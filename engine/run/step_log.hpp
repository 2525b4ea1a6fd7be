// What a step reports besides the new state: contact events and warnings of
// the last step (data.log, emptied when a step starts; simulate() collects
// them), and why a run must stop (data.failure). Plain records with reserved
// capacity, so a step allocates nothing; messages are written from them
// afterwards (describe()).
#pragma once

#include <string>
#include <vector>

namespace elbowsim {

struct Model;

struct ContactEvent {
  enum class Kind { landing, release };
  double t = 0;         // [s]
  int elbow = -1;
  Kind kind = Kind::landing;
  double speed = 0;     // [m/s] approach speed at landing (> 0), 0 at release
  double impulse = 0;   // [N s] landing impulse
  double energy_lost = 0;  // [J] kinetic energy this elbow's impulse took
};

struct Warning {
  enum class Kind {
    dependent_rows,  // touching elbows whose rows of M* are dependent: `count` rows of rank `rank`
    link_in_table,   // link `index` entered table box `box`, `value` [m] deep
  };
  Kind kind = Kind::dependent_rows;
  double t = 0;      // [s]
  int index = -1;    // the link (link_in_table)
  int box = -1;      // the table box (link_in_table)
  int count = 0;     // touching elbows (dependent_rows)
  int rank = 0;      // rank of their rows (dependent_rows)
  double value = 0;  // depth [m] (link_in_table)
};

struct Failure {
  enum class Kind {
    none,
    painleve,             // friction makes a resting elbow's normal force push it into the table
    no_contact_solution,  // no active set has non-negative forces and accelerations
    diverged,             // the state became non-finite or exceeded 1e12
  };
  Kind kind = Kind::none;
  double t = 0;     // [s]
  long step = 0;    // steps taken when it happened
  explicit operator bool() const { return kind != Kind::none; }
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

// The messages users read in summary.json, on stderr and in reports.
std::string describe(const Model& model, const Warning& warning);
std::string describe(const Model& model, const Failure& failure);

}  // namespace elbowsim
