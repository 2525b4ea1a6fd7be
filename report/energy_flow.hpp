// Where every joule of a run went: the energy balance of docs/model.md read
// from summary.json (energy_initial, energy_final, balance_residual) as an
// account. Into the arm: energy drawn from the supply, stored energy given up
// (potential, kinetic, magnetic), work of the table and of projection steps;
// out of it: energy fed back to the supply (regenerated), the losses (Joule,
// viscous, friction, impacts, gears), stored energy gained; and the residual
// the account leaves unexplained (integration error). A term that came out
// negative is booked on the other side, so every term is >= 0.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "report/plot/plot.hpp"

namespace elbowsim::report {

struct EnergyTerm {
  std::string key;          // "drawn", "potential", "joule", ... (the summary's energy key)
  std::string label;        // "drawn from the supply", "potential energy given up", ...
  double value = 0;         // [J] >= 0
  std::string short_label;  // "drawn", "PE given up": a bar chart's category
};

struct EnergyFlow {
  std::vector<EnergyTerm> in;   // sources, largest first
  std::vector<EnergyTerm> out;  // destinations, largest first
  double total_in = 0;          // [J] sum of the sources: the energy that flowed
  double residual = 0;          // [J] summary.json balance_residual (in - out)
  double electrical_in = 0;     // [J] drawn - regenerated (E_in)
  bool motors = false;          // drawn and regenerated are recorded (a motor model)

  double term(const std::string& key) const;  // a term's value on either side; 0 when absent
};

// The account of a summary.json; nullopt when it has no energy_final.
std::optional<EnergyFlow> energy_flow(const nlohmann::ordered_json& summary);

// The account as a waterfall: the sources up to "energy in", the
// destinations back down, and the residual as the last bar.
plot::Waterfall energy_waterfall(const EnergyFlow& flow, const std::string& title);

// Plain sentences that explain the account: what E_in is, where regenerated
// energy went, why the Joule loss can exceed the electrical energy in, how
// large the residual is.
std::vector<std::string> energy_flow_notes(const EnergyFlow& flow);

}  // namespace elbowsim::report
