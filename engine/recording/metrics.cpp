#include "engine/recording/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace elbowsim {

namespace {

struct Vocabulary {
  const char* name;
  const char* unit;
  Metric::Shape shape;
};

constexpr Vocabulary kVocabulary[] = {
#define ELBOWSIM_METRIC_ENTRY(name, unit, shape, what) {#name, unit, Metric::Shape::shape},
    ELBOWSIM_METRICS(ELBOWSIM_METRIC_ENTRY)
#undef ELBOWSIM_METRIC_ENTRY
};

const Vocabulary& vocabulary(const char* name) {
  for (const Vocabulary& v : kVocabulary)
    if (std::string_view(name) == v.name) return v;
  throw std::logic_error(std::string("no metric ") + name + " in ELBOWSIM_METRICS");
}

// Sampled series of one recording, with the integrals metrics need.
struct Series {
  const Recording& rec;
  std::vector<double> t;

  explicit Series(const Recording& r) : rec(r), t(r.series(r.layout.time())) {}
  std::size_t rows() const { return t.size(); }
  double at(std::size_t row, int column) const { return rec.at(row, std::size_t(column)); }
  double span() const { return rows() > 1 ? t.back() - t.front() : 0.0; }
  // Trapezoid integral of f(row) over time.
  template <typename F>
  double integral(F f) const {
    double sum = 0;
    for (std::size_t r = 1; r < rows(); ++r) sum += 0.5 * (t[r] - t[r - 1]) * (f(r) + f(r - 1));
    return sum;
  }
  // Time for which flag(row) holds, each sample holding until the next.
  template <typename F>
  double held(F flag) const {
    double sum = 0;
    for (std::size_t r = 0; r + 1 < rows(); ++r)
      if (flag(r)) sum += t[r + 1] - t[r];
    return sum;
  }
  double rms(int column) const {
    const double T = span();
    if (T <= 0) return std::abs(at(0, column));
    return std::sqrt(integral([&](std::size_t r) { return at(r, column) * at(r, column); }) / T);
  }
  double max_abs(int column) const {
    double m = 0;
    for (std::size_t r = 0; r < rows(); ++r) m = std::max(m, std::abs(at(r, column)));
    return m;
  }
};

// The metric `name` with its values (its unit and shape from the vocabulary).
void add(Metrics& m, const char* name, std::vector<double> values) {
  const Vocabulary& v = vocabulary(name);
  m.list.push_back({name, v.unit, v.shape, std::move(values)});
}

void add(Metrics& m, const char* name, double value) { add(m, name, std::vector<double>{value}); }

void hand_metrics(const Series& s, Metrics& m) {
  const TrajectoryLayout& L = s.rec.layout;
  const int e = L.hand_error();
  if (e >= 0) {
    add(m, metric::hand_error_rms, s.rms(e));
    add(m, metric::hand_error_max, s.max_abs(e));
    add(m, metric::hand_error_final, s.at(s.rows() - 1, e));
  }
  double length = 0;
  for (std::size_t r = 1; r < s.rows(); ++r)
    length += std::hypot(s.at(r, L.hand(0)) - s.at(r - 1, L.hand(0)),
                         s.at(r, L.hand(1)) - s.at(r - 1, L.hand(1)),
                         s.at(r, L.hand(2)) - s.at(r - 1, L.hand(2)));
  add(m, metric::hand_path_length, length);
}

void energy_metrics(const Series& s, Metrics& m) {
  const TrajectoryLayout& L = s.rec.layout;
  const std::size_t last = s.rows() - 1;
  add(m, metric::energy_in, s.at(last, L.energy(Energy::electrical_in)));
  add(m, metric::joule, s.at(last, L.energy(Energy::joule)));
  if (L.energy(Energy::drawn) < 0) return;
  add(m, metric::energy_drawn, s.at(last, L.energy(Energy::drawn)));
  add(m, metric::energy_regenerated, s.at(last, L.energy(Energy::regenerated)));
}

void motor_metrics(const Series& s, Metrics& m) {
  const TrajectoryLayout& L = s.rec.layout;
  if (!L.has_motors()) return;
  const int n = L.dof();
  auto power = [&](std::size_t r) {
    double p = 0;
    for (int j = 0; j < n; ++j) p += s.at(r, L.voltage(j)) * s.at(r, L.current(j));
    return p;
  };
  double peak = -INFINITY;
  for (std::size_t r = 0; r < s.rows(); ++r) peak = std::max(peak, power(r));
  add(m, metric::power_peak, peak);
  std::vector<double> energy(n), current_peak(n), current_rms(n);
  for (int j = 0; j < n; ++j) {
    const int i = L.current(j), v = L.voltage(j);
    energy[j] = s.integral([&](std::size_t r) { return s.at(r, v) * s.at(r, i); });
    current_peak[j] = s.max_abs(i);
    current_rms[j] = s.rms(i);
  }
  add(m, metric::energy_in_per_joint, energy);
  add(m, metric::current_peak, current_peak);
  add(m, metric::current_rms, current_rms);
}

void contact_metrics(const Series& s, Metrics& m) {
  const TrajectoryLayout& L = s.rec.layout;
  if (!L.has_contact()) return;
  const int elbows = L.elbows();
  auto resting = [&](std::size_t r, int k) { return s.at(r, L.elbow_resting(k)) >= 0.5; };
  double sum = 0, count = 0, low = INFINITY, high = 0;
  std::vector<double> fraction(elbows), peak(elbows), drift(elbows);
  for (int k = 0; k < elbows; ++k) {
    for (std::size_t r = 0; r < s.rows(); ++r) {
      const double f = s.at(r, L.elbow_force(k));
      peak[k] = std::max(peak[k], std::abs(f));
      if (!resting(r, k)) continue;
      sum += f, count += 1, low = std::min(low, f), high = std::max(high, f);
      drift[k] = std::max(drift[k], std::abs(s.at(r, L.elbow_distance(k))));
    }
    const double T = s.span();
    const double held = s.held([&](std::size_t r) { return resting(r, k); });
    fraction[k] = T > 0 ? held / T : (resting(0, k) ? 1.0 : 0.0);
  }
  add(m, metric::elbow_force_mean, count > 0 ? sum / count : 0.0);
  add(m, metric::elbow_force_min, count > 0 ? low : 0.0);
  add(m, metric::elbow_force_max, high);
  add(m, metric::time_in_contact, s.held([&](std::size_t r) {
    for (int k = 0; k < elbows; ++k)
      if (resting(r, k)) return true;
    return false;
  }));
  add(m, metric::rest_fraction, fraction);
  add(m, metric::elbow_force_peak, peak);
  add(m, metric::elbow_drift_max, drift);
}

// The columns of one contact body: its force, its resting flag and, with
// friction, its friction loss so far.
struct BodyColumns {
  int force, resting, friction;
};

// Elbows by name, then the links whose solid has a finite distance somewhere.
std::vector<BodyColumns> contact_bodies(const Series& s, Metrics& m) {
  const TrajectoryLayout& L = s.rec.layout;
  std::vector<BodyColumns> columns;
  for (int k = 0; k < L.elbows(); ++k) {
    m.bodies.push_back(L.groups().elbows[std::size_t(k)]);
    m.body_links.push_back(-1);
    columns.push_back({L.elbow_force(k), L.elbow_resting(k), L.elbow_friction(k)});
  }
  for (int j = 0; j < L.dof(); ++j) {
    bool solid = false;
    for (std::size_t r = 0; r < s.rows() && !solid; ++r) solid = std::isfinite(s.at(r, L.link_distance(j)));
    if (!solid) continue;
    m.bodies.push_back("link" + std::to_string(j));
    m.body_links.push_back(j);
    columns.push_back({L.link_force(j), L.link_resting(j), L.link_friction(j)});
  }
  return columns;
}

// Per contact body: rest share, time-weighted mean force while resting (each
// resting sample holds until the next), peak force, friction work.
void body_metrics(const Series& s, Metrics& m) {
  if (!s.rec.layout.has_contact()) return;
  const std::vector<BodyColumns> bodies = contact_bodies(s, m);
  const std::size_t count = bodies.size();
  std::vector<double> fraction(count), mean(count), peak(count), work(count);
  const double T = s.span();
  for (std::size_t b = 0; b < count; ++b) {
    const BodyColumns& c = bodies[b];
    auto resting = [&](std::size_t r) { return s.at(r, c.resting) >= 0.5; };
    double held = 0, impulse = 0;
    for (std::size_t r = 0; r + 1 < s.rows(); ++r)
      if (resting(r)) {
        held += s.t[r + 1] - s.t[r];
        impulse += s.at(r, c.force) * (s.t[r + 1] - s.t[r]);
      }
    for (std::size_t r = 0; r < s.rows(); ++r) peak[b] = std::max(peak[b], std::abs(s.at(r, c.force)));
    fraction[b] = T > 0 ? held / T : (resting(0) ? 1.0 : 0.0);
    mean[b] = held > 0 ? impulse / held : (resting(0) ? s.at(0, c.force) : 0.0);
    if (c.friction >= 0) work[b] = s.at(s.rows() - 1, c.friction);
  }
  add(m, metric::body_rest_fraction, fraction);
  add(m, metric::body_force_mean, mean);
  add(m, metric::body_force_peak, peak);
  if (s.rec.layout.has_body_friction()) add(m, metric::body_friction_work, work);
}

}  // namespace

const Metric* Metrics::find(const std::string& name) const {
  for (const Metric& m : list)
    if (m.name == name) return &m;
  return nullptr;
}

double Metrics::operator[](const std::string& name) const {
  const Metric* m = find(name);
  if (!m || m->shape != Metric::Shape::one) throw std::out_of_range("no metric " + name);
  return m->values[0];
}

std::string metric_unit(const std::string& name) {
  for (const Vocabulary& v : kVocabulary)
    if (name == v.name) return v.unit;
  return "";
}

bool is_metric(const std::string& name) {
  for (const Vocabulary& v : kVocabulary)
    if (name == v.name) return true;
  return false;
}

Metrics compute_metrics(const Recording& recording) {
  Metrics m;
  if (recording.rows() == 0) return m;
  m.elbows = recording.layout.groups().elbows;
  const Series s(recording);
  add(m, metric::samples, double(s.rows()));
  hand_metrics(s, m);
  energy_metrics(s, m);
  motor_metrics(s, m);
  contact_metrics(s, m);
  body_metrics(s, m);
  return m;
}

}  // namespace elbowsim
