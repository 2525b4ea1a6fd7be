// Contact detection at the state in data.x, the first of contact's three
// parts (detection -> rows -> solve): the broad phase (Bullet, collision.hpp)
// picks the primitive-box pairs that are near, and each of their slots
// (primitives.hpp) gets its signed distance, table normal and surface point
// in closed form (geometry.hpp). Elbow slots are measured always (their
// distance is recorded); far link slots keep distance +inf.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Forward kinematics at q of data.x, then every slot into
// data.contact.detected / normal / surface. Needs the run's collision world
// (data.contact.world, built by reset()). Allocates nothing. At the q of the
// last detection (bit for bit: a step starting where the last one ended) it
// keeps that detection's results and costs a comparison.
void detect_contacts(const Model& model, Data& data);

// The frames of the step (data.contact.normal, surface, feature, edge) and
// each slot's start_distance from the last detection, for every slot
// measured: what the rows of the step hold. Called when a step starts (select_active_set), not inside it, so the
// rows stay those of the step while events are located.
void freeze_frames(Data& data);

// How far [m] slot k's ball centre is from leaving the feature of its frame
// (>= 0 while it stays): a face's ball centre must stay over the face, an
// edge's between the edge's ends and, for a ball of radius > 0, beside both
// faces (not over one); likewise a corner's. An event function: the step is
// cut where it turns negative (run/contact_events.hpp). Needs forward_kinematics.
double feature_margin(const Model& model, const Data& data, int slot);

// Normal velocity [m/s] of slot k's ball centre at the rates of data.x, along
// the table normal last detected (< 0 approaching). Needs forward_kinematics.
double normal_speed(const Model& model, const Data& data, int slot);

// World position [m] of slot k's ball centre. Needs forward_kinematics.
Eigen::Vector3d slot_centre(const Data& data, int slot);

// Signed distance [m] of a whole primitive (every point of a segment, ends
// included) to a box, at the kinematics in data; < 0 inside.
double primitive_distance(const Model& model, const Data& data, const Primitive& primitive,
                          const TableBox& box);

}  // namespace elbowsim
