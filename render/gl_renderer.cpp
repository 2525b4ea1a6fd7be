#include "render/gl_renderer.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/meshes.hpp"
#include "render/scene.hpp"

namespace elbowsim {

namespace {

// Blinn-Phong, per fragment. Per instance: the model matrix (4 vec4), the
// normal matrix (inverse transpose of its linear part, 3 vec3) and a colour.
constexpr const char* kLitVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 model0;
layout(location = 3) in vec4 model1;
layout(location = 4) in vec4 model2;
layout(location = 5) in vec4 model3;
layout(location = 6) in vec3 normal0;
layout(location = 7) in vec3 normal1;
layout(location = 8) in vec3 normal2;
layout(location = 9) in vec4 color;
uniform mat4 view_projection;
out vec3 world_position;
out vec3 world_normal;
out vec3 base_color;
void main() {
  vec4 p = mat4(model0, model1, model2, model3) * vec4(position, 1.0);
  world_position = p.xyz;
  world_normal = mat3(normal0, normal1, normal2) * normal;
  base_color = color.rgb;
  gl_Position = view_projection * p;
}
)";

// c = ambient k + sum over lights of L (max(n.l, 0) k + s max(n.h, 0)^48), h = (l + v)/|l + v|
constexpr const char* kLitFragment = R"(#version 330 core
in vec3 world_position;
in vec3 world_normal;
in vec3 base_color;
uniform vec3 eye;
uniform vec3 light_direction[2];
uniform vec3 light_color[2];
uniform float ambient;
uniform float specular;
out vec4 frag_color;
void main() {
  vec3 n = normalize(world_normal);
  vec3 v = normalize(eye - world_position);
  vec3 c = ambient * base_color;
  for (int i = 0; i < 2; ++i) {
    vec3 l = light_direction[i];
    float diffuse = max(dot(n, l), 0.0);
    // (n.h)^48 by squaring: cheaper than pow() on llvmpipe.
    float s1 = max(dot(n, normalize(l + v)), 0.0);
    float s2 = s1 * s1, s4 = s2 * s2, s8 = s4 * s4, s16 = s8 * s8;
    float shine = diffuse > 0.0 ? s16 * s16 * s16 : 0.0;
    c += light_color[i] * (diffuse * base_color + specular * shine);
  }
  frag_color = vec4(min(c, vec3(1.0)), 1.0);
}
)";

constexpr const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
void main() { gl_Position = view_projection * vec4(position, 1.0); }
)";

constexpr const char* kFlatFragment = R"(#version 330 core
uniform vec3 color;
out vec4 frag_color;
void main() { frag_color = vec4(color, 1.0); }
)";

constexpr int kInstanceFloats = 16 + 9 + 4;

enum Shape { sphere, cylinder, tube, cone, box, shape_count };

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("GL shader compile failed: ") + log);
  }
  return shader;
}

GLuint link_program(const char* vertex, const char* fragment) {
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex), fs = compile(GL_FRAGMENT_SHADER, fragment);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("GL program link failed: ") + log);
  }
  return program;
}

// Model matrix [linear t; 0 1] and normal matrix linear^-T, appended to `out`.
void add_instance(std::vector<float>& out, const Eigen::Matrix3d& linear, const Eigen::Vector3d& t,
                  const Color& color) {
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
  model.topLeftCorner<3, 3>() = linear.cast<float>();
  model.topRightCorner<3, 1>() = t.cast<float>();
  const Eigen::Matrix3f normal = linear.inverse().transpose().cast<float>();
  out.insert(out.end(), model.data(), model.data() + 16);
  out.insert(out.end(), normal.data(), normal.data() + 9);
  out.insert(out.end(), {color.r, color.g, color.b, 1.0f});
}

// A unit shape along z from a to b with the given radius.
void add_along(std::vector<float>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
               double radius, const Color& color) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  if (length < 1e-9 || radius <= 0) return;
  const Eigen::Matrix3d linear =
      frame_with_z(d / length) * Eigen::Vector3d(radius, radius, length).asDiagonal();
  add_instance(out, linear, a, color);
}

