// The GL objects behind GlRenderer (programs, unit-shape vertex arrays,
// framebuffers, the shadow map) and the functions that make them. Internal
// to the renderer: only gl_renderer.cpp and gl_resources.cpp include it.
#pragma once

#include <array>
#include <initializer_list>

#include "render/gl_api.hpp"
#include "render/gl_renderer.hpp"
#include "render/instances.hpp"
#include "render/level_of_detail.hpp"
#include "render/meshes.hpp"

namespace elbowsim {

// A unit shape's vertex array: its vertices, indices and per-instance buffer.
struct MeshBuffers {
  GLuint vao = 0, vertices = 0, indices = 0, instances = 0;
  GLsizei index_count = 0;
};

// [texels] the shadow map's longest side at most; its texel is the shadowed
// bounds' diagonal over this (lighting.hpp, shadow_view).
inline constexpr int kShadowMapSize = 1024;

struct GlRenderer::Gl {
  GLuint lit = 0, flat_face = 0, unlit = 0, faded = 0, flat = 0, depth = 0;  // programs
  // Per shape its meshes: one, or for a round shape (is_round) one per
  // level of detail (level_of_detail.hpp), coarsest first.
  std::array<std::vector<MeshBuffers>, shape_count> meshes;
  std::array<std::vector<float>, kSlices.size()> by_level;  // a shape's instances, sorted
  Instances instances;
  ShapeInstances culled;                     // a group's instances in the inset's window
  std::vector<float> lit_boxes, flat_boxes;  // box instances lit per fragment, per vertex
  GLuint line_vao = 0, line_vbo = 0;
  GLuint draw_fbo = 0, draw_color = 0, draw_depth = 0;  // multisampled (or the resolve one)
  GLuint resolve_fbo = 0, resolve_color = 0;
  GLuint shadow_fbo = 0, shadow_map = 0;    // made on first use
  int shadow_width = 0, shadow_height = 0;  // [texels] of shadow_map
  Eigen::Matrix4f light_view_projection = Eigen::Matrix4f::Identity();
  float shadow_texel = 0;  // [m] world size of one texel
};

// Shapes drawn at several levels of detail: spheres, domes, cylinders, shafts.
inline bool is_round(int shape) {
  return shape == sphere || shape == dome || shape == cylinder || shape == shaft;
}

// A program from its stages' sources, each given in pieces joined in order;
// throws on errors.
GLuint link_program(std::initializer_list<const char*> vertex,
                    std::initializer_list<const char*> fragment);
MeshBuffers upload(const Mesh& mesh);
// GL_LINES of 3-float positions (the grid), refilled per frame.
void make_line_buffer(GlRenderer::Gl& g);
// Single-sample colour target `resolve_fbo`, read back; with samples > 1 a
// multisampled colour + depth target `draw_fbo` drawn into and resolved into
// it (otherwise draw_fbo is resolve_fbo, with a depth buffer).
void make_framebuffers(GlRenderer::Gl& g, int width, int height, int samples);
// A width x height depth texture with depth comparison (sampler2DShadow,
// bilinear) and a framebuffer that renders into it: made on first use,
// resized when the size changes.
void size_shadow_map(GlRenderer::Gl& g, int width, int height);
void delete_all(GlRenderer::Gl& g);

}  // namespace elbowsim
