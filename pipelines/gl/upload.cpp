#include "pipelines/gl/upload.h"

namespace mb::gl {
namespace {

// set(loc, args...) and `bytes` counted, unless the location is -1.
template <class Set, class... Args>
void counted(Set set, GLint loc, size_t bytes, uint64_t& counter, Args... args) {
  if (loc < 0) return;
  set(loc, args...);
  counter += bytes;
}

}  // namespace

void bufferData(GLenum target, size_t bytes, const void* data, GLenum usage, uint64_t& counter) {
  glBufferData(target, GLsizeiptr(bytes), data, usage);
  if (data) counter += bytes;  // a null pointer only allocates
}

void uniform1i(GLint loc, int v, uint64_t& counter) { counted(glUniform1i, loc, sizeof v, counter, v); }

void uniform1f(GLint loc, float v, uint64_t& counter) { counted(glUniform1f, loc, sizeof v, counter, v); }

void uniform1fv(GLint loc, int count, const float* v, uint64_t& counter) {
  if (count > 0) counted(glUniform1fv, loc, size_t(count) * sizeof(float), counter, count, v);
}

void uniform3f(GLint loc, const float* v, uint64_t& counter) {
  counted(glUniform3fv, loc, 3 * sizeof(float), counter, 1, v);
}

void uniform4f(GLint loc, const float* v, uint64_t& counter) { uniform4fv(loc, 1, v, counter); }

void uniform4fv(GLint loc, int count, const float* v, uint64_t& counter) {
  counted(glUniform4fv, loc, size_t(count) * 4 * sizeof(float), counter, count, v);
}

void uniformMatrix4(GLint loc, int count, const float* columnMajor, uint64_t& counter) {
  counted(glUniformMatrix4fv, loc, size_t(count) * 16 * sizeof(float), counter, count, GL_FALSE, columnMajor);
}

void uniformMatrix3(GLint loc, int count, const float* columnMajor, uint64_t& counter) {
  counted(glUniformMatrix3fv, loc, size_t(count) * 9 * sizeof(float), counter, count, GL_FALSE, columnMajor);
}

void uniformMatrix4x3(GLint loc, int count, const float* columnMajor, uint64_t& counter) {
  counted(glUniformMatrix4x3fv, loc, size_t(count) * 12 * sizeof(float), counter, count, GL_FALSE, columnMajor);
}

}  // namespace mb::gl
