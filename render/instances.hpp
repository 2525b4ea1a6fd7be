// A scene as instances of the renderer's unit shapes (meshes.hpp), without
// GL: per instance a model matrix, its normal matrix and a colour, packed as
// the floats the GL vertex arrays read. Grouped by what casts shadows.
#pragma once

#include <array>
#include <vector>

#include "render/inset.hpp"
#include "render/scene.hpp"

namespace elbowsim {

// Floats per instance: model matrix (16, column-major), normal matrix (9), colour (4).
inline constexpr int kInstanceFloats = 16 + 9 + 4;

// The ring shape's tube radius over its radius (unit_torus).
inline constexpr double kRingTube = 0.06;

// dome: half a sphere; shaft: a cylinder's side, as round as `cylinder`
// (tube: 6 sides, for thin paths).
enum Shape { sphere, cylinder, tube, cone, box, ring, square, dome, shaft, shape_count };
// arm: the robot, its elbows and force arrows (casts shadows); ground: the
// table and the contact cues; paths: the hand's paths (only receive).
enum Group { arm, ground, paths, group_count };

using ShapeInstances = std::array<std::vector<float>, shape_count>;
using Instances = std::array<ShapeInstances, group_count>;

// The scene's instances (cleared first): a capsule is a cylinder with a
// sphere at each end; an arrow a shaft and a cone; a path thin tubes; a
// contact cue a ring and tubes for its dashes.
void collect(const Scene& scene, Instances& out);

// The inset's paths, in drawing order: the desired band, the traced line
// (each segment a ribbon facing the inset's camera), then the hand.
std::array<ShapeInstances, 3> inset_instances(const Inset& inset);

// The instances of `in` whose bounding sphere reaches into the window of
// the orthographic `camera` (ortho_height > 0), into `out` (cleared first):
// what the inset can show of the scene, so that only that is transformed.
void cull_to_window(const ShapeInstances& in, const Camera& camera, ShapeInstances& out);

// One instance: model matrix [linear t; 0 1] and normal matrix linear^-T.
void add_instance(std::vector<float>& out, const Eigen::Matrix3d& linear, const Eigen::Vector3d& t,
                  const Color& color);

}  // namespace elbowsim
