// What a run records: a table of samples over time (one row per recorded
// step) plus the run's outcome. Plain data: writers, the renderer and the
// report read it; none of them reach back into the engine.
#pragma once

#include <string>
#include <vector>

#include "engine/contact/contact_tracker.hpp"
#include "engine/data.hpp"
#include "engine/recording/metrics.hpp"

namespace elbowsim {

struct Column {
  std::string name;  // e.g. "q0"
  std::string unit;  // e.g. "rad"
};

struct Recording {
  std::vector<Column> columns;
  std::vector<double> values;  // row-major, rows x columns.size()

  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
  double at(std::size_t row, std::size_t column) const {
    return values[row * columns.size() + column];
  }
  // Index of a named column, or -1.
  int column(const std::string& name) const;
};

struct RunResult {
  Recording trajectory;
  bool completed = false;       // false: stopped early, see failure
  std::string failure;          // why the run stopped early
  std::vector<std::string> warnings;
  long steps = 0;
  double final_time = 0;        // [s]
  double wall_seconds = 0;      // [s]
  EnergyTerms energy_initial, energy_final;
  double balance_residual = 0;      // [J] at the end
  double max_abs_balance_residual = 0;  // [J] over recorded samples
  // Contact (effects.contact): events, drift and the collision worlds built.
  ContactLog contact;
  long collision_worlds_built = 0;  // by this run
  Metrics metrics;                  // computed from the trajectory at the end
};

}  // namespace elbowsim
