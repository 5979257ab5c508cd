#include "pipelines/gl/program.h"

#include <utility>

namespace mb::gl {
namespace {

// The info log of a shader or program (`getiv` / `getLog` pick which).
template <class GetIv, class GetLog>
std::string infoLog(GLuint id, GetIv getiv, GetLog getLog) {
  GLint len = 0;
  getiv(id, GL_INFO_LOG_LENGTH, &len);
  std::string log(size_t(len > 0 ? len : 1), '\0');
  getLog(id, GLsizei(log.size()), nullptr, log.data());
  return log.c_str();
}

// Compiles one stage; on failure `error` holds the log with positions mapped to files.
GLuint compile(GLenum stage, const std::string& path, const Defines& defines, std::string& error) {
  auto src = expandShaderFile(path, defines);
  if (!src) {
    error = src.error();
    return 0;
  }
  GLuint shader = glCreateShader(stage);
  const char* text = src->text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    error = src->files[0] + ": compile failed:\n" + mapLog(infoLog(shader, glGetShaderiv, glGetShaderInfoLog), src->files);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

constinit Defines gGlobalDefines;  // setGlobalDefines()'s; constinit, so usable before main()

}  // namespace

void setGlobalDefines(Defines defines) { gGlobalDefines = std::move(defines); }
const Defines& globalDefines() { return gGlobalDefines; }

Result<std::unique_ptr<Program>> Program::fromFiles(const std::string& vsPath,
                                                    const std::string& fsPath,
                                                    const Defines& ownDefines) {
  using R = Result<std::unique_ptr<Program>>;
  Defines defines = ownDefines;
  defines.insert(defines.end(), globalDefines().begin(), globalDefines().end());
  std::string error;
  const GLuint vs = compile(GL_VERTEX_SHADER, vsPath, defines, error);
  const GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, fsPath, defines, error) : 0;
  if (!fs) {
    glDeleteShader(vs);  // GL ignores 0 (the vertex shader failed)
    return R::fail(error);
  }
  std::unique_ptr<Program> p(new Program());
  p->id_ = glCreateProgram();
  for (GLuint s : {vs, fs}) glAttachShader(p->id_, s);
  glLinkProgram(p->id_);
  for (GLuint s : {vs, fs}) {
    glDetachShader(p->id_, s);
    glDeleteShader(s);
  }
  GLint ok = 0;
  glGetProgramiv(p->id_, GL_LINK_STATUS, &ok);
  if (!ok) return R::fail(vsPath + " + " + fsPath + ": link failed:\n" + infoLog(p->id_, glGetProgramiv, glGetProgramInfoLog));
  return p;
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

GLint Program::uniform(const std::string& name) const {
  auto it = uniforms_.find(name);
  if (it != uniforms_.end()) return it->second;
  GLint loc = glGetUniformLocation(id_, name.c_str());
  uniforms_.emplace(name, loc);
  return loc;
}

}  // namespace mb::gl
