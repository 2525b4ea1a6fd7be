#include "render/playback.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/step_grid.hpp"

namespace elbowsim {

namespace {

// The first `rows` values of column c (a layout index), or empty when c < 0.
std::vector<double> column(const Recording& rec, int c, std::size_t rows) {
  std::vector<double> out;
  if (c < 0) return out;
  out.reserve(rows);
  for (std::size_t r = 0; r < rows; ++r) out.push_back(rec.at(r, std::size_t(c)));
  return out;
}

// Rows up to (not including) the first one whose time, angles or hand are
// not finite (a diverged run's). Other columns may be infinite by design:
// d_link<j> of a link without a solid.
std::size_t finite_rows(const Recording& rec) {
  const TrajectoryLayout& L = rec.layout;
  std::vector<int> pose{L.time(), L.hand(0), L.hand(1), L.hand(2)};
  for (int j = 0; j < L.dof(); ++j) pose.push_back(L.q(j));
  for (std::size_t r = 0; r < rec.rows(); ++r)
    for (const int c : pose)
      if (!std::isfinite(rec.at(r, std::size_t(c)))) return r;
  return rec.rows();
}

// Times at which a 0/1 column turns from 0 to 1 (rising) or from 1 to 0.
std::vector<double> edges(const std::vector<double>& flag, const std::vector<double>& time,
                          bool rising) {
  std::vector<double> out;
  for (std::size_t r = 1; r < flag.size(); ++r)
    if ((flag[r] > 0.5) == rising && (flag[r - 1] > 0.5) != rising) out.push_back(time[r]);
  return out;
}

// The last of `times` at or before t; -inf if none.
double last_before(const std::vector<double>& times, double t) {
  double out = -std::numeric_limits<double>::infinity();
  for (double x : times)
    if (x <= t) out = x;
  return out;
}

}  // namespace

Playback::Playback(const Model& model, const Recording& rec) : dof_(model.dof) {
  const TrajectoryLayout& L = rec.layout;
  if (L.dof() != dof_)
    throw std::invalid_argument("the trajectory has " + std::to_string(L.dof()) +
                                " joints, the model " + std::to_string(dof_));
  const std::size_t rows = finite_rows(rec);
  time_ = column(rec, L.time(), rows);
  if (time_.empty()) throw std::invalid_argument("the trajectory has no (finite) samples");
  for (int j = 0; j < dof_; ++j) q_.push_back(column(rec, L.q(j), rows));
  for (int axis = 0; axis < 3; ++axis) hand_.push_back(column(rec, L.hand(axis), rows));
  for (const Elbow& e : model.elbows) {
    const int k = L.elbow(e.name);  // -1: contact was off, nothing recorded
    fn_.push_back(column(rec, k < 0 ? -1 : L.elbow_force(k), rows));
    rest_.push_back(column(rec, k < 0 ? -1 : L.elbow_resting(k), rows));
    distance_.push_back(column(rec, k < 0 ? -1 : L.elbow_distance(k), rows));
    landings_.push_back(edges(rest_.back(), time_, true));
    lifts_.push_back(edges(rest_.back(), time_, false));
  }
  if (L.has_contact())
    for (int j = 0; j < dof_; ++j) {
      link_fn_.push_back(column(rec, L.link_force(j), rows));
      link_rest_.push_back(column(rec, L.link_resting(j), rows));
    }
  energy_in_ = column(rec, L.energy(Energy::electrical_in), rows);
  // Hand path: drop samples closer than 1 mm to the last kept one.
  for (std::size_t r = 0; !hand_.empty() && r < rows; ++r) {
    const Eigen::Vector3d p(hand_[0][r], hand_[1][r], hand_[2][r]);
    if (path_rows_.empty()) {
      path_rows_.push_back(r);
      continue;
    }
    const std::size_t k = path_rows_.back();
    if ((p - Eigen::Vector3d(hand_[0][k], hand_[1][k], hand_[2][k])).norm() >= 1e-3)
      path_rows_.push_back(r);
  }
  // Desired hand path: all of it, thinned the same way, the last sample kept.
  std::vector<std::vector<double>> d;
  for (int axis = 0; axis < 3; ++axis) d.push_back(column(rec, L.hand_desired(axis), rows));
  if (!d[0].empty() && !d[1].empty() && !d[2].empty()) {
    for (std::size_t r = 0; r < rows; ++r) {
      const Eigen::Vector3d p(d[0][r], d[1][r], d[2][r]);
      desired_all_.push_back(p);
      if (desired_path_.empty() || (p - desired_path_.back()).norm() >= 1e-3 || r + 1 == rows)
        desired_path_.push_back(p);
    }
  }
}

Playback::Bracket Playback::bracket(double t) const {
  if (t <= time_.front() || time_.size() == 1) return {0, 0};
  if (t >= time_.back()) return {time_.size() - 1, 0};
  // Last row with time <= t (rows may repeat a time at events).
  const auto it = std::upper_bound(time_.begin(), time_.end(), t);
  const std::size_t row = std::size_t(it - time_.begin()) - 1;
  const double span = time_[row + 1] - time_[row];
  return {row, span > 0 ? (t - time_[row]) / span : 0.0};
}

double Playback::lerp(const std::vector<double>& c, const Bracket& b) const {
  if (b.alpha == 0) return c[b.row];
  return (1 - b.alpha) * c[b.row] + b.alpha * c[b.row + 1];
}

PlaybackState Playback::at(double t) const {
  const Bracket b = bracket(t);
  PlaybackState s;
  s.t = std::clamp(t, time_.front(), time_.back());
  s.q.resize(dof_);
  for (int j = 0; j < dof_; ++j) s.q[j] = lerp(q_[j], b);
  if (!hand_.empty())
    s.hand = Eigen::Vector3d(lerp(hand_[0], b), lerp(hand_[1], b), lerp(hand_[2], b));
  for (std::size_t k = 0; k < fn_.size(); ++k) {
    ElbowSample e;
    if (!fn_[k].empty()) e.fn = lerp(fn_[k], b);
    if (!rest_[k].empty()) e.resting = rest_[k][b.row] > 0.5;
    if (!distance_[k].empty()) e.distance = lerp(distance_[k], b);
    e.landed_at = last_before(landings_[k], s.t);
    e.lifted_at = last_before(lifts_[k], s.t);
    s.elbows.push_back(e);
  }
  for (std::size_t j = 0; j < link_fn_.size(); ++j)
    s.links.push_back({lerp(link_fn_[j], b), link_rest_[j][b.row] > 0.5});
  if (!energy_in_.empty()) s.energy_in = lerp(energy_in_, b);
  return s;
}

Eigen::VectorXd Playback::q(std::size_t row) const {
  Eigen::VectorXd out(dof_);
  for (int j = 0; j < dof_; ++j) out[j] = q_[j][row];
  return out;
}

std::vector<Eigen::Vector3d> Playback::hand_path(double t) const {
  std::vector<Eigen::Vector3d> path;
  if (hand_.empty()) return path;
  for (std::size_t r : path_rows_) {
    if (time_[r] > t) break;
    path.emplace_back(hand_[0][r], hand_[1][r], hand_[2][r]);
  }
  const Bracket b = bracket(t);
  path.emplace_back(lerp(hand_[0], b), lerp(hand_[1], b), lerp(hand_[2], b));
  return path;
}

std::vector<Eigen::Vector3d> Playback::full_hand_path(double t) const {
  std::vector<Eigen::Vector3d> path;
  if (hand_.empty() || hand_[0].empty()) return path;
  const Bracket b = bracket(t);
  for (std::size_t r = 0; r <= b.row; ++r) path.emplace_back(hand_[0][r], hand_[1][r], hand_[2][r]);
  if (b.alpha > 0) path.emplace_back(lerp(hand_[0], b), lerp(hand_[1], b), lerp(hand_[2], b));
  return path;
}

double Playback::max_force() const {
  double out = 0;
  for (const std::vector<double>& f : fn_)
    for (double x : f) out = std::max(out, x);
  for (const std::vector<double>& f : link_fn_)
    for (double x : f) out = std::max(out, x);
  return out;
}

int frame_count(double duration, double fps) {
  return static_cast<int>(step_grid::whole_spacings(std::max(duration, 0.0) * fps)) + 1;
}

}  // namespace elbowsim
