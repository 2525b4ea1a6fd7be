#include "app/output/trajectory_csv.hpp"

#include <cstdio>
#include <ostream>

namespace elbowsim {

void write_trajectory_csv(std::ostream& out, const Recording& recording) {
  const std::size_t cols = recording.columns.size();
  for (std::size_t c = 0; c < cols; ++c)
    out << (c ? "," : "") << recording.columns[c].name << " [" << recording.columns[c].unit << "]";
  out << '\n';
  // 12 significant digits: far below any modelling error, and the same bytes
  // for the same numbers on every run.
  char buffer[32];
  for (std::size_t row = 0; row < recording.rows(); ++row) {
    for (std::size_t c = 0; c < cols; ++c) {
      std::snprintf(buffer, sizeof buffer, "%.12g", recording.at(row, c));
      out << (c ? "," : "") << buffer;
    }
    out << '\n';
  }
}

}  // namespace elbowsim
