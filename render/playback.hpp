// A recorded run played back at any time: the columns the renderer draws,
// interpolated linearly between recorded samples (trajectory.csv or the
// Recording in memory). Frames are sampled by simulation time, independent of
// the physics step and of output.every.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

struct ElbowSample {
  double fn = 0;         // [N] normal force, linear between samples (0 if not recorded)
  bool resting = false;  // held from the sample at or before t (rest_<name>)
  // [s] time of the last touchdown (rest 0 -> 1 between samples) at or before t;
  // -inf if none. An elbow resting from t = 0 has not landed.
  double landed_at = -std::numeric_limits<double>::infinity();
  // [s] time of the last lift-off (rest 1 -> 0) at or before t; -inf if none.
  double lifted_at = -std::numeric_limits<double>::infinity();
  // [m] signed distance from the sphere to the table (d_<name>), linear
  // between samples; unset if not recorded.
  std::optional<double> distance;
};

// A link's own solid against the table (fn_link<j>, rest_link<j>).
struct LinkContactSample {
  double fn = 0;         // [N] normal force on the link's solid, linear between samples
  bool resting = false;  // held from the sample at or before t
};

struct PlaybackState {
  double t = 0;                         // [s]
  Eigen::VectorXd q;                    // [dof] joint angles [rad]
  std::optional<Eigen::Vector3d> hand;  // [m] world, if recorded
  std::vector<ElbowSample> elbows;      // [model.elbows]
  std::vector<LinkContactSample> links;  // [dof] when link contact was recorded, else empty
  std::optional<double> energy_in;      // [J] E_in so far, if recorded
};

class Playback {
 public:
  // Needs columns time and q0..q<dof-1>; uses hand_x/y/z, hand_d_x/y/z,
  // fn_/d_/rest_<elbow> and E_in when present. Rows after the first non-finite value are dropped
  // (a diverged run). Throws std::invalid_argument naming a missing column or
  // an empty recording.
  Playback(const Model& model, const Recording& recording);

  double start_time() const { return time_.front(); }  // [s]
  double end_time() const { return time_.back(); }     // [s]
  std::size_t samples() const { return time_.size(); }
  double time(std::size_t row) const { return time_[row]; }

  // The state at time t [s], clamped to the recorded span.
  PlaybackState at(double t) const;
  // Joint angles of recorded row `row` [rad].
  Eigen::VectorXd q(std::size_t row) const;
  // The hand's path from the start up to t: recorded hand positions at least
  // 1 mm apart, ending with the interpolated position at t. Empty if the hand
  // was not recorded.
  std::vector<Eigen::Vector3d> hand_path(double t) const;
  // The same with every recorded position (for the magnified inset).
  std::vector<Eigen::Vector3d> full_hand_path(double t) const;
  // Every recorded desired hand position (hand_d_*); empty if not recorded.
  const std::vector<Eigen::Vector3d>& full_desired_hand_path() const { return desired_all_; }
  // The largest recorded normal force of any elbow or link [N] (0 if none recorded).
  double max_force() const;
  // The whole desired hand path (hand_d_x/y/z), independent of t: the first
  // sample, then samples at least 1 mm from the last kept one, and always the
  // last sample. Empty if the recording has no desired hand position.
  const std::vector<Eigen::Vector3d>& desired_hand_path() const { return desired_path_; }

 private:
  struct Bracket {
    std::size_t row;  // sample at or before t
    double alpha;     // weight of row + 1, in [0, 1)
  };
  Bracket bracket(double t) const;
  double lerp(const std::vector<double>& column, const Bracket& b) const;

  int dof_;
  std::vector<double> time_;
  std::vector<std::vector<double>> q_;         // [dof][rows]
  std::vector<std::vector<double>> hand_;      // [3][rows] or empty
  std::vector<std::vector<double>> fn_;        // [elbows][rows] (empty column: not recorded)
  std::vector<std::vector<double>> rest_;      // [elbows][rows]
  std::vector<std::vector<double>> distance_;  // [elbows][rows] (empty column: not recorded)
  std::vector<std::vector<double>> landings_;  // [elbows] touchdown times
  std::vector<std::vector<double>> lifts_;     // [elbows] lift-off times
  std::vector<std::vector<double>> link_fn_;   // [dof][rows] or empty (no link contact recorded)
  std::vector<std::vector<double>> link_rest_; // [dof][rows] or empty
  std::vector<double> energy_in_;              // [rows] or empty
  std::vector<std::size_t> path_rows_;         // rows kept for hand_path
  std::vector<Eigen::Vector3d> desired_path_;  // [m] world, or empty
  std::vector<Eigen::Vector3d> desired_all_;   // [m] world, every row, or empty
};

// Number of frames for `duration` [s] at `fps`: one at t = 0 and one every
// 1/fps up to and including the end, floor(duration fps) + 1.
int frame_count(double duration, double fps);

}  // namespace elbowsim
