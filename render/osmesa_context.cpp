#include "render/osmesa_context.hpp"

#include <dlfcn.h>

// The header for its types and constants only: every OSMesa function is
// called through a pointer from dlsym, so the program does not link libOSMesa.
#include <GL/osmesa.h>

#include <mutex>
#include <stdexcept>

#include "render/gl_loader.hpp"

namespace elbowsim {

namespace {

// libOSMesa's entry points, from dlopen: loaded by the first context, kept
// for the life of the process (LLVM, which it loads, is not made to be unloaded).
struct Osmesa {
  decltype(&OSMesaCreateContextAttribs) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;
  decltype(&OSMesaPixelStore) pixel_store = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

// Debian's libosmesa6 installs libOSMesa.so.8; the unversioned name is the
// development link, for other layouts.
constexpr const char* kLibraries[] = {"libOSMesa.so.8", "libOSMesa.so"};

// OSMesaGetProcAddress, for the GL lookup (a function pointer without captures).
decltype(&OSMesaGetProcAddress) proc_address = nullptr;

GlProcedure gl_procedure(const char* name) {
  return reinterpret_cast<GlProcedure>(proc_address(name));
}

template <class F>
void find(void* library, F& f, const char* name) {
  f = reinterpret_cast<F>(dlsym(library, name));
  if (!f) throw std::runtime_error(std::string("libOSMesa has no ") + name);
}

Osmesa open_osmesa() {
  void* library = nullptr;
  std::string errors;
  for (const char* name : kLibraries) {
    if ((library = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
    const char* error = dlerror();
    errors += std::string("\n  ") + (error ? error : name);
  }
  if (!library)
    throw std::runtime_error(
        "cannot load OSMesa, which renders the frames (Debian: apt-get install libosmesa6):" +
        errors);
  Osmesa o;
  find(library, o.create, "OSMesaCreateContextAttribs");
  find(library, o.make_current, "OSMesaMakeCurrent");
  find(library, o.destroy, "OSMesaDestroyContext");
  find(library, o.pixel_store, "OSMesaPixelStore");
  find(library, o.get_proc_address, "OSMesaGetProcAddress");
  proc_address = o.get_proc_address;
  const std::string missing = load_gl_functions(gl_procedure);
  if (!missing.empty()) throw std::runtime_error("OSMesa lacks GL functions: " + missing);
  return o;
}

// Loaded once, by whichever thread makes the first context.
const Osmesa& osmesa() {
  static const Osmesa o = open_osmesa();
  return o;
}

}  // namespace

// Ask for 3.3 core: llvmpipe gives 4.5 core anyway; 3.3 keeps softpipe usable.
OsmesaContext::OsmesaContext() {
  const Osmesa& o = osmesa();
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
  context_ = o.create(attributes, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
  if (!o.make_current(static_cast<OSMesaContext>(context_), placeholder_, GL_UNSIGNED_BYTE, 1, 1)) {
    o.destroy(static_cast<OSMesaContext>(context_));
    throw std::runtime_error("OSMesa could not make its context current");
  }
  // Our framebuffer objects are read bottom-up like any GL framebuffer.
  o.pixel_store(OSMESA_Y_UP, 1);
}

OsmesaContext::~OsmesaContext() { osmesa().destroy(static_cast<OSMesaContext>(context_)); }

std::string OsmesaContext::description() const { return gl_description(); }

}  // namespace elbowsim
