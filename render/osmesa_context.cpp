#include "render/osmesa_context.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>

#include <stdexcept>

namespace elbowsim {

// Ask for 3.3 core: llvmpipe gives 4.5 core anyway; 3.3 keeps softpipe usable.
OsmesaContext::OsmesaContext() {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), placeholder_, GL_UNSIGNED_BYTE, 1,
                         1)) {
    OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
    throw std::runtime_error("OSMesa could not make its context current");
  }
  // Our framebuffer objects are read bottom-up like any GL framebuffer.
  OSMesaPixelStore(OSMESA_Y_UP, 1);
}

OsmesaContext::~OsmesaContext() { OSMesaDestroyContext(static_cast<OSMesaContext>(context_)); }

std::string OsmesaContext::description() const {
  auto text = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

}  // namespace elbowsim
