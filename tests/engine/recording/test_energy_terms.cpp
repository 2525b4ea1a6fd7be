// engine/recording/energy_terms.hpp: the one list of energy terms. The state slots, columns and
// summary keys expanded from it must be those the engine had before the list (golden
// layouts), and the balance's sums must take each term with its sign.
#include <doctest/doctest.h>

#include <iterator>
#include <set>
#include <string>

#include "engine/recording/energy_terms.hpp"
#include "engine/state_layout.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// driven_arm (2 joints, full motors) with every optional energy group on or off.
Model arm_with(bool everything) {
  Model m = driven_arm(IntegratorKind::rk4, 1e-3, 1.0, 0.5e-3);
  m.effects.contact = everything;
  m.effects.friction = everything;
  m.effects.joint_friction = everything;
  m.gear_losses = everything;
  m.hand_load.force = everything ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d::Zero();
  m.elbows.clear();
  if (everything) m.elbows.push_back(Elbow{"elbow", 0, Eigen::Vector3d::Zero(), 0.03, Pad{1e4, 1.0, 0.005}});
  return m;
}

}  // namespace

TEST_CASE("energy terms: the state slots of a model with every term (golden order)") {
  // The order the integrated state had before the list: adaptive error control and
  // the golden hashes depend on it; it changes only on purpose.
  const Model m = arm_with(true);
  const StateLayout s(m);
  REQUIRE(s.energy == 3 * 2);  // q, qd, i of 2 joints
  const std::pair<Energy, int> golden[] = {
      {Energy::electrical_in, 0}, {Energy::joule, 1},          {Energy::viscous, 2},
      {Energy::friction, 3},      {Energy::normal_work, 4},    {Energy::drawn, 5},
      {Energy::regenerated, 6},   {Energy::joint_friction, 7}, {Energy::gear_loss, 8},
      {Energy::external, 9},      {Energy::pad_loss, 10}};
  for (const auto& [term, offset] : golden) {
    CAPTURE(std::string(energy_term(term).name));
    CHECK(s.slot(term) == s.energy + offset);
  }
  for (Energy stored : {Energy::kinetic_links, Energy::kinetic_rotors, Energy::potential,
                        Energy::magnetic, Energy::impact_loss, Energy::projection, Energy::pad_elastic,
                        Energy::spring})
    CHECK(s.slot(stored) == -1);  // not integrated
  CHECK(s.body_friction == s.energy + 11);  // then one per elbow and per link
  CHECK(s.size == s.energy + 11 + 1 + 2);
  CHECK(s.controlled == s.body_friction);
}

TEST_CASE("energy terms: a model without the optional groups integrates E_in, E_joule, E_viscous (and drawn, regenerated)") {
  const Model m = arm_with(false);
  const StateLayout s(m);
  CHECK(s.slot(Energy::electrical_in) == s.energy);
  CHECK(s.slot(Energy::joule) == s.energy + 1);
  CHECK(s.slot(Energy::viscous) == s.energy + 2);
  CHECK(s.slot(Energy::drawn) == s.energy + 3);  // motors
  CHECK(s.slot(Energy::regenerated) == s.energy + 4);
  for (Energy absent : {Energy::friction, Energy::normal_work, Energy::joint_friction,
                        Energy::gear_loss, Energy::external, Energy::pad_loss})
    CHECK(s.slot(absent) == -1);
  CHECK(s.body_friction == -1);
  CHECK(s.size == s.energy + 5);
}

TEST_CASE("energy terms: names are unique; a summary key is the member's name") {
  std::set<std::string> names, columns;
  for (const EnergyTermInfo& t : kEnergyTerms) {
    CAPTURE(std::string(t.name));
    CHECK(names.insert(t.name).second);
    if (*t.column) CHECK(columns.insert(t.column).second);
    CHECK((std::string(t.summary_key).empty() || std::string(t.summary_key) == t.name));
    CHECK(&energy_term(t.term) == &t);  // the enumerators follow the list
  }
}

TEST_CASE("energy terms: the balance adds supplied, subtracts lost and stored, leaves the split out") {
  // docs/model.md's balance: (E_in + E_normal + E_projection + hand force work) -
  // (E_joule + E_viscous + E_friction + E_impact + E_joint_friction + E_gear + E_pad) =
  // change of (KE + PE + E_magnetic + E_pad_elastic + E_spring); E_drawn - E_regenerated = E_in is no term of it.
  // One term at a time set to 1 J: its effect on supplied - lost - stored is its sign.
  const std::pair<Energy, double> golden[] = {
      {Energy::electrical_in, 1}, {Energy::joule, -1},         {Energy::viscous, -1},
      {Energy::kinetic_links, -1}, {Energy::kinetic_rotors, -1}, {Energy::potential, -1},
      {Energy::magnetic, -1},     {Energy::friction, -1},      {Energy::normal_work, 1},
      {Energy::impact_loss, -1},  {Energy::projection, 1},     {Energy::drawn, 0},
      {Energy::regenerated, 0},   {Energy::joint_friction, -1}, {Energy::gear_loss, -1},
      {Energy::external, 1},      {Energy::pad_loss, -1},      {Energy::pad_elastic, -1},
      {Energy::spring, -1}};
  REQUIRE(std::size(golden) == kEnergyTermCount);
  for (const auto& [term, sign] : golden) {
    CAPTURE(std::string(energy_term(term).name));
    EnergyTerms e;
    e.*energy_term(term).value = 1.0;
    CHECK(energy_sum(e, EnergyRole::supplied) - energy_sum(e, EnergyRole::lost) - e.stored() == sign);
  }
  EnergyTerms e;
  e.kinetic_links = 1, e.kinetic_rotors = 2, e.potential = 4, e.magnetic = 8;
  CHECK(e.stored() == 15.0);
  CHECK(e.mechanical() == 7.0);
}
