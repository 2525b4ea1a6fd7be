// One step of the simulation, the way MuJoCo's mj_step reads: a flat list of
// stages, each a named function, only those of the scene's effects running.
//
//   detect -> active set -> integrate -> events -> impacts -> stabilise -> checks
//
// reset() puts a Data at the model's initial state; step() advances it by one
// step; simulate() (simulator.hpp) is a loop over step() plus recording.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Prepares data for a run: integrator coefficients, the initial state (on the
// controller's plan when data.controller tracks one; set it first), the
// collision world and the active set at t = 0 (contact scenes), the stage
// outputs and energies there (data.energy_initial). Allocates (the collision
// world) once. Throws std::invalid_argument when data was made for another
// model (check_data).
void reset(const Model& model, Data& data);

// Advances data by one step of model.options.step, the last step before
// model.options.duration shortened to end on it. data.log holds the step's
// contact events and warnings afterwards. When the run cannot go on or its
// state cannot be trusted, data.failure says why (Painleve's paradox, no
// contact solution, and the checks of run/validity.hpp: divergence, current
// and speed bounds, a link or elbow in the table) and the state is left
// where it stopped. Allocates nothing (but when it fails).
void step(const Model& model, Data& data);

// Whether the run has reached model.options.duration (within a thousandth
// of a step: t accumulates rounding).
bool finished(const Model& model, const Data& data);

// How close [s] a fixed step's end must come to a row time k x interval to be
// on it (Data::record_interval): far above t's accumulated rounding, far below a step.
double row_tolerance(const Model& model);

// Evaluates the stage outputs (qdd, voltage, current, actuation, contact
// forces, energy) at the state in data.x without advancing it.
void evaluate_outputs(const Model& model, Data& data);

// Puts the model's initial state into data (t = 0, x, q, qd, current); a
// tracking controller starts on its plan, with the currents that hold it.
void reset_state(const Model& model, Data& data);

}  // namespace elbowsim
