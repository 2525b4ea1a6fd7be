#include "simulator.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "derivative.hpp"
#include "energy.hpp"
#include "integrator.hpp"
#include "kinematics.hpp"
#include "state_vector.hpp"

namespace elbowsim {

namespace {

Eigen::VectorXd or_zeros(const Eigen::VectorXd& v, int n) {
  return v.size() == n ? v : Eigen::VectorXd::Zero(n);
}

void add_columns(std::vector<Column>& cols, const char* prefix, const char* unit, int n) {
  for (int j = 0; j < n; ++j) cols.push_back({prefix + std::to_string(j), unit});
}

std::vector<Column> trajectory_columns(const Model& model) {
  const int n = model.dof;
  std::vector<Column> cols{{"time", "s"}};
  add_columns(cols, "q", "rad", n);
  add_columns(cols, "qd", "rad/s", n);
  add_columns(cols, "qdd", "rad/s^2", n);
  if (model.has_motor()) {
    add_columns(cols, "i", "A", n);
    add_columns(cols, "v", "V", n);
  }
  add_columns(cols, "tau", "N m", n);
  for (const char* axis : {"hand_x", "hand_y", "hand_z"}) cols.push_back({axis, "m"});
  for (const char* e : {"E_in", "E_joule", "E_viscous", "KE_links", "KE_rotors", "PE",
                        "E_magnetic", "balance_residual"})
    cols.push_back({e, "J"});
  return cols;
}

void append(std::vector<double>& row, const Eigen::VectorXd& v) {
  row.insert(row.end(), v.data(), v.data() + v.size());
}

void record_sample(const Model& model, const Data& data, Recording& rec) {
  std::vector<double>& row = rec.values;
  row.push_back(data.t);
  append(row, data.q);
  append(row, data.qd);
  append(row, data.qdd);
  if (model.has_motor()) {
    append(row, data.current);
    append(row, data.voltage);
  }
  append(row, data.actuation);
  const Eigen::Vector3d hand = point_position(data, model.hand_link, model.hand_point);
  row.insert(row.end(), {hand.x(), hand.y(), hand.z()});
  const EnergyTerms& e = data.energy;
  row.insert(row.end(), {e.electrical_in, e.joule, e.viscous, e.kinetic_links, e.kinetic_rotors,
                         e.potential, e.magnetic, balance_residual(e, data.energy_initial)});
}

std::string divergence_message(const Model& model, const Data& data) {
  std::ostringstream msg;
  msg << "simulation diverged at t = " << data.t << " s (step " << data.steps
      << "): the state became non-finite or exceeded 1e12; try a smaller simulation.step"
      << " (now " << model.options.step << " s) or the rk4 integrator";
  return msg.str();
}

bool state_is_sane(const Data& data) {
  return data.x.allFinite() && data.x.cwiseAbs().maxCoeff() < 1e12;
}

}  // namespace

void reset_state(const Model& model, Data& data) {
  const StateLayout s(model);
  data.t = 0;
  data.steps = 0;
  data.x.setZero();
  data.x.segment(s.q(), s.n) = or_zeros(model.initial.q, s.n);
  data.x.segment(s.qd(), s.n) = or_zeros(model.initial.qd, s.n);
  if (s.current >= 0) data.x.segment(s.current, s.n) = or_zeros(model.initial.current, s.n);
}

void evaluate_outputs(const Model& model, Data& data) {
  const StateLayout s(model);
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  data.q = data.x.segment(s.q(), s.n);
  data.qd = data.x.segment(s.qd(), s.n);
  if (s.current >= 0) data.current = data.x.segment(s.current, s.n);
  // nonstiff_rates leaves the full di/dt in data.current_rate (motor_stage).
  stored_energy(model, data, data.qd, data.current, data.energy);
  data.energy.electrical_in = data.x[s.energy];
  data.energy.joule = data.x[s.energy + 1];
  data.energy.viscous = data.x[s.energy + 2];
}

RunResult simulate(const Model& model, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RunResult result;
  result.trajectory.columns = trajectory_columns(model);
  Data data(model);
  prepare_integrator(model, data);
  reset_state(model, data);
  evaluate_outputs(model, data);
  data.energy_initial = data.energy;
  record_sample(model, data, result.trajectory);

  const long total = std::lround(model.options.duration / model.options.step);
  const long every = std::max(1, options.record_every);
  const long progress_every = std::max(1L, total / 100);
  result.completed = true;
  for (long k = 1; k <= total; ++k) {
    integrate_step(model, data);
    if (!state_is_sane(data)) {
      result.completed = false;
      result.failure = divergence_message(model, data);
      break;
    }
    if (k % every == 0 || k == total) {
      evaluate_outputs(model, data);
      record_sample(model, data, result.trajectory);
      result.max_abs_balance_residual = std::max(
          result.max_abs_balance_residual, std::abs(balance_residual(data.energy, data.energy_initial)));
    }
    if (options.progress && k % progress_every == 0) options.progress(double(k) / double(total));
  }
  result.steps = data.steps;
  result.final_time = data.t;
  result.energy_initial = data.energy_initial;
  result.energy_final = data.energy;
  result.balance_residual = balance_residual(data.energy, data.energy_initial);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace elbowsim
