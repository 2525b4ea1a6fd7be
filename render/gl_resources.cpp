#include "render/gl_resources.hpp"

#include <stdexcept>
#include <string>

namespace elbowsim {

namespace {

GLuint compile(GLenum type, std::initializer_list<const char*> source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, GLsizei(source.size()), source.begin(), nullptr);
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

GLuint link_program(std::initializer_list<const char*> vertex,
                    std::initializer_list<const char*> fragment) {
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
}

void size_shadow_map(GlRenderer::Gl& g, int width, int height) {
  if (g.shadow_fbo && width == g.shadow_width && height == g.shadow_height) return;
  const bool made = g.shadow_fbo != 0;
  if (!made) glGenTextures(1, &g.shadow_map);
  glBindTexture(GL_TEXTURE_2D, g.shadow_map);
  // 16 bits: over the light's depth range fitted to the scene, far below a
  // texel's size; half the bytes of 24 to clear, write and sample each frame.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, width, height, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_SHORT, nullptr);
  g.shadow_width = width;
  g.shadow_height = height;
  if (made) return;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Outside the map: depth 1, nothing between the point and the light.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float far[4] = {1, 1, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, far);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glGenFramebuffers(1, &g.shadow_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, g.shadow_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, g.shadow_map, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  check_framebuffer("shadow map");
}

void delete_all(GlRenderer::Gl& g) {
  for (const std::vector<MeshBuffers>& levels : g.meshes)
    for (const MeshBuffers& m : levels) {
      const GLuint buffers[3] = {m.vertices, m.indices, m.instances};
      glDeleteBuffers(3, buffers);
      glDeleteVertexArrays(1, &m.vao);
    }
  glDeleteBuffers(1, &g.line_vbo);
  glDeleteVertexArrays(1, &g.line_vao);
  const GLuint rbs[3] = {g.draw_color, g.draw_depth, g.resolve_color};
  glDeleteRenderbuffers(3, rbs);
  if (g.draw_fbo != g.resolve_fbo) glDeleteFramebuffers(1, &g.draw_fbo);
  glDeleteFramebuffers(1, &g.resolve_fbo);
  glDeleteProgram(g.lit);
  glDeleteProgram(g.flat_face);
  glDeleteProgram(g.unlit);
  glDeleteProgram(g.faded);
  glDeleteProgram(g.flat);
  glDeleteProgram(g.depth);
  if (g.shadow_fbo) glDeleteFramebuffers(1, &g.shadow_fbo);
  if (g.shadow_map) glDeleteTextures(1, &g.shadow_map);
}

}  // namespace elbowsim
