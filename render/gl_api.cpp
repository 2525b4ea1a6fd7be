#include "render/gl_api.hpp"

#include "render/gl_loader.hpp"

namespace elbowsim {

#define ELBOWSIM_GL_DEFINE(type, name) type name = nullptr;
ELBOWSIM_GL_FUNCTIONS(ELBOWSIM_GL_DEFINE)
#undef ELBOWSIM_GL_DEFINE

std::string load_gl_functions(GlProcedure (*lookup)(const char* name)) {
  std::string missing;
#define ELBOWSIM_GL_LOAD(type, name)                               \
  name = reinterpret_cast<type>(lookup(#name));                    \
  if (!name) missing += std::string(missing.empty() ? "" : ", ") + #name;
  ELBOWSIM_GL_FUNCTIONS(ELBOWSIM_GL_LOAD)
#undef ELBOWSIM_GL_LOAD
  return missing;
}

std::string gl_description() {
  auto text = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

}  // namespace elbowsim
