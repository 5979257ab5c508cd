// A headless OpenGL 4.5 core context on the device MB_GPU names (gpu_choice.h): an EGL device
// (EGL_EXT_platform_device: a real GPU, or Mesa's software device), Mesa's surfaceless platform,
// or OSMesa (loaded at run time) as the last fallback. No window, no default framebuffer: draw
// into a gl::Framebuffer.
#pragma once
#include <memory>
#include <string>

#include "pipelines/result.h"

namespace mb::gl {

struct ContextInfo {
  std::string backend;   // "egl-device N", "egl-surfaceless" or "osmesa"
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;   // GL_VERSION
  std::string vendor;    // GL_VENDOR
  int deviceIndex = -1;  // the EGL device drawn on (egl-device N), -1 for the other backends
  bool deviceSoftware = true;  // the device is a CPU rasteriser (EGL_MESA_device_software / GL_RENDERER)
  std::string drm;       // the hardware device's DRM node, "" when none
  // A real GPU: neither the device nor GL_RENDERER is a software rasteriser.
  bool realGpu() const;
  // "egl-device 0, software" / "egl-device 1, hardware /dev/dri/renderD128" / "egl-surfaceless"
  std::string deviceText() const;
};

class Context {
public:
  // Creates a GL 4.5 core context, makes it current on this thread and loads the entry points
  // of gl_api.h. MB_GPU (gpu_choice.h) picks the device: auto (default) tries the first hardware
  // EGL device, then EGL surfaceless, then OSMesa; llvmpipe starts at EGL surfaceless (software
  // only); N takes EGL device N or fails, listing the devices seen. MB_GL_BACKEND=egl|osmesa
  // restricts the choice to one backend. On failure the message says what each one reported.
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
