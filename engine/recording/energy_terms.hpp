// The energy terms of the balance (docs/model.md), each listed once. Like
// MuJoCo's mjxmacro.h, the list is an X-macro expanded where a term needs a
// name; everything else loops over kEnergyTerms:
//   - the members of EnergyTerms and the enumerators of Energy (below),
//   - the state slots of the integrated terms, in list order (state_layout.hpp),
//     read back by run/step.cpp's evaluate_outputs,
//   - the trajectory.csv columns, in list order (recording/trajectory_layout.cpp),
//   - summary.json's energy_initial / energy_final keys (app/output/summary_json.cpp),
//   - the balance residual's sums (dynamics/energy.cpp),
//   - the reports' labels (report/energy_flow.cpp).
// A new term is one line here, its presence group (if new: state_layout.hpp and
// TrajectoryLayout::Groups) and the code that computes it (an integrated term:
// its rate in run/derivative.cpp).
//
// X(member, column, summary_key, role, source, group, meaning, label_in, label_out, short_label)
//   member       EnergyTerms member and Energy enumerator
//   column       trajectory.csv column [J], "" for none
//   summary_key  key under summary.json's energy_initial and energy_final [J], "" for none
//   role         in the balance (supplied) - (lost) = change of (stored); split: E_in
//                split by the sign of each motor's power, not in the balance
//   source       integrated: a state slot, integrated with the motion; stored: from the
//                state (stored_energy); contact: summed by the contact stages
//   group        what the term needs to exist (else no slot, no column; 0 in EnergyTerms)
//   meaning      what it is, for the documentation
//   label_in     the reports' name for it as energy into the arm, label_out out of it
//   short_label  a few words for a chart's category
// The sums of the balance add the terms in this order: moving a line changes the
// residual's last bits (and the golden hashes).
#pragma once

#include <cstddef>

