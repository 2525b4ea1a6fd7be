// A URDF file as plain data: what urdfdom (liburdfdom) parsed, with its poses
// turned into Eigen transforms. urdf_file.cpp is the only file that sees
// urdfdom; urdf_chain.cpp turns this tree into the engine's serial chain.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace elbowsim::urdf {

// A problem with the URDF itself; what() names the element
// ("link \"forearm\": <inertial> is missing"), not the file: the caller adds it.
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One <collision> element: a primitive in its own origin frame.
struct Collision {
  enum class Shape { sphere, box, cylinder, mesh };
  Shape shape = Shape::sphere;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link frame
  double radius = 0;                                          // [m] sphere, cylinder
  double length = 0;                                          // [m] cylinder, along origin z
  Eigen::Vector3d size = Eigen::Vector3d::Zero();             // [m] box edges
};

struct Inertial {
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // com frame in the link frame
  double mass = 0;                                            // [kg]
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();          // [kg m^2] about the com, origin axes
};

struct Link {
  std::string name;
  bool has_inertial = false;
  Inertial inertial;
  std::vector<Collision> collisions;  // in file order
};

struct Joint {
  enum class Type { revolute, continuous, prismatic, fixed, floating, planar, unknown };
  std::string name;
  Type type = Type::unknown;
  std::string parent, child;                                  // link names
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // child frame in the parent frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();            // in the child frame
  double damping = 0;                                         // [N m s/rad] <dynamics>
  double friction = 0;                                        // [N m] <dynamics>
  bool has_limits = false;
  double lower = 0, upper = 0;  // [rad] <limit> (revolute)
  bool mimics = false;          // has a <mimic> element
};

struct Tree {
  std::string robot_name;
  std::string root;                    // the link no joint moves
  std::map<std::string, Link> links;   // by name
  std::map<std::string, Joint> joints; // by name
  // The joints whose parent is each link, in name order (urdfdom keeps no file order).
  std::map<std::string, std::vector<std::string>> children;
  std::map<std::string, std::string> parent_joint;  // link -> the joint that carries it
};

const char* to_string(Joint::Type type);

// Parses URDF text with urdfdom. Throws UrdfError with urdfdom's own messages
// when it rejects the text (malformed XML, a joint naming a missing link, a
// link with two parents, several roots, ...).
Tree parse(const std::string& xml);

}  // namespace elbowsim::urdf
