// Stored energy of the arm and motors. Dissipated and supplied energy are
// integrated along with the state (state_layout.hpp, run/derivative.cpp).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Fills the stored terms of `out` (kinetic_links, kinetic_rotors, potential,
// magnetic) for rates qd and motor currents; needs forward_kinematics(q).
// Potential energy is -sum m_i g.c_i (zero when gravity is off).
void stored_energy(const Model& model, const Data& data, ConstVec qd, ConstVec current,
                   EnergyTerms& out);

// (supplied) - (lost) - (E_stored - E_stored(0)), the roles of energy_terms.hpp
// (E_in + E_normal + E_projection + the hand force's work) - (E_joule + E_viscous
// + E_friction + E_impact + E_joint_friction + E_gear) - ...: zero for exact
// integration, so it measures the integration error.
double balance_residual(const EnergyTerms& now, const EnergyTerms& initial);

}  // namespace elbowsim
