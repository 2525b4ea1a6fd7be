// Friction at a resting contact (effects.friction; the law is
// contact.friction.law, model.hpp): the tangent directions of the contact,
// the velocity of its contact point, and the sliding force of each law.
//
// The contact point is the ball's surface point under its centre, c - r n: a
// ball that rolls has a contact point at rest, one that slides does not.
// Along the tangents t of the contact the friction force is f_t; a sliding
// contact's row of M* carries it in Jf = Jc - mu s^T J_p (J_p the contact
// point's Jacobian, s its unit slip direction scaled by the law), so the
// normal force alone is unknown. A sticking contact (coulomb) gets one row
// per tangent, t^T J_p qdd = -t^T Jdot_p qd, and its force f_t is unknown too.
#pragma once

#include <Eigen/Core>

#include "engine/data.hpp"

namespace elbowsim {

// The tangents of a contact with unit normal n. A planar arm's contact whose
// normal lies in the arm's plane has one, t1 = axis x n (every point of the
// arm moves in the plane, so the second would be a zero row); every other
// contact has two, t1 and t2 = n x t1. Returns their number (1 or 2).
int tangent_basis(const Model& model, const Eigen::Vector3d& n, Eigen::Vector3d& t1,
                  Eigen::Vector3d& t2);

// The contact point of slot k's ball for the normal n, in its link's frame.
Eigen::Vector3d contact_point_local(const Data& data, int slot, const Eigen::Vector3d& n);

// The tangential velocity [m/s] of slot k's contact point (normal n) at rates qd.
// Needs forward_kinematics.
Eigen::Vector3d tangential_velocity(const Data& data, int slot, const Eigen::Vector3d& n, ConstVec qd);

// |f_t| / (mu f_n) of a sliding contact slipping at `speed` [m/s] >= 0:
// 1 (coulomb), tanh(speed / tanh_velocity), speed / max(speed, slip_velocity).
double friction_scale(const FrictionOptions& friction, double speed);

}  // namespace elbowsim
