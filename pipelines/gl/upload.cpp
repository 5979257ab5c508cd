#include "pipelines/gl/upload.h"

namespace mb::gl {

void bufferData(GLenum target, size_t bytes, const void* data, GLenum usage, uint64_t& counter) {
  glBufferData(target, GLsizeiptr(bytes), data, usage);
  if (data) counter += bytes;  // a null pointer only allocates
}

void uniform1i(GLint loc, int v, uint64_t& counter) {
  if (loc < 0) return;
  glUniform1i(loc, v);
  counter += sizeof(int);
}

void uniform1f(GLint loc, float v, uint64_t& counter) {
  if (loc < 0) return;
  glUniform1f(loc, v);
  counter += sizeof(float);
}

void uniform1fv(GLint loc, int count, const float* v, uint64_t& counter) {
  if (loc < 0 || count <= 0) return;
  glUniform1fv(loc, count, v);
  counter += size_t(count) * sizeof(float);
}

void uniform3f(GLint loc, const float* v, uint64_t& counter) {
  if (loc < 0) return;
  glUniform3fv(loc, 1, v);
  counter += 3 * sizeof(float);
}

void uniform4f(GLint loc, const float* v, uint64_t& counter) { uniform4fv(loc, 1, v, counter); }

void uniform4fv(GLint loc, int count, const float* v, uint64_t& counter) {
  if (loc < 0) return;
  glUniform4fv(loc, count, v);
  counter += size_t(count) * 4 * sizeof(float);
}

void uniformMatrix4(GLint loc, int count, const float* columnMajor, uint64_t& counter) {
  if (loc < 0) return;
  glUniformMatrix4fv(loc, count, GL_FALSE, columnMajor);
  counter += size_t(count) * 16 * sizeof(float);
}

void uniformMatrix3(GLint loc, int count, const float* columnMajor, uint64_t& counter) {
  if (loc < 0) return;
  glUniformMatrix3fv(loc, count, GL_FALSE, columnMajor);
  counter += size_t(count) * 9 * sizeof(float);
}

void uniformMatrix4x3(GLint loc, int count, const float* columnMajor, uint64_t& counter) {
  if (loc < 0) return;
  glUniformMatrix4x3fv(loc, count, GL_FALSE, columnMajor);
  counter += size_t(count) * 12 * sizeof(float);
}

}  // namespace mb::gl
