#include "render/gl_renderer.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "render/gl_resources.hpp"
#include "render/gl_shaders.hpp"
#include "render/lighting.hpp"
#include "render/meshes.hpp"

namespace elbowsim {

GlRenderer::GlRenderer(int width, int height, int msaa)
    : gl_(std::make_unique<Gl>()), width_(width), height_(height) {
  Gl& g = *gl_;
  using namespace shaders;
  g.lit = link_program({kVersion, kInstanceInputs, kShadowCoordinate, kLitVertex},
                       {kVersion, kLighting, kShadowLookup, kLitFragment});
  g.flat_face =
      link_program({kVersion, kInstanceInputs, kLighting, kShadowCoordinate, kFlatFaceVertex},
                   {kVersion, kShadowLookup, kFlatFaceFragment});
  g.unlit = link_program({kVersion, kInstanceInputs, kShadowCoordinate, kLitVertex},
                         {kVersion, kUnlitFragment});
  g.faded = link_program({kVersion, kInstanceInputs, kLighting, kFadedVertex},
                         {kVersion, kUnlitFragment});
  g.flat = link_program({kVersion, kFlatVertex}, {kVersion, kFlatFragment});
  g.depth = link_program({kVersion, kInstanceInputs, kDepthVertex}, {kVersion, kDepthFragment});
  // Round shapes at every level of detail, chosen per instance by its size
  // on screen (level_of_detail.hpp).
  for (const int n : kSlices) {
    g.meshes[sphere].push_back(upload(unit_sphere(n, n / 2)));
    g.meshes[dome].push_back(upload(unit_dome(n, std::max(n / 4, 2))));
    g.meshes[cylinder].push_back(upload(unit_cylinder(n)));
    g.meshes[shaft].push_back(upload(unit_tube(n)));
  }
  // Paths and drop lines: a few pixels wide, so 6 sides and no caps (the
  // next segment covers the joint) are as good as more, at a third of the
  // triangles of 8 capped sides.
  g.meshes[tube] = {upload(unit_tube(6))};
  g.meshes[cone] = {upload(unit_cone(32))};
  g.meshes[box] = {upload(unit_box())};
  g.meshes[ring] = {upload(unit_torus(48, 8, kRingTube))};
  g.meshes[square] = {upload(unit_square())};
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

GlRenderer::~GlRenderer() { delete_all(*gl_); }

void GlRenderer::begin_frame(const Color& background) {
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->draw_fbo);
  glViewport(0, 0, width_, height_);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

namespace {

// The view that sizes shapes on screen: `camera` over `height` pixels,
// drawn at `contrast` (1 - fade: an outline's error shows that much).
struct ViewScale {
  const Camera& camera;
  int height;
  double contrast = 1.0;
};

// Uploads instances into a mesh's instance buffer and draws them.
void draw_instanced(const MeshBuffers& mesh, const std::vector<float>& inst) {
  if (inst.empty()) return;
  glBindVertexArray(mesh.vao);
  glBindBuffer(GL_ARRAY_BUFFER, mesh.instances);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(inst.size() * sizeof(float)), inst.data(),
               GL_STREAM_DRAW);
  glDrawElementsInstanced(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr,
                          GLsizei(inst.size() / kInstanceFloats));
}

// Appends the instance at float k of `from` to `to`.
void append_instance(const std::vector<float>& from, std::size_t k, std::vector<float>& to) {
  to.insert(to.end(), from.begin() + std::ptrdiff_t(k),
            from.begin() + std::ptrdiff_t(k + kInstanceFloats));
}

// A round shape's instances sorted by their level of detail in `view` (the
// radius: the larger of the model's first two columns, times the view's
// contrast; measured at the instance's origin, moved half its axis up for
// the cylinders), each level drawn with one call.
void draw_by_level(GlRenderer::Gl& g, int shape, const std::vector<float>& inst,
                   const ViewScale& view) {
  for (std::vector<float>& v : g.by_level) v.clear();
  const bool axis = shape == cylinder || shape == shaft;
  for (std::size_t k = 0; k + kInstanceFloats <= inst.size(); k += kInstanceFloats) {
    const Eigen::Map<const Eigen::Matrix4f> model(inst.data() + k);
    const Eigen::Vector3f at =
        model.col(3).head<3>() + (axis ? 0.5f : 0.0f) * model.col(2).head<3>();
    const double radius = std::max(model.col(0).head<3>().norm(), model.col(1).head<3>().norm());
    const double px =
        radius * view.contrast * view.camera.pixels_per_metre(at.cast<double>(), view.height);
    append_instance(inst, k, g.by_level[std::size_t(detail_level(px))]);
  }
  for (std::size_t level = 0; level < g.by_level.size(); ++level)
    draw_instanced(g.meshes[std::size_t(shape)][level], g.by_level[level]);
}

// Uploads each shape's instances (but those of shape `except`) and draws
// them, one instanced call per shape (per level of detail for the round ones).
void draw_shapes(GlRenderer::Gl& g, const ShapeInstances& shapes, const ViewScale& view,
                 int except = -1) {
  for (int s = 0; s < shape_count; ++s) {
    const std::vector<float>& inst = shapes[std::size_t(s)];
    if (inst.empty() || s == except) continue;
    if (is_round(s))
      draw_by_level(g, s, inst, view);
    else
      draw_instanced(g.meshes[std::size_t(s)].front(), inst);
  }
  glBindVertexArray(0);
}

void set_matrix(GLuint program, const char* name, const Eigen::Matrix4f& m) {
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

// The key light's depth of the arm (the table and the paths only receive)
// into the shadow map: back faces, pushed back a little (polygon offset), so
// lit faces do not shadow themselves.
void shadow_pass(GlRenderer::Gl& g, const Scene& scene, const Lighting& lights) {
  const ShadowView view = shadow_view(lights.key, scene.shadows.bounds, kShadowMapSize);
  const Camera& light = view.camera;
  size_shadow_map(g, view.width, view.height);
  g.light_view_projection = (light.projection() * light.view()).cast<float>();
  g.shadow_texel = float(view.texel);
  glBindFramebuffer(GL_FRAMEBUFFER, g.shadow_fbo);
  glViewport(0, 0, view.width, view.height);
  glClear(GL_DEPTH_BUFFER_BIT);
  glUseProgram(g.depth);
  set_matrix(g.depth, "view_projection", g.light_view_projection);
  glCullFace(GL_FRONT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  draw_shapes(g, g.instances[arm], {light, view.height});
  glDisable(GL_POLYGON_OFFSET_FILL);
  glCullFace(GL_BACK);
  glBindFramebuffer(GL_FRAMEBUFFER, g.draw_fbo);
}

// The lighting uniforms (kLighting) of program `p`, current, for a view
// through `camera` from `eye` under `lights`.
void set_lighting(GLuint p, const Camera& camera, const Eigen::Vector3d& eye,
                  const Lighting& lights) {
  glUseProgram(p);
  set_matrix(p, "view_projection", (camera.projection() * camera.view()).cast<float>());
  const Eigen::Vector3f key = lights.key.cast<float>(), fill = lights.fill.cast<float>();
  const float directions[6] = {key.x(), key.y(), key.z(), fill.x(), fill.y(), fill.z()};
  const Eigen::Vector3f &kc = lights.key_color, &fc = lights.fill_color;
  const float colors[6] = {kc.x(), kc.y(), kc.z(), fc.x(), fc.y(), fc.z()};
  glUniform3fv(glGetUniformLocation(p, "light_direction"), 2, directions);
  glUniform3fv(glGetUniformLocation(p, "light_color"), 2, colors);
  glUniform1f(glGetUniformLocation(p, "ambient"), lights.ambient);
  glUniform1f(glGetUniformLocation(p, "specular"), lights.specular);
  const Eigen::Vector3f e = eye.cast<float>();
  glUniform3fv(glGetUniformLocation(p, "eye"), 1, e.data());
}

// The uniforms of the two lit programs (per fragment, and per vertex for
// flat faces) for a view from `eye` under `lights`; the per-fragment one current.
void use_lit(GlRenderer::Gl& g, const Camera& camera, const Eigen::Vector3d& eye,
             const Lighting& lights, bool shadows) {
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, shadows ? g.shadow_map : 0);
  for (const GLuint p : {g.flat_face, g.lit}) {
    set_lighting(p, camera, eye, lights);
    glUniform1i(glGetUniformLocation(p, "shadows"), shadows ? 1 : 0);
    set_matrix(p, "light_view_projection", g.light_view_projection);
    glUniform1f(glGetUniformLocation(p, "shadow_texel"), g.shadow_texel);
    glUniform1f(glGetUniformLocation(p, "shadow_keep"), 0.3f);
    glUniform1i(glGetUniformLocation(p, "shadow_map"), 0);
  }
}

// Every group's boxes into g.lit_boxes and g.flat_boxes: per vertex (flat)
// where `per_vertex` allows and no face shows a highlight seen from `eye`.
void sort_boxes(GlRenderer::Gl& g, const Lighting& lights, const Eigen::Vector3d& eye,
                bool per_vertex) {
  g.lit_boxes.clear();
  g.flat_boxes.clear();
  for (const ShapeInstances& group : g.instances) {
    const std::vector<float>& boxes = group[box];
    for (std::size_t k = 0; k + kInstanceFloats <= boxes.size(); k += kInstanceFloats) {
      const Eigen::Map<const Eigen::Matrix4f> model(boxes.data() + k);
      const bool flat = per_vertex && !specular_shows(lights, eye, model);
      append_instance(boxes, k, flat ? g.flat_boxes : g.lit_boxes);
    }
  }
}

void draw_grid(GlRenderer::Gl& g, const LineSet& grid, const Eigen::Matrix4f& view_projection) {
  if (grid.points.empty()) return;
  std::vector<float> lines;
  for (const Eigen::Vector3d& p : grid.points)
    lines.insert(lines.end(), {float(p.x()), float(p.y()), float(p.z())});
  glUseProgram(g.flat);
  set_matrix(g.flat, "view_projection", view_projection);
  glUniform3f(glGetUniformLocation(g.flat, "color"), grid.color.r, grid.color.g, grid.color.b);
  glBindVertexArray(g.line_vao);
  glBindBuffer(GL_ARRAY_BUFFER, g.line_vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(float)), lines.data(),
               GL_STREAM_DRAW);
  // Smooth lines (coverage in alpha, blended) when the frame has one sample
  // per pixel; GL ignores this under multisampling.
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_LINES, 0, GLsizei(lines.size() / 3));
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glBindVertexArray(0);
}

void set_viewport(const Viewport& v, int frame_height) {
  glViewport(v.x, frame_height - v.y - v.height, v.width, v.height);
}

}  // namespace

