#include "engine/recording/recording.hpp"

namespace elbowsim {

int Recording::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].name == name) return static_cast<int>(c);
  return -1;
}

}  // namespace elbowsim
