#include "pipelines/gl/gl_api.h"

namespace mb::glapi {
#define MB_GL_FN(type, name) type name = nullptr;
#include "pipelines/gl/gl_functions.inc"
#undef MB_GL_FN
}  // namespace mb::glapi

namespace mb::gl {

std::string loadGlFunctions(GetProcFn getProc) {
  std::string missing;
#define MB_GL_FN(type, name)                                              \
  glapi::name = reinterpret_cast<type>(getProc(#name));                   \
  if (!glapi::name) missing += (missing.empty() ? "" : ", ") + std::string(#name);
#include "pipelines/gl/gl_functions.inc"
#undef MB_GL_FN
  return missing;
}

const char* errorName(GLenum error) {
  switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: return "unknown GL error";
  }
}

}  // namespace mb::gl
