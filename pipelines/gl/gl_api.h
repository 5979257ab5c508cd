// The GL 4.5 core API for motorbench code: types and enums from <GL/glcorearb.h>, entry points
// as function pointers loaded at run time from whichever backend created the context (EGL or
// OSMesa), so the same code works on both. Include this header instead of <GL/gl.h>.
//
// The pointers live in namespace mb::glapi (mangled names, so they never collide with the C
// symbols libGL exports) and are brought into the global namespace, so code reads like plain
// GL: glBufferData(...). The list is pipelines/gl/gl_functions.inc.
#pragma once
#include <GL/glcorearb.h>

#include <string>

// Keep <GL/gl.h> out: its prototypes would clash with the pointers below. (<GL/glext.h> declares
// none unless GL_GLEXT_PROTOTYPES is defined.)
#ifndef __gl_h_
#define __gl_h_
#endif

namespace mb::glapi {
#define MB_GL_FN(type, name) extern type name;
#include "pipelines/gl/gl_functions.inc"
#undef MB_GL_FN
}  // namespace mb::glapi

using namespace mb::glapi;  // NOLINT: GL entry points read as the plain GL API

namespace mb::gl {

// Resolves every entry point of gl_functions.inc with `getProc`. Returns "" on success, else the
// names that could not be resolved. Called by the context; needs no current context itself.
using GetProcFn = void* (*)(const char* name);
std::string loadGlFunctions(GetProcFn getProc);

// "GL_INVALID_ENUM" etc. for a glGetError() value.
const char* errorName(GLenum error);

}  // namespace mb::gl