void add_sphere(std::vector<float>& out, const Eigen::Vector3d& c, double r, const Color& color) {
  if (r > 0) add_instance(out, r * Eigen::Matrix3d::Identity(), c, color);
}

// A unit shape's vertex array: its vertices, indices and per-instance buffer.
struct MeshBuffers {
  GLuint vao = 0, vertices = 0, indices = 0, instances = 0;
  GLsizei index_count = 0;
};

}  // namespace

struct GlRenderer::Gl {
  GLuint lit = 0, flat = 0;
  std::array<MeshBuffers, shape_count> meshes;
  std::array<std::vector<float>, shape_count> instances;
  GLuint line_vao = 0, line_vbo = 0;
  GLuint draw_fbo = 0, draw_color = 0, draw_depth = 0;  // multisampled (or the resolve one)
  GLuint resolve_fbo = 0, resolve_color = 0;
  std::array<GLuint, 2> pbo{};
};

namespace {

MeshBuffers upload(const Mesh& mesh) {
  MeshBuffers b;
  glGenVertexArrays(1, &b.vao);
  glBindVertexArray(b.vao);
  glGenBuffers(1, &b.vertices);
  glBindBuffer(GL_ARRAY_BUFFER, b.vertices);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(float)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                        reinterpret_cast<void*>(3 * sizeof(float)));
  glGenBuffers(1, &b.indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  b.index_count = GLsizei(mesh.indices.size());
  // Per-instance attributes 2..9: model matrix columns, normal matrix columns, colour.
  glGenBuffers(1, &b.instances);
  glBindBuffer(GL_ARRAY_BUFFER, b.instances);
  const GLsizei stride = kInstanceFloats * sizeof(float);
  const int sizes[8] = {4, 4, 4, 4, 3, 3, 3, 4};
  std::size_t offset = 0;
  for (int k = 0; k < 8; ++k) {
    glEnableVertexAttribArray(GLuint(2 + k));
    glVertexAttribPointer(GLuint(2 + k), sizes[k], GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offset * sizeof(float)));
    glVertexAttribDivisor(GLuint(2 + k), 1);
    offset += std::size_t(sizes[k]);
  }
  glBindVertexArray(0);
  return b;
}

GLuint renderbuffer(int samples, GLenum format, int width, int height) {
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  if (samples > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  return rb;
}

void check_framebuffer(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("GL framebuffer incomplete (") + what + "), status 0x" +
                             std::to_string(status));
}

}  // namespace

namespace {

// GL_LINES of 3-float positions (the grid), refilled per frame.
void make_line_buffer(GlRenderer::Gl& g);

// Single-sample colour target `resolve_fbo`, read back; with samples > 1 a
// multisampled colour + depth target `draw_fbo` drawn into and resolved into
// it (otherwise draw_fbo is resolve_fbo, with a depth buffer); two pixel-buffer
// objects for the read-back.
void make_framebuffers(GlRenderer::Gl& g, int width, int height, int samples);

}  // namespace

