// What a run records: a table of samples over time (one row per recorded
// step). Plain data: writers, the renderer and the report read it; none of
// them reach back into the engine.
#pragma once

#include <string>
#include <vector>

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

}  // namespace elbowsim
