// Draws abstract scenes (scene.hpp) with OpenGL 3.3 core into framebuffer
// objects and reads the frames back. Needs a current context (OsmesaContext).
//
// Each frame: begin_frame clears; draw() renders one scene into a viewport
// (several viewports make side-by-side panels), first its shadow map when the
// scene asks for shadows and its inset; end_frame resolves the
// multisampled buffer into a single-sample one (glBlitFramebuffer) and reads
// it into memory. Straight into memory, not through pixel-buffer objects:
// llvmpipe fills those with a shader pass over every pixel, which cost 9 %
// of a video's CPU and more wall time than the overlap it bought.
#pragma once

#include <cstdint>
#include <memory>

#include "render/camera.hpp"
#include "render/inset.hpp"
#include "render/scene.hpp"

namespace elbowsim {

// A rectangle of the frame in pixels, from the top-left corner.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
};

class GlRenderer {
 public:
  // width x height [px]; msaa: requested samples per pixel (1 = off, 2, 4),
  // capped at what the driver offers. Compiles the shaders, tessellates the
  // unit shapes into vertex buffers and makes the framebuffers. Throws
  // std::runtime_error on any GL failure.
  GlRenderer(int width, int height, int msaa);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }  // samples per pixel in use

  void begin_frame(const Color& background);
  // One panel: the scene's shadow map (when it asks for shadows), then the
  // inset when given (see InsetView), then the scene in `camera` into
  // `viewport`, leaving the inset's pixels alone.
  struct InsetView {
    const Inset& inset;
    Viewport viewport;  // the inset's rectangle, in this renderer's pixels
  };
  void draw(const Scene& scene, const Camera& camera, const Viewport& viewport,
            const InsetView* inset = nullptr);
  // Boxes whose faces show no highlight are lit per vertex (the default;
  // within a level of per fragment: lighting.hpp, specular_shows); false:
  // every box per fragment, as a reference.
  void set_flat_faces_per_vertex(bool on) { flat_faces_per_vertex_ = on; }
  // Resolves the frame and reads it into rgba (width * height * 4 bytes,
  // RGBA, rows bottom-up as GL stores them), once drawn.
  void end_frame(std::uint8_t* rgba);

  struct Gl;  // GL object names and per-shape instance lists (opaque: gl_renderer.cpp)

 private:
  std::unique_ptr<Gl> gl_;
  int width_, height_, samples_ = 1;
  bool flat_faces_per_vertex_ = true;
};

}  // namespace elbowsim
