// A count with its noun, singular for one: "1 item", "3 items", "1 entry".
#pragma once

#include <string>

namespace elbowsim {

// `plural` defaults to `singular` + "s".
inline std::string counted(long long n, const std::string& singular,
                           const std::string& plural = "") {
  return std::to_string(n) + " " + (n == 1 ? singular : plural.empty() ? singular + "s" : plural);
}

}  // namespace elbowsim
