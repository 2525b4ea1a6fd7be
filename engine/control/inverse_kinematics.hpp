// Constrained inverse kinematics for the hand task: the hand on its target
// and the declared elbows on the table (or at a clearance above it, or held
// at a point of it) as equality rows; the remaining redundancy goes to a
// preferred posture.
#pragma once

#include <stdexcept>
#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

// A flat table face under a point: outward unit normal and a point on it.
struct TablePlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  int box = -1;       // the table box whose top it is
  bool over = false;  // the point asked about lies over that box's top face
};

// The top face (box +z) of the table box whose footprint holds `p`, or of the
// box whose centre is nearest when none does.
TablePlane table_plane_under(const Model& model, const Eigen::Vector3d& p);

struct IkProblem {
  Eigen::Vector3d hand;            // [m] world target of the hand point
  std::vector<int> elbows;         // elbow indices kept at `clearance` above their plane
  std::vector<TablePlane> planes;  // one per elbow
  double clearance = 0.0;          // [m] sphere surface above the table
  // Resting elbows that stick (Coulomb friction): each elbow's centre held at
  // its point [m, world] (3 rows), not only on its plane (1 row: it may slide).
  std::vector<Eigen::Vector3d> pins;
  Eigen::VectorXd posture;       // [n] preferred q
  double posture_gain = 1.0;     // null-space step toward the posture per iteration
  Eigen::VectorXd q_min, q_max;  // [n] limits, or empty
};

struct IkResult {
  Eigen::VectorXd q;
  double hand_residual = 0;   // [m] |target - hand|
  double elbow_residual = 0;  // [m] max |C_k - clearance|
  int iterations = 0;
  double tolerance = 0;     // [m] rows within this are met: 1e-8 x arm_size (10 nm per metre)
  bool rows_met = false;    // hand and elbow residuals within `tolerance`
  // The polish could lower the residual no further (a local minimum of the
  // rows' error): with rows not met, the target is out of reach (of the arm,
  // or within its joint limits); not stationary and not met: the iterations
  // ran out while it still fell (did not converge).
  bool stationary = false;
  // Singular values of the rows at q, largest first (rows that no joint
  // moves, like y of a planar arm, left out). Against a regular pose's rank,
  // one falling to ~0 marks a singular pose (an arm stretched or folded);
  // rows dependent at every pose (two pins of an elbow on link 0) are not.
  Eigen::VectorXd singular_values;
};

// The number of singular values above 1e-9 of the largest (a pose's rank).
int numerical_rank(const Eigen::VectorXd& singular_values);

// singular_values[rank - 1] / singular_values[0]: how near the pose is to
// losing one of the `rank` directions a regular pose has (1: none lost).
double conditioning(const Eigen::VectorXd& singular_values, int rank);

// A length scale of the arm [m]: the sum of its joint offsets and the hand
// point's distance from its link (the longest reach it could have).
double arm_size(const Model& model);

// Gauss-Newton with a damped least-squares pseudo-inverse from the thin SVD
// of the row Jacobian (damping grows as the smallest singular value falls
// below 1e-3 of the largest, as near a stretched arm), plus the posture step
// projected into the exact null space of the rows (gain posture_gain while
// far, up to 1 in the last 1e-3 rad: see follow_posture), until the rows are
// met to rounding and the posture step vanishes; then undamped, posture-free
// iterations polish the rows to ~1e-13 m. Starts from q0.
IkResult solve_ik(const Model& model, Data& data, const IkProblem& problem,
                  const Eigen::VectorXd& q0);

// The task cannot be followed: names the time and the distance missed.
class PlanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace elbowsim
