// Per-run contact state and scratch (effects.contact), part of Data. Sized once
// from the model for every row count p = 0 .. capacity, so a contact step
// allocates nothing: the rows of M* for the p resting slots live in the flat
// members below, and changing p swaps them with a pre-sized set (swap moves
// pointers, it does not allocate). A slot (primitives.hpp) is a place where a
// ball of the arm (an elbow, a capsule's end or nearest interior point, a
// link sphere, a box corner) may touch a table box.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <memory>
#include <utility>
#include <vector>

#include "engine/contact/friction_lcp.hpp"
#include "engine/contact/geometry.hpp"
#include "engine/contact/lemke.hpp"
#include "engine/contact/primitives.hpp"
#include "engine/eigen_types.hpp"

namespace elbowsim {

class CollisionWorld;

// One slot's closest approach to its box at the last detection.
struct SlotContact {
  bool near = false;       // within the broad phase's reach; else distance is +inf
  double distance = 0;     // [m] signed: the slot's ball to the box surface, < 0 penetrating
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, world, from the box toward the ball
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // [m] world, the closest point of the box surface
  Eigen::Vector3d local = Eigen::Vector3d::Zero();    // [m] the ball's centre in its link's frame
  BoxFeature feature = BoxFeature::face;
  Eigen::Vector3d edge = Eigen::Vector3d::Zero();     // unit, world, along an edge (feature edge)
};

// A sticking slot's tangent row (friction law coulomb): rows p_n .. p - 1 of
// the contact system follow the p_n normal rows.
struct TangentRow {
  int slot = -1;
  int normal_row = -1;  // the slot's normal row
  int axis = 0;         // 0: t1, 1: t2 (friction.hpp, tangent_basis)
};

// The rows of M* for p rows (constraint_rows.hpp): p_n normal rows, then the
// tangent rows of sticking slots; and the Schur solve's p-sized scratch
// (constrained_dynamics.hpp).
struct ContactRows {
  Eigen::MatrixXd Jc;      // [p x n] rows j_ck = n_k^T J_k (eq. 8); a tangent row t^T J_p
  Eigen::MatrixXd Jf;      // [p x n] Jc - mu s^T J_p: where the row's force acts, with sliding friction (eq. 9)
  Eigen::VectorXd gamma;   // [p] -n^T Jdot qd (eq. 15, 31), plus Baumgarte terms
  Eigen::VectorXd C, Cd;   // [p] constraint value [m] and rate [m/s] (a tangent row: 0 and its slip)
  Eigen::VectorXd fn;      // [p] row forces [N]: normal ones > 0 when the table pushes; tangent ones
  Eigen::VectorXd slide;   // [p] sliding speed of each contact point [m/s]
  Eigen::VectorXd Jf_qd;   // [p] scratch: Jf qd (friction power)
  Eigen::MatrixXd Y, Z;    // [n x p] scratch: L^-1 Jc^T, L^-1 Jf^T
  Eigen::MatrixXd A;       // [p x p] Jc M^-1 Jf^T (the paper's M~, eq. 49)
  Eigen::VectorXd rhs;     // [p] scratch
  Eigen::VectorXd lcp_b, lcp_f, lcp_w;  // [p] the active-set LCP: w = A f + b

  ContactRows() = default;
  ContactRows(int p, int n);
  void swap(ContactRows& other);
};

// Factorisations and scratch for one m x m system of contact rows (m fixed
// per workspace; one workspace per m = 1 .. elbows).
struct SolverWorkspace {
  Eigen::LLT<Eigen::MatrixXd> llt;                          // A without friction (symmetric)
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;                  // A with friction
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;       // [m x m] minimum-norm solves
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> rows_rank; // [m x n] rank of Jc (warnings)
  Eigen::MatrixXd block;         // [m x m] an LCP block, an impact's Delassus matrix
  Eigen::VectorXd rhs, x, work;  // [m]
  Eigen::VectorXd work_cols;     // [m] Householder scratch of the minimum-norm solve
  Eigen::MatrixXd Jc;            // [m x n] impact rows
  Eigen::MatrixXd MinvJt;        // [n x m] (M + Jm)^-1 Jc^T (impacts, projection)
  Eigen::VectorXd dx;            // [n] a correction of q or qd (projection)
  // An impact on m rows (impact.hpp): its LCP and result, kept here so that it allocates nothing.
  Eigen::MatrixXd A;                                                   // [m x m]
  Eigen::VectorXd b, impulse, speed_before, speed_after, energy_lost, w;  // [m]

  SolverWorkspace(int m, int n);
};

struct ContactData {
  ContactData() = default;
  // Slots from `geometry` (primitives.hpp), rows for up to `capacity` of them.
  // `cone_capacity`: LCP variables of the stick-slip problem (0 without
  // Coulomb friction).
  ContactData(ContactGeometry geometry, int boxes, int n, int capacity, int cone_capacity = 0);

