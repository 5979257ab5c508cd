// Counted GL uploads. Pipelines call these instead of glBufferData / glUniform* so that every
// byte in PipelineStats is the size actually handed to GL, never a constant. Each call adds the
// bytes it uploads to `counter`; uniform calls count nothing when the location is -1 (GL
// ignores those, so nothing was uploaded).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pipelines/gl/gl_api.h"

namespace mb::gl {

void bufferData(GLenum target, size_t bytes, const void* data, GLenum usage, uint64_t& counter);

// Generates a buffer, binds it to `target` and uploads `v` (counted). Returns its name.
template <class T>
GLuint createBuffer(GLenum target, const std::vector<T>& v, uint64_t& counter,
                    GLenum usage = GL_STATIC_DRAW) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  glBindBuffer(target, id);
  bufferData(target, v.size() * sizeof(T), v.data(), usage, counter);
  return id;
}

void uniform1i(GLint loc, int v, uint64_t& counter);
void uniform1f(GLint loc, float v, uint64_t& counter);
void uniform1fv(GLint loc, int count, const float* v, uint64_t& counter);  // float[count]
void uniform3f(GLint loc, const float* v, uint64_t& counter);   // one vec3
void uniform4f(GLint loc, const float* v, uint64_t& counter);   // one vec4
void uniform4fv(GLint loc, int count, const float* v, uint64_t& counter);
void uniformMatrix4(GLint loc, int count, const float* columnMajor, uint64_t& counter);
void uniformMatrix3(GLint loc, int count, const float* columnMajor, uint64_t& counter);
// GLSL mat4x3 (4 columns of 3 rows: an affine transform), 12 floats each.
void uniformMatrix4x3(GLint loc, int count, const float* columnMajor, uint64_t& counter);

}  // namespace mb::gl
