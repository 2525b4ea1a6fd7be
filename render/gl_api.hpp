// The GL entry points the renderer calls, as pointers filled at run time
// from libOSMesa (osmesa_context.cpp loads it with dlopen when a render
// starts), so that a program that renders nothing never loads OSMesa and
// LLVM. Calls read like plain GL: inside namespace elbowsim, glClear(...)
// is the pointer elbowsim::glClear. Only gl_renderer.cpp, gl_resources.cpp
// (through gl_resources.hpp) and gl_api.cpp include this; gl_loader.hpp fills it.
#pragma once

// Without GL_GLEXT_PROTOTYPES, glcorearb.h declares only the types, the
// constants and the PFNGL...PROC pointer types, no functions.
#include <GL/glcorearb.h>

// X(pointer type, name) for every GL function the renderer uses.
#define ELBOWSIM_GL_FUNCTIONS(X) \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture) \
  X(PFNGLATTACHSHADERPROC, glAttachShader) \
  X(PFNGLBINDBUFFERPROC, glBindBuffer) \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer) \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer) \
  X(PFNGLBINDTEXTUREPROC, glBindTexture) \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray) \
  X(PFNGLBLENDFUNCPROC, glBlendFunc) \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer) \
  X(PFNGLBUFFERDATAPROC, glBufferData) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus) \
  X(PFNGLCLEARPROC, glClear) \
  X(PFNGLCLEARCOLORPROC, glClearColor) \
  X(PFNGLCLEARDEPTHPROC, glClearDepth) \
  X(PFNGLCOMPILESHADERPROC, glCompileShader) \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram) \
  X(PFNGLCREATESHADERPROC, glCreateShader) \
  X(PFNGLCULLFACEPROC, glCullFace) \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers) \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers) \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram) \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers) \
  X(PFNGLDELETESHADERPROC, glDeleteShader) \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures) \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays) \
  X(PFNGLDISABLEPROC, glDisable) \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays) \
  X(PFNGLDRAWBUFFERPROC, glDrawBuffer) \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced) \
  X(PFNGLENABLEPROC, glEnable) \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray) \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer) \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D) \
  X(PFNGLGENBUFFERSPROC, glGenBuffers) \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers) \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers) \
  X(PFNGLGENTEXTURESPROC, glGenTextures) \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays) \
  X(PFNGLGETERRORPROC, glGetError) \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv) \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog) \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv) \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog) \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv) \
  X(PFNGLGETSTRINGPROC, glGetString) \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation) \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram) \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei) \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset) \
  X(PFNGLREADBUFFERPROC, glReadBuffer) \
  X(PFNGLREADPIXELSPROC, glReadPixels) \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage) \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample) \
  X(PFNGLSCISSORPROC, glScissor) \
  X(PFNGLSHADERSOURCEPROC, glShaderSource) \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D) \
  X(PFNGLTEXPARAMETERFVPROC, glTexParameterfv) \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri) \
  X(PFNGLUNIFORM1FPROC, glUniform1f) \
  X(PFNGLUNIFORM1IPROC, glUniform1i) \
  X(PFNGLUNIFORM3FPROC, glUniform3f) \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv) \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv) \
  X(PFNGLUSEPROGRAMPROC, glUseProgram) \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor) \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer) \
  X(PFNGLVIEWPORTPROC, glViewport)

namespace elbowsim {

#define ELBOWSIM_GL_DECLARE(type, name) extern type name;
ELBOWSIM_GL_FUNCTIONS(ELBOWSIM_GL_DECLARE)
#undef ELBOWSIM_GL_DECLARE

}  // namespace elbowsim
