// What a run returns: the recorded trajectory and the run's outcome (whether
// it completed, why not, warnings, contact events and statistics, energies).
#pragma once

#include <string>
#include <vector>

#include "engine/data.hpp"
#include "engine/recording/metrics.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

// Contact statistics over the run (effects.contact).
struct ContactStats {
  double max_abs_C = 0;         // [m] over resting elbows, sampled after each step
  double max_abs_Cd = 0;        // [m/s]
  long dependent_steps = 0;     // steps whose active rows were dependent
};

// The gains a tracking controller ran with (all empty in open loop): as
// given, or as controller.tuning placed them (control/tuning.hpp).
struct ControllerGains {
  Eigen::VectorXd kp, kd, ki;  // [V/rad], [V s/rad], [V/(rad s)] per joint
  Eigen::VectorXd inertia;     // [kg m^2] the tuning rule's I_j; empty without a rule
  std::vector<int> integral_held;  // joints left without integral: the resting elbows hold them
};

struct RunResult {
  Recording trajectory;
  bool completed = false;       // reached the end (false: stopped early, see failure)
  bool valid = false;           // completed and every check of run/validity.hpp held
  std::string failure;          // why the run stopped early or is not valid
  bool interrupted = false;     // stopped from outside (RunOptions::stop), not by the physics
  std::vector<std::string> warnings;
  std::vector<ContactEvent> events;  // landings and releases, in time order
  long steps = 0;
  Data::IntegratorWork work;    // evaluations, rejected steps, Jacobians, factorisations
  double stiff_from = -1;       // [s] when dopri5 found the equations stiff (its warning); -1: never
  double final_time = 0;        // [s]
  double wall_seconds = 0;      // [s]
  ControllerGains gains;
  double plan_cpu_seconds = 0;  // [s] CPU time of the controller's plan (inverse kinematics), before the run
  EnergyTerms energy_initial, energy_final;
  double balance_residual = 0;      // [J] at the end
  double max_abs_balance_residual = 0;  // [J] over recorded samples
  ContactStats contact;
  long collision_worlds_built = 0;  // by this run
  Metrics metrics;                  // computed from the trajectory at the end
  std::vector<double> saturation;   // [dof] share of the run each motor spent at its limit (warnings.hpp); empty without motors
};

}  // namespace elbowsim
