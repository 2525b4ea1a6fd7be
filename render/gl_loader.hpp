// Filling the GL function pointers of gl_api.hpp, without GL's headers (so
// that osmesa_context.cpp, which includes OSMesa's, can call it).
#pragma once

#include <string>

namespace elbowsim {

using GlProcedure = void (*)();

// Fills every pointer through `lookup` (OSMesaGetProcAddress). Returns the
// names it could not find, comma-separated; empty when all were found.
std::string load_gl_functions(GlProcedure (*lookup)(const char* name));

// GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5
// (Core Profile) Mesa 22.3.6".
std::string gl_description();

}  // namespace elbowsim
