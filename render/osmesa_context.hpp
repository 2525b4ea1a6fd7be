// An offscreen OpenGL 3.3 core context from OSMesa (Mesa's llvmpipe or
// softpipe): no X, no window, no GPU. The only file that includes osmesa.h
// (one file per library, docs/architecture.md). Drawing goes to framebuffer
// objects the renderer makes (gl_renderer.hpp); the context's own buffer is a
// 1x1 placeholder.
#pragma once

#include <string>

namespace elbowsim {

class OsmesaContext {
 public:
  // Creates a 3.3 core-profile context and makes it current on this thread.
  // Throws std::runtime_error if OSMesa cannot make one.
  OsmesaContext();
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa".
  std::string description() const;

 private:
  void* context_;                   // OSMesaContext
  unsigned char placeholder_[4]{};  // the context's 1x1 RGBA default framebuffer
};

}  // namespace elbowsim
