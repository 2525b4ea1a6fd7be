// Reading a finished run: the last recorded value of a column, the first event of a kind.
#pragma once

#include <string>

#include "engine/run/run_result.hpp"

namespace elbowsim::testing {

// The value of `column` in the last recorded row.
inline double last(const RunResult& r, const std::string& column) {
  return r.trajectory.at(r.trajectory.rows() - 1, static_cast<std::size_t>(r.trajectory.column(column)));
}

// The run's first contact event of `kind`, or nullptr.
inline const ContactEvent* first_event(const RunResult& r, ContactEvent::Kind kind) {
  for (const ContactEvent& e : r.events)
    if (e.kind == kind) return &e;
  return nullptr;
}
// A pointer into a temporary run would dangle at the end of the full expression
// (a heap-use-after-free AddressSanitizer found in test_events.cpp): keep the run.
const ContactEvent* first_event(const RunResult&& r, ContactEvent::Kind kind) = delete;

}  // namespace elbowsim::testing
