// What a user needs to know about a run whose numbers can be trusted (a valid
// run, run/validity.hpp) but whose design may not be what they meant: motors
// that cannot give what they are asked or would overheat, an elbow the task
// keeps on the table that lifts off, a hand that misses its path, electrics
// too fast for the step, an elbow that locks joint 0. Each is one sentence
// that names the quantity, its value, the threshold (model.warn, the scenario's
// `warnings:`) and what to change; the run prints them on stderr and writes
// them into summary.json, and the report shows them first.
#pragma once

#include <string>
#include <vector>

#include "engine/contact/primitives.hpp"
#include "engine/control/controller.hpp"
#include "engine/model.hpp"
#include "engine/recording/metrics.hpp"
#include "engine/recording/recording.hpp"
#include "engine/run/step_log.hpp"

namespace elbowsim {

// The share of the recorded run [0, 1] each motor spends at its voltage limit
// or, with a current limit, at the edge of the voltage window that keeps the
// current within it (motor.cpp): one value per joint, empty without motors.
// A row's state holds until the next row (like metrics' rest share).
std::vector<double> saturation_shares(const Model& model, const Recording& recording);

// One sentence per motor saturated longer than warn.saturation_share of the run.
std::vector<std::string> saturation_warnings(const Model& model, const std::vector<double>& shares);

// One sentence per motor whose RMS current over the run (the metrics'
// current_rms) exceeds its rated continuous current: the run is valid, the
// design is not (a real motor of that rating would overheat).
std::vector<std::string> motor_rating_warnings(const Model& model, const Metrics& metrics);

// One sentence per elbow the task keeps on the table (`planned_resting`, model
// elbow indices) that left it during the run (release events of its slots,
// `geometry` as the run's contact data), with the first time and the count.
std::vector<std::string> lift_off_warnings(const Model& model, const ContactGeometry& geometry,
                                           const std::vector<ContactEvent>& events,
                                           const std::vector<int>& planned_resting);

// One sentence per contact body (metrics' body_rest_fraction) the scene does
// not plan to rest on the table, resting for more than
// warn.unplanned_contact_share of the run: a link's own solid, or an elbow the
// task holds above the table (`held`, model elbow indices). Names the body,
// its share and forces, and what that means for the run's numbers.
std::vector<std::string> unplanned_contact_warnings(const Model& model, const Metrics& metrics,
                                                    const std::vector<int>& held);

// Of those bodies, the one that rested longest, and its share of the run (0
// and "" when none rested): what a Monte Carlo study records per draw.
struct UnplannedContact {
  double share = 0;
  std::string body;
};
UnplannedContact longest_unplanned_contact(const Metrics& metrics, const std::vector<int>& held);

// One sentence when the hand was farther than warn.hand_error from its
// desired point at some recorded sample (a task), with when and the RMS.
std::vector<std::string> hand_error_warnings(const Model& model, const Recording& recording);

// A fixed-step integrator the motor-arm system linearised at initial.q makes
// unstable (fixed_step_stability.hpp; controller: its continuous feedback
// gains, or null), or one that is stable there on motor electrics far faster
// than its step (L/R under a tenth of it: first order there, engine/MODEL.md,
// "Integration"): one warning with the numbers and the fix.
std::vector<std::string> stiffness_warnings(const Model& model,
                                            const ControllerSpec* controller = nullptr);

// The unstable fixed step of stiffness_warnings as the possible cause of a
// divergence, a bound or an energy balance broken (step_log.hpp, FailureCause).
std::vector<FailureCause> stiffness_causes(const Model& model,
                                           const ControllerSpec* controller = nullptr);

// Each saturation warning's motor at its limit as the possible cause of an
// elbow that did not rest as planned (the arm followed the limit).
std::vector<FailureCause> saturation_causes(const Model& model, const std::vector<double>& shares);

// An elbow on link 0: its point moves with joint 0 alone (the base is fixed),
// so while it rests or sticks the table holds joint 0 still, and with friction
// its normal and friction rows are one row up to scale: rigid-body mechanics
// fixes only the force's moment about joint 0 (the run uses the minimum-norm
// split). One sentence per such elbow; the run is valid.
std::vector<std::string> first_link_elbow_warnings(const Model& model);

// What a run says about its model before it starts (stiffness, first-link
// elbows), in that order; printed by `validate` too.
std::vector<std::string> model_warnings(const Model& model,
                                        const ControllerSpec* controller = nullptr);

}  // namespace elbowsim
