// Which elbows rest on the table, step by step (issue: unilateral contact).
//
// At the start of every step Bullet (collision.hpp) gives each elbow its
// signed distance and the table normal under it; the elbows that touch
// (distance <= touch_distance, not separating) form a small LCP on the
// Delassus matrix, whose solution is the active set: rows of M* that stay on
// for the whole step (so the step is smooth and keeps its order). After the
// step, an elbow that went into the table has landed and an active one whose
// force turned negative has released; with events: locate the step is
// redone up to the event time, found by root finding.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/contact/collision.hpp"
#include "engine/data.hpp"

namespace elbowsim {

struct ContactEvent {
  enum class Kind { landing, release };
  double t = 0;         // [s]
  int elbow = -1;
  Kind kind = Kind::landing;
  double speed = 0;     // [m/s] approach speed at landing (> 0), 0 at release
  double impulse = 0;   // [N s] landing impulse
  double energy_lost = 0;  // [J] kinetic energy this elbow's impulse took
};

struct ContactLog {
  std::vector<ContactEvent> events;
  std::vector<std::string> warnings;
  std::string failure;              // set when the run must stop (Painleve, ...)
  double max_abs_C = 0;             // [m] over resting elbows, sampled after each step
  double max_abs_Cd = 0;            // [m/s]
  long dependent_steps = 0;         // steps whose active rows were dependent
};

class ContactTracker {
 public:
  explicit ContactTracker(const Model& model);

  // Detection and the active set at the state in data.x (time data.t).
  // Returns false (and sets log.failure) when no valid set exists.
  bool begin_step(const Model& model, Data& data, ContactLog& log);

  // After data.x was advanced from data.x_start (time t0): landings and
  // releases inside the step; with events: locate, the step is redone up to
  // the earliest event. Impacts are applied. Returns false on failure.
  bool end_step(const Model& model, Data& data, double t0, ContactLog& log);

  // Signed distances [m] of every elbow at the state in data.x (Bullet).
  const std::vector<ElbowContact>& detect(const Model& model, Data& data);

 private:
  bool lands(const Model& model, int elbow, const ElbowContact& c, double normal_speed) const;
  double normal_speed(const Model& model, Data& data, int elbow) const;
  void land(const Model& model, Data& data, const std::vector<int>& elbows, ContactLog& log);
  void release(Data& data, int elbow, ContactLog& log);
  void check_links(const Model& model, Data& data, ContactLog& log);
  void record_drift(const Model& model, Data& data, ContactLog& log);
  double locate(const Model& model, Data& data, double t0, double h, int elbow, bool landing);
  double event_value(const Model& model, Data& data, int elbow, bool landing);

  CollisionWorld world_;
  std::vector<ElbowContact> contacts_;
  std::vector<LinkPenetration> penetrations_;
  std::vector<bool> link_warned_;
  bool dependent_warned_ = false;
};

}  // namespace elbowsim