GlRenderer::GlRenderer(int width, int height, int msaa)
    : gl_(std::make_unique<Gl>()), width_(width), height_(height) {
  Gl& g = *gl_;
  g.lit = link_program(kLitVertex, kLitFragment);
  g.flat = link_program(kFlatVertex, kFlatFragment);
  g.meshes[sphere] = upload(unit_sphere(32, 16));
  g.meshes[cylinder] = upload(unit_cylinder(32));
  g.meshes[tube] = upload(unit_cylinder(8));
  g.meshes[cone] = upload(unit_cone(32));
  g.meshes[box] = upload(unit_box());
  make_line_buffer(g);
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(msaa, 1, std::max(1, int(max_samples)));
  make_framebuffers(g, width, height, samples_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("GL error while setting up the renderer");
}

namespace {

void make_line_buffer(GlRenderer::Gl& g) {
  glGenVertexArrays(1, &g.line_vao);
  glBindVertexArray(g.line_vao);
  glGenBuffers(1, &g.line_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, g.line_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindVertexArray(0);
}

void make_framebuffers(GlRenderer::Gl& g, int width, int height, int samples) {
  glGenFramebuffers(1, &g.resolve_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, g.resolve_fbo);
  g.resolve_color = renderbuffer(1, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.resolve_color);
  if (samples > 1) {
    check_framebuffer("resolve");
    glGenFramebuffers(1, &g.draw_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, g.draw_fbo);
    g.draw_color = renderbuffer(samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.draw_color);
  } else {
    g.draw_fbo = g.resolve_fbo;
  }
  g.draw_depth = renderbuffer(samples, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g.draw_depth);
  check_framebuffer("draw");
  glGenBuffers(2, g.pbo.data());
  for (GLuint pbo : g.pbo) {
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo);
    glBufferData(GL_PIXEL_PACK_BUFFER, GLsizeiptr(width) * height * 4, nullptr, GL_STREAM_READ);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

}  // namespace

GlRenderer::~GlRenderer() {
  Gl& g = *gl_;
  for (auto& m : g.meshes) {
    const GLuint buffers[3] = {m.vertices, m.indices, m.instances};
    glDeleteBuffers(3, buffers);
    glDeleteVertexArrays(1, &m.vao);
  }
  glDeleteBuffers(1, &g.line_vbo);
  glDeleteVertexArrays(1, &g.line_vao);
  glDeleteBuffers(2, g.pbo.data());
  const GLuint rbs[3] = {g.draw_color, g.draw_depth, g.resolve_color};
  glDeleteRenderbuffers(3, rbs);
  if (g.draw_fbo != g.resolve_fbo) glDeleteFramebuffers(1, &g.draw_fbo);
  glDeleteFramebuffers(1, &g.resolve_fbo);
  glDeleteProgram(g.lit);
  glDeleteProgram(g.flat);
}

void GlRenderer::begin_frame(const Color& background) {
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->draw_fbo);
  glViewport(0, 0, width_, height_);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

namespace {

// The scene as instances of the unit shapes: a capsule is a cylinder with a
// sphere at each end; an arrow a shaft and a cone; the hand path thin tubes.
void collect(const Scene& s, std::array<std::vector<float>, shape_count>& out) {
  for (auto& v : out) v.clear();
  for (const Box& b : s.table)
    add_instance(out[box], b.rotation * b.size.asDiagonal(), b.center, b.color);
  add_instance(out[box], s.base.rotation * s.base.size.asDiagonal(), s.base.center, s.base.color);
  for (const Capsule& c : s.links) {
    add_along(out[cylinder], c.a, c.b, c.radius, c.color);
    add_sphere(out[sphere], c.a, c.radius, c.color);
    add_sphere(out[sphere], c.b, c.radius, c.color);
  }
  for (const Cylinder& c : s.joints) add_along(out[cylinder], c.a, c.b, c.radius, c.color);
  for (const ElbowMarker& e : s.elbows)
    add_sphere(out[sphere], e.sphere.center, e.sphere.radius, e.sphere.color);
  for (const Arrow& a : s.forces) {
    const double length = (a.tip - a.tail).norm();
    const double head = std::min(0.4 * length, 4.0 * a.radius);
    const Eigen::Vector3d neck = a.tip + (a.tail - a.tip).normalized() * head;
    add_along(out[cylinder], a.tail, neck, a.radius, a.color);
    add_along(out[cone], neck, a.tip, 2.2 * a.radius, a.color);
  }
  const auto& path = s.hand_path.points;
  for (std::size_t k = 1; k < path.size(); ++k)
    add_along(out[tube], path[k - 1], path[k], s.hand_path.radius, s.hand_path.color);
  const auto& desired = s.desired_hand_path.points;  // the whole planned path, grey
  for (std::size_t k = 1; k < desired.size(); ++k)
    add_along(out[tube], desired[k - 1], desired[k], s.desired_hand_path.radius,
              s.desired_hand_path.color);
}

// Key light mostly from above (world z, docs/conventions.md), a little from the
// viewer's side and left, so that tops are brighter than the faces toward
// the camera in every view; a dim fill from the viewer's right.
void set_lights(GLuint program, const Camera& camera) {
  const Eigen::Vector3d back = (camera.eye - camera.target).normalized();
  const Eigen::Vector3d right = camera.up.cross(back).normalized();
  const Eigen::Vector3d key_d = 0.6 * Eigen::Vector3d::UnitZ() + 0.35 * back - 0.3 * right;
  const Eigen::Vector3f key = key_d.normalized().cast<float>();
  const Eigen::Vector3f fill = (0.8 * right + 0.2 * back).normalized().cast<float>();
  const float directions[6] = {key.x(), key.y(), key.z(), fill.x(), fill.y(), fill.z()};
  const float colors[6] = {0.72f, 0.72f, 0.72f, 0.22f, 0.22f, 0.24f};
  glUniform3fv(glGetUniformLocation(program, "light_direction"), 2, directions);
  glUniform3fv(glGetUniformLocation(program, "light_color"), 2, colors);
  glUniform1f(glGetUniformLocation(program, "ambient"), 0.32f);
  glUniform1f(glGetUniformLocation(program, "specular"), 0.22f);
  const Eigen::Vector3f eye = camera.eye.cast<float>();
  glUniform3fv(glGetUniformLocation(program, "eye"), 1, eye.data());
}

}  // namespace

void GlRenderer::draw(const Scene& scene, const Camera& camera, const Viewport& v) {
  Gl& g = *gl_;
  glViewport(v.x, height_ - v.y - v.height, v.width, v.height);
  const Eigen::Matrix4f vp = (camera.projection() * camera.view()).cast<float>();

  glUseProgram(g.lit);
  glUniformMatrix4fv(glGetUniformLocation(g.lit, "view_projection"), 1, GL_FALSE, vp.data());
  set_lights(g.lit, camera);
  collect(scene, g.instances);
  for (int s = 0; s < shape_count; ++s) {
    const std::vector<float>& inst = g.instances[s];
    if (inst.empty()) continue;
    glBindVertexArray(g.meshes[s].vao);
    glBindBuffer(GL_ARRAY_BUFFER, g.meshes[s].instances);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(inst.size() * sizeof(float)), inst.data(),
                 GL_STREAM_DRAW);
    glDrawElementsInstanced(GL_TRIANGLES, g.meshes[s].index_count, GL_UNSIGNED_INT, nullptr,
                            GLsizei(inst.size() / kInstanceFloats));
  }

  if (!scene.grid.points.empty()) {
    std::vector<float> lines;
    for (const Eigen::Vector3d& p : scene.grid.points)
      lines.insert(lines.end(), {float(p.x()), float(p.y()), float(p.z())});
    glUseProgram(g.flat);
    glUniformMatrix4fv(glGetUniformLocation(g.flat, "view_projection"), 1, GL_FALSE, vp.data());
    const Color& c = scene.grid.color;
    glUniform3f(glGetUniformLocation(g.flat, "color"), c.r, c.g, c.b);
    glBindVertexArray(g.line_vao);
    glBindBuffer(GL_ARRAY_BUFFER, g.line_vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(float)), lines.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size() / 3));
  }
  glBindVertexArray(0);
}

void GlRenderer::end_frame() {
  Gl& g = *gl_;
  if (pending_.size() >= g.pbo.size())
    throw std::logic_error("GlRenderer: fetch() a frame before ending another");
  if (g.draw_fbo != g.resolve_fbo) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, g.draw_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g.resolve_fbo);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, g.resolve_fbo);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, g.pbo[std::size_t(next_pbo_)]);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  pending_.push_back(next_pbo_);
  next_pbo_ = (next_pbo_ + 1) % int(g.pbo.size());
}

bool GlRenderer::fetch(std::uint8_t* rgba) {
  if (pending_.empty()) return false;
  const GLuint pbo = gl_->pbo[std::size_t(pending_.front())];
  pending_.pop_front();
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo);
  const std::size_t bytes = std::size_t(width_) * std::size_t(height_) * 4;
  const void* data = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, GLsizeiptr(bytes), GL_MAP_READ_BIT);
  if (!data) throw std::runtime_error("GL could not map the read-back buffer");
  std::memcpy(rgba, data, bytes);
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  return true;
}

}  // namespace elbowsim
