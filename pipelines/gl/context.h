// A headless OpenGL 4.5 core context: EGL on Mesa's surfaceless platform, with OSMesa (loaded
// at run time) as the fallback when EGL cannot start. No window, no default framebuffer: draw
// into a gl::Framebuffer.
#pragma once
#include <memory>
#include <string>

#include "pipelines/result.h"

namespace mb::gl {

struct ContextInfo {
  std::string backend;   // "egl-surfaceless" or "osmesa"
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;   // GL_VERSION
  std::string vendor;    // GL_VENDOR
  std::string eglError;  // why EGL was skipped when the fallback was taken ("" otherwise)
};

class Context {
public:
  // Creates a GL 4.5 core context, makes it current on this thread and loads the entry points
  // of gl_api.h. Tries EGL surfaceless, then OSMesa. The environment variable
  // MB_GL_BACKEND=egl|osmesa restricts the choice to one backend. On failure the message says
  // what each backend reported.
  static Result<std::unique_ptr<Context>> create();
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const ContextInfo& info() const { return info_; }
  // Makes this context current on the calling thread again.
  bool makeCurrent();

  struct Impl;  // backend state (context.cpp)

private:
  Context() = default;
  std::unique_ptr<Impl> impl_;
  ContextInfo info_;
};

// The process-wide context the harness and the tests render with: created on first call and
// kept (never destroyed, so no backend teardown runs during static destruction). Later calls
// make it current again and return it; a creation failure is remembered and returned again.
Result<Context*> sharedContext();

}  // namespace mb::gl