  ContactGeometry geometry;               // primitives and slots (fixed for the run)
  // --- which slots rest -----------------------------------------------------
  std::vector<char> resting;              // [slots] row of M* on
  std::vector<int> active;                // [p_n] slot index of each normal row (capacity: `capacity`)
  std::vector<TangentRow> tangent_rows;   // [p - p_n] tangent rows of sticking slots (coulomb)
  // --- detection (contact/detection.hpp), at the last detected state -------
  std::vector<SlotContact> detected;      // [slots]
  std::vector<int> near_pairs;            // primitive * boxes + box, near at the last detection
  Eigen::VectorXd detected_q;             // [n] the q of the last detection (NaN: none yet)
  // --- the step's frames: the feature each touching slot rests on, frozen
  // when the step starts (freeze_frames, detection.hpp); its rows follow the
  // ball on that feature (a face's plane, an edge's line, a corner's point).
  std::vector<Eigen::Vector3d> normal;    // [slots] table normal at the slot (world, unit)
  std::vector<Eigen::Vector3d> surface;   // [slots] a point of the feature [m]
  std::vector<BoxFeature> feature;        // [slots]
  std::vector<Eigen::Vector3d> edge;      // [slots] unit edge direction (feature edge)
  // [slots] signed distance when the step started [m]: a free slot already in
  // the table by rounding lands when it goes deeper than this (events.cpp)
  std::vector<double> start_distance;
  // --- Coulomb friction (law coulomb): each resting slot sticks or slips ----
  std::vector<char> sticking;             // [slots] 1: tangent rows hold its contact point
  std::vector<Eigen::Vector3d> slip;      // [slots] unit world direction a sliding slot slips in
  std::vector<char> slip_stopped;         // [slots] 1: its slip's stop was located (it may stick)
  std::vector<char> may_stick, was_sticking;  // [slots] scratch of the mode decision (stick_slip.hpp)
  // --- compliant pads (pad.hpp): a released pad's surface comes back up ----
  std::vector<double> pad_release_depth;  // [slots] [m] its depth where it let go (0: relaxed)
  std::vector<double> pad_release_time;   // [slots] [s] when
  double pad_relaxed = 0;                 // [J] lost by pads that relaxed before they were pressed again
  FrictionLcpScratch cones;               // the stick-slip LCP (friction_lcp.hpp)
  Eigen::VectorXd cone_slip;              // [cone capacity] its slips sigma
  // --- rows of M* for the p rows (flat: the ContactRows of size p) ---------
  Eigen::MatrixXd Jc, Jf;
  Eigen::VectorXd gamma, C, Cd, fn, slide, Jf_qd;
  Eigen::MatrixXd Y, Z, A;
  Eigen::VectorXd rhs, lcp_b, lcp_f, lcp_w;
  Eigen::VectorXd a_free;        // [n] scratch: L^-1 (tau - B_J)
  Eigen::VectorXd qd_before_impact;  // [n] scratch: the rates an impact started from
  Matrix3Xd J3;                  // [3 x n] scratch point Jacobian
  // [3 x n] scratch of constraint_rows: each link's angular velocity and, with
  // qdd = 0, angular acceleration and its origin's acceleration (when
  // bias_torques() has not left them in Data at this state)
  Matrix3Xd link_omega, link_omega_dot, link_acc;
  bool rates_in_data = false;  // constraint_rows: read them from bias_torques()' pass instead
  Matrix3Xd row_normal;          // [3 x capacity] each normal row's normal at the last constraint_rows
  Matrix3Xd row_friction;        // [3 x capacity] its sliding friction force per newton of fn (world)
  bool dependent = false;        // last solve met dependent rows
  // --- run totals -----------------------------------------------------------
  double impact_loss = 0;        // [J] kinetic energy lost in impacts so far
  double projection_energy = 0;  // [J] stored-energy change made by projection so far
  double max_abs_C = 0;          // [m] over resting elbows, sampled after each step
  double max_abs_Cd = 0;         // [m/s]
  long dependent_steps = 0;      // steps whose active rows were dependent
  bool dependent_warned = false; // the dependent-rows warning was given
  int last_located_slot = -1;    // the slot of the last event located inside a step (stall messages)
  // --- scratch of the stages (capacities reserved) ---------------------------
  std::vector<int> candidates, landing, impact_rows;  // slot indices
  std::vector<std::pair<int, int>> events_found;      // slot and event at a step's end (events.cpp)
  std::vector<bool> lcp_active;                       // [<= capacity]
  std::vector<int> lcp_index;                         // [<= capacity]
  std::vector<SolverWorkspace> solvers;               // [capacity + 1], index m
  LemkeScratch lemke;                                 // [capacity]
  // The collision world (Bullet), built by reset() for a contact scene.
  std::shared_ptr<CollisionWorld> world;

  // Puts the rows for p rows into the flat members (no allocation).
  void use_rows(int p);
  int rows() const { return rows_in_use_; }
  int normal_rows() const { return static_cast<int>(active.size()); }
  int capacity() const { return static_cast<int>(solvers.size()) - 1; }  // most rows at once
  SolverWorkspace& solver(int m) { return solvers[static_cast<std::size_t>(m)]; }
  int slots() const { return static_cast<int>(geometry.slots.size()); }
  const ContactSlot& slot(int k) const { return geometry.slots[static_cast<std::size_t>(k)]; }
  const Primitive& primitive_of(int k) const {
    return geometry.primitives[static_cast<std::size_t>(slot(k).primitive)];
  }

 private:
  std::vector<ContactRows> spare_;  // [capacity + 1] index p; the in-use size holds empty matrices
  int rows_in_use_ = -1;            // p of the flat members
  void swap_rows(ContactRows& set);
};

}  // namespace elbowsim
