// The cases of a scenario's study (its study.axes): one level of every axis,
// all combinations. A case is named by its levels joined with '-' (level
// names hold no '-'), e.g. loops-fast-mid; it is also its folder's name.
#pragma once

#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"

namespace elbowsim::study {

struct StudyCase {
  std::string name;                 // "" for a scenario without a study
  std::vector<std::string> levels;  // one per axis, in axis order; empty without a study
};

// Every case, the first axis varying slowest; one unnamed case without a study.
std::vector<StudyCase> study_cases(const Scenario& scenario);

// The cases whose levels match `selection`: "axis=level,axis=level,..." (an
// axis left out takes every level; the same axis twice takes either level).
// Empty: every case. Throws std::invalid_argument naming an unknown axis or
// level, or a selection on a scenario without a study.
std::vector<StudyCase> select_cases(const Scenario& scenario, const std::string& selection);

}  // namespace elbowsim::study
