// A parsed URDF tree -> the engine's serial chain: from the base link down,
// one engine joint per revolute or continuous joint, each carrying one rigid
// body: its moving link with every link fixed to it merged in (masses, centres
// of mass and inertias combined; collision solids moved into its frame).
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "app/scenario/urdf_file.hpp"
#include "engine/model.hpp"

namespace elbowsim::urdf {

struct Chain {
  std::vector<elbowsim::Joint> joints;  // [dof]
  std::vector<elbowsim::Link> links;    // [dof]
  std::vector<std::string> joint_names; // [dof]
  std::vector<std::string> link_names;  // [dof] the link each joint moves
  std::vector<std::vector<std::string>> merged;  // [dof] the links fixed to it
  Eigen::VectorXd damping;              // [dof] <dynamics damping> [N m s/rad]
  Eigen::VectorXd q_min, q_max;         // [dof] <limit> [rad]; +-infinity for continuous
  Eigen::VectorXd friction;             // [dof] <dynamics friction> [N m] (not simulated)
  // Where each link of the chain is: on engine link `link` (-1: fixed to the
  // base), its frame's pose in that link's frame.
  struct Frame {
    int link = -1;
    Eigen::Isometry3d to_link = Eigen::Isometry3d::Identity();
  };
  std::map<std::string, Frame> frames;
  std::string base, tip;  // the base link and the tip link (the hand's frame)
};

// The chain from `base` (empty: the tree's root) to `tip` (empty: the end of
// the chain, the hand at the last moving link's origin). Throws UrdfError
// naming the element: a branch (two moving joints below one rigid body), a
// prismatic, floating, planar or mimic joint, a moving link without
// <inertial> or with a mass <= 0, an inertia no rigid body has, a mesh or a
// turned box as a collision solid, more than one solid on a rigid body, a
// base or tip link that is not there.
Chain build_chain(const Tree& tree, const std::string& base, const std::string& tip);

}  // namespace elbowsim::urdf
