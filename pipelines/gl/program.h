// A linked GL program from a vertex and a fragment shader file, with #include/#define
// expansion (shader_source.h). Compile and link errors come back as a Result whose message
// names the file and line of each diagnostic.
#pragma once
#include <memory>
#include <string>
#include <unordered_map>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/shader_source.h"
#include "pipelines/result.h"

namespace mb::gl {

// Defines added (after the caller's) to every program linked from now on: a process-wide view
// mode such as survey's geometry view (MB_GEOMETRY_VIEW, forward.fs). Programs linked before
// keep theirs. Not thread-safe: set it between frames of one thread's context.
void setGlobalDefines(Defines defines);
const Defines& globalDefines();

class Program {
public:
  // `vsPath` and `fsPath` are absolute or relative to shaderDir(); `defines` go to both stages.
  // Needs a current context.
  static Result<std::unique_ptr<Program>> fromFiles(const std::string& vsPath,
                                                    const std::string& fsPath,
                                                    const Defines& defines = {});
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  void use() const { glUseProgram(id_); }
  // Location of a uniform (cached); -1 when the program does not use it.
  GLint uniform(const std::string& name) const;

private:
  Program() = default;
  GLuint id_ = 0;
  mutable std::unordered_map<std::string, GLint> uniforms_;
};

}  // namespace mb::gl
