// Shared by the scenario-loader tests (test_scenario*.cpp): fixtures written
// as raw strings, loading from text, and CHECK_ERROR, which checks where an
// error is reported and what it says. Line numbers in the checks count from
// the fixture's first line.
#pragma once

#include <doctest/doctest.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"

namespace scenario_test {

using elbowsim::load_scenario_text;
using elbowsim::Scenario;
using elbowsim::ScenarioError;

// Fixtures are written as R"(\n...)": drop the first newline so that the
// first line of the text is line 1.
inline std::string yaml(const char* text) {
  std::string s(text);
  return s.starts_with('\n') ? s.substr(1) : s;
}

inline Scenario load(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return load_scenario_text(text, "x.yaml", overrides);
}

// The error message of loading `text`, or "" if it loads.
inline std::string error_of(const std::string& text,
                            const std::vector<std::string>& overrides = {}) {
  try {
    load(text, overrides);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

inline bool approx(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double atol = 1e-12) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a - b).cwiseAbs().maxCoeff() <= atol;
}

// Checks that loading `text` fails at `location` ("x.yaml:7:" or
// "x.yaml:7:12:") naming `key`, with `words` in the message.
#define CHECK_ERROR(text, location, key, words)              \
  do {                                                       \
    const std::string msg_ = error_of(text);                 \
    INFO("message: " << msg_);                               \
    CHECK(msg_.starts_with(location));                       \
    CHECK(contains(msg_, std::string(": ") + (key) + ": ")); \
    CHECK(contains(msg_, words));                            \
  } while (0)

// Two planar links; the second overrides every default.
//
//   z
//   |      link 1 (0.2 m)
//   |    o------o hand
//   |   / link 0 (0.3 m)
//   o------ x
inline const std::string kTwoLink = yaml(R"(
name: two_link
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 0.5, com: 0.08, inertia: 0.002, radius: 0.03}
simulation:
  duration: 1.0
)");

// The planar arm with `lines` appended (top-level sections).
inline std::string two_link_with(const char* lines) { return kTwoLink + yaml(lines); }

inline std::filesystem::path scenarios_dir() {
  return std::filesystem::path(__FILE__).parent_path().parent_path() / "scenarios";
}

}  // namespace scenario_test