namespace elbowsim {

// clang-format off
#define ELBOWSIM_ENERGY_TERMS(X)                                                                  \
  X(electrical_in, "E_in", "electrical_in", supplied, integrated, always,                         \
    "electrical energy in: integral of v.i over the motors (without motors: the work of the "     \
    "input torques, the hand force's share left out)",                                            \
    "work of the joint inputs", "work done on the joint inputs", "input work")                    \
  X(joule, "E_joule", "joule", lost, integrated, always,                                          \
    "Joule loss in the windings: integral of i^T R i",                                            \
    "Joule loss (windings) (negative)", "Joule loss (windings)", "Joule")                         \
  X(viscous, "E_viscous", "viscous", lost, integrated, always,                                    \
    "viscous loss in joints and gears: integral of qd^T (D + Dm) qd",                             \
    "viscous loss (joints, gears) (negative)", "viscous loss (joints, gears)", "viscous")         \
  X(kinetic_links, "KE_links", "kinetic_links", stored, stored, always,                           \
    "kinetic energy of the links: 1/2 sum m v_c^2 + w^T I w",                                     \
    "kinetic energy of the links given up", "kinetic energy of the links gained", "KE links")     \
  X(kinetic_rotors, "KE_rotors", "kinetic_rotors", stored, stored, always,                        \
    "kinetic energy of the rotors: 1/2 qd^T Jm qd",                                               \
    "kinetic energy of the rotors given up", "kinetic energy of the rotors gained", "KE rotors")  \
  X(potential, "PE", "potential", stored, stored, always,                                         \
    "potential energy: -sum m g.c (0 without gravity)",                                           \
    "potential energy given up", "potential energy gained", "PE")                                 \
  X(magnetic, "E_magnetic", "magnetic", stored, stored, always,                                   \
    "magnetic energy in the windings: 1/2 i^T L i (the full motor model; else 0)",                \
    "magnetic energy given up", "magnetic energy gained", "magnetic")                             \
  X(friction, "E_friction", "friction", lost, integrated, contact,                                \
    "friction loss at the table: integral of mu fn |v_slide| (energy lost to sliding)",           \
    "elbow friction (sliding) (negative)", "elbow friction (sliding)", "elbow friction")          \
  X(normal_work, "E_normal", "normal_work", supplied, integrated, contact,                        \
    "work of the table's normal push: integral of fn^T Jc qd (0 while C holds)",                  \
    "work of the table", "work against the table", "table")                                       \
  X(impact_loss, "E_impact", "impact_loss", lost, contact, contact,                               \
    "kinetic energy lost in impacts (landings)",                                                  \
    "impacts (landings) (negative)", "impacts (landings)", "impacts")                             \
  X(projection, "E_projection", "projection", supplied, contact, contact,                         \
    "stored-energy change made by drift projection (stabilization: projection)",                  \
    "work of the projection steps", "work against the projection steps", "projection")            \
  X(drawn, "E_drawn", "drawn", split, integrated, motors,                                         \
    "drawn from the supply: integral of sum_j max(v_j i_j, 0)",                                   \
    "drawn from the supply", "drawn from the supply", "drawn")                                    \
  X(regenerated, "E_regenerated", "regenerated", split, integrated, motors,                       \
    "fed back by braking motors: integral of sum_j max(-v_j i_j, 0) (drawn - regenerated = "      \
    "electrical_in)",                                                                             \
    "fed back to the supply", "fed back to the supply", "regenerated")                            \
  X(joint_friction, "E_joint_friction", "joint_friction", lost, integrated, joint_friction,       \
    "friction loss of the sliding joints (joint_friction)",                                       \
    "joint friction (negative)", "joint friction", "joint fr.")                                   \
  X(gear_loss, "E_gear", "gear_loss", lost, integrated, gear,                                     \
    "the gears' loss (gear efficiency below 1)",                                                  \
    "gear loss (negative)", "gear loss", "gears")                                                 \
  X(external, "", "", supplied, integrated, hand_force,                                           \
    "work of the constant hand force (in the balance; not recorded)",                             \
    "work of the hand force", "work against the hand force", "hand force")                        \
  X(pad_loss, "E_pad", "pad_loss", lost, integrated, pads,                                        \
    "the elbow pads' loss: their damping, integral of c d'^2 while pressed, and the elastic "     \
    "energy k d^2 / 2 a pad still holds when it lets go",                                         \
    "pad loss (negative)", "pad loss (damping, release)", "pads")                                 \
  X(pad_elastic, "E_pad_elastic", "pad_elastic", stored, contact, pads,                           \
    "elastic energy in the pressed elbow pads: sum k d^2 / 2",                                    \
    "elastic energy of the pads given up", "elastic energy of the pads gained", "pad elastic")     \
  X(spring, "E_spring", "spring", stored, stored, springs,                                        \
    "potential energy of the joint springs: sum -torque (q - at) + stiffness (q - at)^2 / 2",     \
    "energy of the joint springs given up", "energy of the joint springs gained", "springs")
// clang-format on

enum class Energy {
#define ELBOWSIM_ENUMERATOR(member, ...) member,
  ELBOWSIM_ENERGY_TERMS(ELBOWSIM_ENUMERATOR)
#undef ELBOWSIM_ENUMERATOR
};

// Energy terms of the balance E_in - losses = change of stored energy [J]:
// integrals from t = 0 and stored energies at time t (the list above says which).
struct EnergyTerms {
#define ELBOWSIM_MEMBER(member, ...) double member = 0;
  ELBOWSIM_ENERGY_TERMS(ELBOWSIM_MEMBER)
#undef ELBOWSIM_MEMBER
  double mechanical() const { return kinetic_links + kinetic_rotors + potential; }
  double stored() const;  // the terms of role stored
};

enum class EnergyRole { supplied, lost, stored, split };
enum class EnergySource { integrated, stored, contact };
enum class EnergyGroup { always, contact, motors, joint_friction, gear, hand_force, pads, springs };

struct EnergyTermInfo {
  Energy term;
  double EnergyTerms::*value;
  const char* name;         // the member's name
  const char* column;       // "" for none
  const char* summary_key;  // "" for none
  EnergyRole role;
  EnergySource source;
  EnergyGroup group;
  const char* meaning;
  const char* label_in;
  const char* label_out;
  const char* short_label;
};

inline constexpr EnergyTermInfo kEnergyTerms[] = {
#define ELBOWSIM_INFO(member, column, summary_key, role, source, group, meaning, label_in,      \
                      label_out, short_label)                                                  \
  {Energy::member, &EnergyTerms::member, #member, column, summary_key, EnergyRole::role,       \
   EnergySource::source, EnergyGroup::group, meaning, label_in, label_out, short_label},
    ELBOWSIM_ENERGY_TERMS(ELBOWSIM_INFO)
#undef ELBOWSIM_INFO
};

inline constexpr std::size_t kEnergyTermCount = sizeof kEnergyTerms / sizeof kEnergyTerms[0];

inline constexpr const EnergyTermInfo& energy_term(Energy e) {
  return kEnergyTerms[static_cast<std::size_t>(e)];
}

// The sum of the terms of `role`, added in list order (the balance's sums).
inline double energy_sum(const EnergyTerms& e, EnergyRole role) {
  double sum = 0;
  bool first = true;
  for (const EnergyTermInfo& t : kEnergyTerms)
    if (t.role == role) {
      sum = first ? e.*t.value : sum + e.*t.value;  // not 0 + first: keeps a -0 a -0
      first = false;
    }
  return sum;
}

inline double EnergyTerms::stored() const { return energy_sum(*this, EnergyRole::stored); }

}  // namespace elbowsim
