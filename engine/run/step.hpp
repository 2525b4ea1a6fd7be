// One step of the simulation, the way MuJoCo's mj_step reads: a flat list of
// stages, each a named function, only those of the scene's effects running.
// This is the engine's one stage list (docs/architecture.md links here), in the
// order step.cpp calls them. "runs with": contact (effects.contact), joint friction
// (effects.joint_friction), projection (effects.contact and stabilization:
// projection), digital loop (controller.sample_rate), fixed or adaptive step
// (simulation.integrator); blank: always.
//
// reset(model, data) function             file (engine/)            runs with
//   check            check_data           data
//   integrator       prepare_integrator   run/integrator
//       the ETD coefficients for the step
//   initial state    reset_state          run/step
//       t = 0; on the plan when a controller tracks one
//   first sample     start_digital_loop   control/digital_loop      digital loop
//   joint modes      decide_joint_modes   run/joint_stick_slip      joint friction
//   collision        CollisionWorld       contact/collision_bullet  contact
//       Bullet's world, built once
//   active set       select_active_set    run/active_set            contact
//       as in step()
//   outputs          evaluate_outputs     run/step
//       qdd, voltage, forces and energies at t = 0
//
// step(model, data)  function             file (engine/)            runs with
//   check            check_data           data
//   active set       select_active_set    run/active_set            contact
//       detection (detect_contacts, contact/detection: Bullet distances, normals, surface
//       points), then the LCP on the touching contacts (elbows, links): the rows on for the step
//   joint modes      decide_joint_modes   run/joint_stick_slip      joint friction
//       which joints stick and which slide, held over the step
//   integrate        integrate_step       run/integrator            fixed step
//       euler, semi-implicit Euler, rk4 (ETD)
//     or             adaptive_step        run/adaptive              adaptive step
//       dopri5, ros34pw2, with error control
//   joint events     locate_joint_event   run/joint_stick_slip      joint friction
//       a joint stopping or breaking away inside the step: the step is redone up to it
//   contact events   locate_first_event   run/contact_events        contact
//       the detection at the step's end; with contact.events: locate, the landings and
//       releases inside the step: the step is redone up to the first
//   impacts          land_touching_slots  contact/impact            contact
//       impulses for the contacts that landed
//   stabilise        stabilise            contact/projection        projection
//       back onto C = 0, dC/dt = 0
//   contact checks   check_contacts       contact/contact_checks    contact
//       how far the resting contacts drift off C = 0 and dC/dt = 0
//   validity         check_step           run/validity
//       divergence, current and speed bounds, a link or elbow in the table
//   sample           sample_if_due        control/digital_loop      digital loop
//       at a sample instant, unless the step failed: sensors, control law, held voltage
//
// Every derivative evaluation (integrate, and the steps the event searches redo) is
// nonstiff_rates (run/derivative): forward kinematics (dynamics/kinematics) -> control law
// (command, control/controller) -> motor (motor_stage, dynamics/motor) -> applied torques
// (dynamics/applied_torques) -> arm accelerations (dynamics/forward_dynamics, or
// dynamics/joint_friction with joint friction; while elbows rest, contact/constraint_rows and
// contact/constrained_dynamics) -> energy powers. simulate() (simulator.hpp) is a loop
// over step() plus recording.
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

// Whether the run has reached model.options.duration: a fixed-step run within a
// thousandth of a step, an adaptive one within rounding (engine/step_grid.hpp).
bool finished(const Model& model, const Data& data);

// Evaluates the stage outputs (qdd, voltage, current, actuation, contact
// forces, energy) at the state in data.x without advancing it.
void evaluate_outputs(const Model& model, Data& data);

// Puts the model's initial state into data (t = 0, x, q, qd, current); a
// tracking controller starts on its plan, with the currents that hold it.
void reset_state(const Model& model, Data& data);

}  // namespace elbowsim
