#include <iostream>

#include "app/commands/commands.hpp"
#include "app/scenario/scenario.hpp"
#include "app/study/cases.hpp"
#include "engine/run/validity.hpp"

namespace elbowsim {

namespace {

void print_model(const Scenario& s) {
  const Model& m = s.model;
  double total = 0;
  for (const Link& link : m.links) total += link.mass;
  std::cout << "scenario   " << m.name << " (" << s.file << ")\n";
  if (!s.description.empty()) std::cout << "           " << s.description << '\n';
  std::cout << "dof        " << m.dof << '\n' << "masses     ";
  for (const Link& link : m.links) std::cout << link.mass << ' ';
  std::cout << "kg (total " << total << " kg)\n" << "effects    ";
  for (const std::string& e : m.active_effects()) std::cout << e << ' ';
  if (m.active_effects().empty()) std::cout << "(none)";
  std::cout << '\n';
  if (m.has_motor()) {
    std::cout << "motors     Km ";
    for (int j = 0; j < m.dof; ++j) std::cout << m.km[j] << ' ';
    std::cout << "N m/A, Jm ";
    for (int j = 0; j < m.dof; ++j) std::cout << m.armature[j] << ' ';
    std::cout << "kg m^2\n";
  }
  std::cout << "simulation " << m.options.duration << " s, step " << m.options.step << " s, "
            << to_string(m.options.integrator) << ", " << to_string(m.options.dynamics) << '\n'
            << "output     " << s.output.folder << '\n';
  for (const std::string& w : model_warnings(m)) std::cout << "note       " << w << '\n';
}

}  // namespace

int validate_command(const std::string& scenario, const std::vector<std::string>& sets) {
  try {
    const Scenario s = load_scenario(scenario, sets);
    print_model(s);
    // Every case of the study, with every variant, as montecarlo loads them.
    const auto cases = study::study_cases(s);
    if (!s.study.empty()) {
      for (const study::StudyCase& c : cases) {
        load_scenario_case(scenario, c.levels, "", sets);
        for (const auto& [variant, overrides] : s.variants) load_scenario_case(scenario, c.levels, variant, sets);
      }
      std::cout << "study      " << cases.size() << " cases (";
      for (std::size_t a = 0; a < s.study.size(); ++a)
        std::cout << (a ? " x " : "") << s.study[a].levels.size() << " " << s.study[a].name;
      std::cout << "), each loaded\n";
    }
  } catch (const ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace elbowsim
