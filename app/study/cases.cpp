#include "app/study/cases.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace elbowsim::study {

namespace {

std::string level_names(const Scenario::StudyAxis& axis) {
  std::string out;
  for (const auto& [name, overrides] : axis.levels) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

std::vector<StudyCase> study_cases(const Scenario& scenario) {
  std::vector<StudyCase> cases{{}};
  for (const Scenario::StudyAxis& axis : scenario.study) {
    std::vector<StudyCase> next;
    for (const StudyCase& c : cases)
      for (const auto& [level, overrides] : axis.levels) {
        StudyCase n = c;
        n.name += (n.name.empty() ? "" : "-") + level;
        n.levels.push_back(level);
        next.push_back(std::move(n));
      }
    cases = std::move(next);
  }
  return cases;
}

std::vector<StudyCase> select_cases(const Scenario& scenario, const std::string& selection) {
  std::vector<StudyCase> all = study_cases(scenario);
  if (selection.empty()) return all;
  if (scenario.study.empty())
    throw std::invalid_argument("--case: " + scenario.file + " has no study: section (no cases to select)");
  std::map<std::size_t, std::set<std::string>> wanted;  // axis index -> levels
  std::stringstream items(selection);
  for (std::string item; std::getline(items, item, ',');) {
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("--case: expected axis=level, got \"" + item + "\"");
    const std::string axis = item.substr(0, eq), level = item.substr(eq + 1);
    const auto a = std::find_if(scenario.study.begin(), scenario.study.end(),
                                [&](const Scenario::StudyAxis& x) { return x.name == axis; });
    if (a == scenario.study.end()) {
      std::string axes;
      for (const auto& x : scenario.study) axes += (axes.empty() ? "" : ", ") + x.name;
      throw std::invalid_argument("--case: no study axis \"" + axis + "\" (the axes: " + axes + ")");
    }
    const bool known = std::any_of(a->levels.begin(), a->levels.end(),
                                   [&](const auto& l) { return l.first == level; });
    if (!known)
      throw std::invalid_argument("--case: axis " + axis + " has no level \"" + level +
                                  "\" (its levels: " + level_names(*a) + ")");
    wanted[static_cast<std::size_t>(a - scenario.study.begin())].insert(level);
  }
  std::vector<StudyCase> out;
  for (const StudyCase& c : all) {
    const bool match = std::all_of(wanted.begin(), wanted.end(), [&](const auto& w) {
      return w.second.count(c.levels[w.first]) > 0;
    });
    if (match) out.push_back(c);
  }
  return out;
}

}  // namespace elbowsim::study