namespace {

void scissor(const Viewport& v, int frame_height) {
  glScissor(v.x, frame_height - v.y - v.height, v.width, v.height);
}

// The inset into its rectangle: cleared to its background, the scene faded
// toward it (where the hand is, not what to read; lit per vertex, the faded
// program), then its paths over everything in order (desired band, traced
// line, hand), flat. Lights as in the panel's view `main`; no shadows
// (faded, they would not show).
void draw_inset(GlRenderer::Gl& g, const Inset& inset, const Camera& main, const Viewport& v,
                int frame_height) {
  set_viewport(v, frame_height);
  glEnable(GL_SCISSOR_TEST);
  scissor(v, frame_height);
  glClearColor(inset.background.r, inset.background.g, inset.background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  set_lighting(g.faded, inset.camera, inset.camera.eye, view_lighting(main));
  glUniform1f(glGetUniformLocation(g.faded, "fade"), inset.fade);
  glUniform3f(glGetUniformLocation(g.faded, "fade_color"), inset.background.r, inset.background.g,
              inset.background.b);
  for (const Group group : {arm, ground}) {
    cull_to_window(g.instances[group], inset.camera, g.culled);
    draw_shapes(g, g.culled, {inset.camera, v.height, 1.0 - inset.fade});
  }
  // The paths in their own colours, unlit: a program of their own (in the
  // lit one, llvmpipe ran the whole lighting for them under a mask).
  glUseProgram(g.unlit);
  set_matrix(g.unlit, "view_projection",
             (inset.camera.projection() * inset.camera.view()).cast<float>());
  glDisable(GL_DEPTH_TEST);
  for (const ShapeInstances& layer : inset_instances(inset))
    draw_shapes(g, layer, {inset.camera, v.height});
  glEnable(GL_DEPTH_TEST);
  // Depth 0 over the inset: the main view's fragments there fail the depth
  // test before they are shaded.
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glClearDepth(1.0);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace

void GlRenderer::draw(const Scene& scene, const Camera& camera, const Viewport& v,
                      const InsetView* inset) {
  Gl& g = *gl_;
  const Lighting lights = view_lighting(camera);
  collect(scene, g.instances);
  const bool shadows = scene.shadows.enabled && !scene.shadows.bounds.isEmpty();
  if (shadows) shadow_pass(g, scene, lights);
  if (inset) draw_inset(g, inset->inset, camera, inset->viewport, height_);
  set_viewport(v, height_);
  use_lit(g, camera, camera.eye, lights, shadows);
  for (const ShapeInstances& group : g.instances) draw_shapes(g, group, {camera, v.height}, box);
  // Boxes last (what the arm hides of a table then fails the depth test
  // before it is shaded), lit per vertex where no highlight shows on them.
  sort_boxes(g, lights, camera.eye, flat_faces_per_vertex_);
  glUseProgram(g.lit);
  draw_instanced(g.meshes[box].front(), g.lit_boxes);
  glUseProgram(g.flat_face);
  draw_instanced(g.meshes[box].front(), g.flat_boxes);
  glBindVertexArray(0);
  draw_grid(g, scene.grid, (camera.projection() * camera.view()).cast<float>());
}

void GlRenderer::end_frame(std::uint8_t* rgba) {
  Gl& g = *gl_;
  if (g.draw_fbo != g.resolve_fbo) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, g.draw_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g.resolve_fbo);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, g.resolve_fbo);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("GL could not read the frame back");
}

}  // namespace elbowsim
