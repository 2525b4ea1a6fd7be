#include "engine/recording/metrics.hpp"

#include "engine/recording/recording.hpp"

#include <cmath>

namespace elbowsim {

namespace {

struct Series {
  const Recording& rec;
  int time;
  double at(std::size_t row, int column) const { return rec.at(row, std::size_t(column)); }
  double dt(std::size_t row) const { return row == 0 ? 0.0 : at(row, time) - at(row - 1, time); }
  // Trapezoid integral of f(row) over time.
  template <typename F>
  double integral(F f) const {
    double sum = 0;
    for (std::size_t r = 1; r < rec.rows(); ++r) sum += 0.5 * dt(r) * (f(r) + f(r - 1));
    return sum;
  }
  double span() const { return rec.rows() > 1 ? at(rec.rows() - 1, time) - at(0, time) : 0.0; }
  double rms(int column) const {
    const double T = span();
    if (T <= 0) return std::abs(at(0, column));
    return std::sqrt(integral([&](std::size_t r) { return at(r, column) * at(r, column); }) / T);
  }
};

void hand_metrics(const Series& s, Metrics& m) {
  const int e = s.rec.column("hand_error");
  if (e < 0) return;
  m.has_task = true;
  m.hand_error_rms = s.rms(e);
  for (std::size_t r = 0; r < s.rec.rows(); ++r) m.hand_error_max = std::max(m.hand_error_max, s.at(r, e));
  m.hand_error_final = s.at(s.rec.rows() - 1, e);
}

void motor_metrics(const Model& model, const Series& s, Metrics& m) {
  if (!model.has_motor()) return;
  const int n = model.dof;
  m.energy_in_per_joint = m.current_peak = m.current_rms = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j) {
    const int i = s.rec.column("i" + std::to_string(j)), v = s.rec.column("v" + std::to_string(j));
    m.energy_in_per_joint[j] = s.integral([&](std::size_t r) { return s.at(r, v) * s.at(r, i); });
    for (std::size_t r = 0; r < s.rec.rows(); ++r)
      m.current_peak[j] = std::max(m.current_peak[j], std::abs(s.at(r, i)));
    m.current_rms[j] = s.rms(i);
  }
}

void contact_metrics(const Model& model, const Series& s, Metrics& m) {
  if (!model.effects.contact) return;
  m.has_contact = true;
  double sum = 0, weight = 0;
  m.elbow_force_min = 1e300;
  for (const Elbow& e : model.elbows) {
    const int f = s.rec.column("fn_" + e.name), rest = s.rec.column("rest_" + e.name);
    for (std::size_t r = 0; r < s.rec.rows(); ++r) {
      if (s.at(r, rest) < 0.5) continue;
      sum += s.at(r, f), weight += 1;
      m.elbow_force_min = std::min(m.elbow_force_min, s.at(r, f));
      m.elbow_force_max = std::max(m.elbow_force_max, s.at(r, f));
    }
  }
  m.elbow_force_mean = weight > 0 ? sum / weight : 0.0;
  if (weight == 0) m.elbow_force_min = 0;
  m.time_in_contact = s.integral([&](std::size_t r) {
    for (const Elbow& e : model.elbows)
      if (s.at(r, s.rec.column("rest_" + e.name)) > 0.5) return 1.0;
    return 0.0;
  });
}

}  // namespace

Metrics compute_metrics(const Model& model, const Recording& recording) {
  Metrics m;
  if (recording.rows() == 0) return m;
  const Series s{recording, recording.column("time")};
  hand_metrics(s, m);
  motor_metrics(model, s, m);
  contact_metrics(model, s, m);
  const std::size_t last = recording.rows() - 1;
  m.energy_in = recording.at(last, recording.column("E_in"));
  m.joule = recording.at(last, recording.column("E_joule"));
  return m;
}

}  // namespace elbowsim
