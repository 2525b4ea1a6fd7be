// The abstract scene of one frame: what to draw, where, in which colour, with
// no GL, so tests can read it (after MuJoCo's mjv_updateScene). Built from the
// Model and one played-back state; gl_renderer.hpp draws it, tests read it.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "engine/data.hpp"
#include "engine/model.hpp"
#include "render/playback.hpp"

namespace elbowsim {

struct Color {
  float r = 0, g = 0, b = 0;  // display RGB, each in [0, 1]
};

// Box with edge lengths `size` in its own frame, centred and rotated.
struct Box {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();        // [m] world
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // box frame -> world
  Eigen::Vector3d size = Eigen::Vector3d::Ones();          // [m] full edge lengths
  Color color;
};

struct Sphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // [m] world
  double radius = 0;                                 // [m]
  Color color;
};

// A segment a-b swept by a sphere of `radius` (a link).
struct Capsule {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();  // [m] world
  double radius = 0;                                                         // [m]
  Color color;
};

// A solid, capped cylinder from a to b (a joint housing).
struct Cylinder {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();  // [m] world
  double radius = 0;                                                         // [m]
  Color color;
};

// An arrow from tail to tip (shaft and cone head); its length |tip - tail|
// is the force times SceneOptions::force_scale.
struct Arrow {
  Eigen::Vector3d tail = Eigen::Vector3d::Zero(), tip = Eigen::Vector3d::Zero();  // [m] world
  double radius = 0;  // [m] of the shaft
  Color color;
  int elbow = -1;    // index into Model::elbows; -1 for a link's own solid
  int link = -1;     // the link whose own solid the table pushes (elbow -1)
  double force = 0;  // [N]
};

// A polyline drawn as a thin tube.
struct Polyline {
  std::vector<Eigen::Vector3d> points;  // [m] world
  double radius = 0;                    // [m]
  Color color;
};

// Thin lines (1 px): each pair of points is one segment.
struct LineSet {
  std::vector<Eigen::Vector3d> points;  // [m] world, 2 per segment
  Color color;
};

// landed: resting, touched down recently; lifted: free, left the table recently.
enum class ElbowState { free, resting, landed, lifted };

struct ElbowMarker {
  Sphere sphere;
  ElbowState state = ElbowState::free;
};

// Where an elbow meets the table, drawn on the table top: a ring around the
// foot of the sphere (the table point under its centre, along the table's
// normal) in the elbow's state colour, and for an elbow off the table a
// dashed drop line from the sphere's lowest point down to the foot.
struct ContactCue {
  int elbow = -1;                                     // index into Model::elbows
  Eigen::Vector3d foot = Eigen::Vector3d::Zero();     // [m] world, on the table top
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // table normal at the foot
  double radius = 0;                                  // [m] of the ring (centre line)
  double gap = 0;                                     // [m] sphere to table; 0 when resting
  Color color;
  std::vector<Eigen::Vector3d> dashes;  // [m] world, 2 points per dash; empty when resting
};

// Shadow mapping from the key light (lighting.hpp) over `bounds`: what casts
// and receives shadows must lie inside it.
struct Shadows {
  bool enabled = false;
  Eigen::AlignedBox3d bounds;  // [m] world
};

struct SceneStyle {
  Color background{0.93f, 0.94f, 0.96f};
  Color table{0.72f, 0.53f, 0.33f};
  Color base{0.32f, 0.33f, 0.36f};
  Color link{0.25f, 0.45f, 0.75f};
  Color joint{0.20f, 0.21f, 0.24f};
  Color elbow_free{0.80f, 0.80f, 0.80f};
  Color elbow_resting{0.15f, 0.70f, 0.30f};
  Color elbow_landed{0.98f, 0.55f, 0.05f};
  Color elbow_lifted{0.25f, 0.65f, 0.95f};
  Color cue_free{0.42f, 0.42f, 0.45f};  // ring and drop line of an elbow off the table
  Color force{0.85f, 0.12f, 0.15f};
  Color hand_path{0.60f, 0.20f, 0.70f};
  // Desired hand path: neutral mid grey (darker than the 0.70 grid, lighter
  // than the joints), drawn thinner than the purple traced path.
  Color desired_hand_path{0.50f, 0.50f, 0.53f};
  Color grid{0.70f, 0.72f, 0.76f};
};

struct SceneOptions {
  double force_scale = 0.01;      // [m/N] arrow length per newton of normal force
  double landed_window = 0.1;     // [s] an elbow that touched down (left) this recently is
                                  // "landed" ("lifted")
  double cue_range = 3;           // contact cues for elbows within this many radii of the table
  double floor_z = 0;             // [m] height of the ground grid
  Eigen::AlignedBox2d grid_area;  // [m] x-y extent of the grid; empty: no grid
  double grid_spacing = 0.1;      // [m]
  SceneStyle style;
};

struct Scene {
  Color background;
  std::vector<Box> table;           // [table boxes]
  Box base;                         // plate behind joint 0, normal along its axis
  std::vector<Capsule> links;       // [dof] joint origin -> tip, link radius
  std::vector<Cylinder> joints;     // [dof] housing at each joint origin, along its axis
  std::vector<ElbowMarker> elbows;  // [model elbows]
  std::vector<Arrow> forces;        // one per resting elbow, then per resting link solid, with fn > 0
  std::vector<ContactCue> cues;     // per elbow near the table, with a recorded distance
  Polyline hand_path;               // traced hand positions up to now
  Polyline desired_hand_path;       // whole desired hand path (hand_d_*); empty if none
  LineSet grid;                     // ground grid at floor_z
  Shadows shadows;                  // off unless the caller turns them on
};

// The scene of `state` (joint angles placed with forward_kinematics in
// `kinematics`, a Data of the model kept by the caller), with the traced
// `hand_path` (Playback::hand_path) and the whole `desired_path`
// (Playback::desired_hand_path; empty: none drawn).
Scene build_scene(const Model& model, Data& kinematics, const PlaybackState& state,
                  const std::vector<Eigen::Vector3d>& hand_path, const SceneOptions& options,
                  const std::vector<Eigen::Vector3d>& desired_path = {});
// The same with a Data made for the call (one scene; frame loops keep one Data).
Scene build_scene(const Model& model, const PlaybackState& state,
                  const std::vector<Eigen::Vector3d>& hand_path, const SceneOptions& options,
                  const std::vector<Eigen::Vector3d>& desired_path = {});

// A rotation whose z axis is the unit vector n (x and y: any orthonormal pair).
Eigen::Matrix3d frame_with_z(const Eigen::Vector3d& n);

// Axis-aligned bounds of the arm: links, joints, elbows, base and forces [m].
Eigen::AlignedBox3d arm_bounds(const Scene& scene);
// Bounds of a box (any rotation) [m].
Eigen::AlignedBox3d box_bounds(const Box& box);

// The table's outward normal at the top (the box face most aligned with -gravity).
Eigen::Vector3d table_up(const Model& model, const Eigen::Vector3d& point);

}  // namespace elbowsim
