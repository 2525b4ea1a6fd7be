// What a run records: a table of samples over time (one row per recorded
// step) and its layout (trajectory_layout.hpp), which owns every column's
// name, unit and index. Plain data: writers, the renderer and the report read
// it; none of them reach back into the engine.
#pragma once

#include <string>
#include <vector>

#include "engine/recording/trajectory_layout.hpp"

namespace elbowsim {

struct Recording {
  TrajectoryLayout layout;
  std::vector<double> values;  // row-major, rows x layout.size()

  Recording() = default;
  explicit Recording(TrajectoryLayout l) : layout(std::move(l)) {}

  const std::vector<Column>& columns() const { return layout.columns(); }
  std::size_t rows() const { return layout.size() == 0 ? 0 : values.size() / layout.columns().size(); }
  double at(std::size_t row, std::size_t column) const {
    return values[row * layout.columns().size() + column];
  }
  // Index of a named column, or -1.
  int column(const std::string& name) const;
  // The values of column `c` (an index from the layout), one per row; empty when c < 0.
  std::vector<double> series(int c) const;
};

}  // namespace elbowsim
