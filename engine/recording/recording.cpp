#include "engine/recording/recording.hpp"

namespace elbowsim {

int Recording::column(const std::string& name) const {
  const std::vector<Column>& cols = columns();
  for (std::size_t c = 0; c < cols.size(); ++c)
    if (cols[c].name == name) return static_cast<int>(c);
  return -1;
}

std::vector<double> Recording::series(int c) const {
  if (c < 0) return {};
  std::vector<double> out(rows());
  for (std::size_t row = 0; row < out.size(); ++row) out[row] = at(row, static_cast<std::size_t>(c));
  return out;
}

}  // namespace elbowsim
