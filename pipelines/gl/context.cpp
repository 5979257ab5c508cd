#include "pipelines/gl/context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

#include "pipelines/gl/egl_devices.h"
#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/gpu_choice.h"

namespace mb::gl {

// OSMesa is opened with dlopen, so the fallback costs nothing when libOSMesa is absent; the
// constants are those of <GL/osmesa.h> (that header pulls in <GL/gl.h>, which gl_api.h avoids).
namespace osmesa {
constexpr int kFormat = 0x22, kDepthBits = 0x30, kStencilBits = 0x31, kAccumBits = 0x32;
constexpr int kProfile = 0x33, kCoreProfile = 0x34, kMajor = 0x36, kMinor = 0x37;
using CreateFn = void* (*)(const int* attribs, void* share);
using MakeCurrentFn = unsigned char (*)(void* ctx, void* buffer, GLenum type, int w, int h);
using DestroyFn = void (*)(void* ctx);
}  // namespace osmesa

// The GL pointers are process-global; this records which context's backend filled them, so
// switching between an EGL and an OSMesa context reloads them.
const void* gPointersLoadedFor = nullptr;

struct Context::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  void* osLib = nullptr;
  void* osContext = nullptr;
  osmesa::MakeCurrentFn osMakeCurrent = nullptr;
  osmesa::DestroyFn osDestroy = nullptr;
  GetProcFn osGetProc = nullptr;
  unsigned char osBuffer[4 * 4 * 4] = {};  // OSMesa needs a colour buffer to be current

  // Makes the context current and (re)loads the GL pointers from its backend when needed.
  // Returns "" or what went wrong.
  std::string makeCurrent();
  // Drops the context: a failed attempt's half-made one, or this one at destruction. The OSMesa
  // library stays loaded: GL pointers may still refer into it.
  ~Impl() {
    if (context != EGL_NO_CONTEXT) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display, context);
    }
    if (osContext) osDestroy(osContext);
    if (gPointersLoadedFor == this) gPointersLoadedFor = nullptr;
  }
};

namespace {

std::string eglErrorText(const std::string& what) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what.c_str(), eglGetError());
  return buf;
}

void* eglProc(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

// The GL 4.5 core context on the display of `platform` (client extension `extension`) for
// `native`, a platform without windows (surfaceless, or one device): no surface at all
// (EGL_KHR_surfaceless_context), rendering into FBOs only.
std::string startPlatform(Context::Impl& s, const char* extension, EGLenum platform, void* native,
                          const std::string& name) {
  if (!eglExtensionListed(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), extension))
    return std::string(extension) + " not available";
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return "eglGetPlatformDisplayEXT not available";
  s.display = getPlatformDisplay(platform, native, nullptr);
  if (s.display == EGL_NO_DISPLAY) return eglErrorText("eglGetPlatformDisplayEXT(" + name + ")");
  if (!eglInitialize(s.display, nullptr, nullptr)) return eglErrorText("eglInitialize");  // version not needed
  const char* exts = eglQueryString(s.display, EGL_EXTENSIONS);
  if (!eglExtensionListed(exts, "EGL_KHR_surfaceless_context"))
    return "EGL_KHR_surfaceless_context not available";
  if (!eglBindAPI(EGL_OPENGL_API)) return eglErrorText("eglBindAPI(EGL_OPENGL_API)");

  EGLConfig config = nullptr;  // EGL_NO_CONFIG_KHR
  if (!eglExtensionListed(exts, "EGL_KHR_no_config_context")) {
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(s.display, want, &config, 1, &count) || count < 1)
      return eglErrorText("eglChooseConfig");
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  s.context = eglCreateContext(s.display, config, EGL_NO_CONTEXT, attribs);
  if (s.context == EGL_NO_CONTEXT) return eglErrorText("eglCreateContext(GL 4.5 core)");
  return s.makeCurrent();
}

// One EGL device (EGL_EXT_platform_device): how NVIDIA's EGL, which has no surfaceless
// platform, offers a headless context; Mesa offers its software device the same way. `info`
// names the device when its context started.
std::string startDevice(Context::Impl& s, const EglDevice& device, ContextInfo& info) {
  std::string why = startPlatform(s, "EGL_EXT_platform_device", EGL_PLATFORM_DEVICE_EXT, device.handle,
                                  "device " + std::to_string(device.index));
  if (!why.empty()) return why;
  info.backend = "egl-device " + std::to_string(device.index);
  info.deviceIndex = device.index, info.deviceSoftware = device.software, info.drm = device.drm;
  return "";
}

std::string startOsmesa(Context::Impl& s) {
  for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"})
    if ((s.osLib = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
  if (!s.osLib) return "libOSMesa not found (dlopen libOSMesa.so.8/.6/.so)";
  auto create = reinterpret_cast<osmesa::CreateFn>(dlsym(s.osLib, "OSMesaCreateContextAttribs"));
  s.osMakeCurrent = reinterpret_cast<osmesa::MakeCurrentFn>(dlsym(s.osLib, "OSMesaMakeCurrent"));
  s.osDestroy = reinterpret_cast<osmesa::DestroyFn>(dlsym(s.osLib, "OSMesaDestroyContext"));
  s.osGetProc = reinterpret_cast<GetProcFn>(dlsym(s.osLib, "OSMesaGetProcAddress"));
  if (!create || !s.osMakeCurrent || !s.osDestroy || !s.osGetProc)
    return "libOSMesa lacks OSMesaCreateContextAttribs/MakeCurrent/GetProcAddress";
  const int attribs[] = {osmesa::kFormat, GL_RGBA, osmesa::kDepthBits, 24,
                         osmesa::kStencilBits, 0, osmesa::kAccumBits, 0,
                         osmesa::kProfile, osmesa::kCoreProfile,
                         osmesa::kMajor, 4, osmesa::kMinor, 5, 0};
  s.osContext = create(attribs, nullptr);
  if (!s.osContext) return "OSMesaCreateContextAttribs(GL 4.5 core) failed";
  return s.makeCurrent();
}

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

std::string Context::Impl::makeCurrent() {
  const bool egl = context != EGL_NO_CONTEXT;
  // After another backend was current, EGL (glvnd) may still consider this context current
  // and skip re-installing its dispatch; releasing first forces a full bind.
  if (gPointersLoadedFor != this && egl)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  const bool bound = egl ? eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) == EGL_TRUE
                         : osContext && osMakeCurrent(osContext, osBuffer, GL_UNSIGNED_BYTE, 4, 4) != 0;
  if (!bound) return egl ? eglErrorText("eglMakeCurrent(no surface)") : "OSMesaMakeCurrent failed";
  if (gPointersLoadedFor == this) return "";
  std::string missing = loadGlFunctions(egl ? eglProc : osGetProc);
  if (!missing.empty()) return "GL entry points missing: " + missing;
  gPointersLoadedFor = this;
  return "";
}

Context::~Context() = default;

bool Context::makeCurrent() { return impl_ && impl_->makeCurrent().empty(); }

Result<std::unique_ptr<Context>> Context::create() {
  using R = Result<std::unique_ptr<Context>>;
  const char* force = std::getenv("MB_GL_BACKEND");
  std::string want = force ? force : "";
  if (!want.empty() && want != "egl" && want != "osmesa")
    return R::fail("MB_GL_BACKEND=" + want + ": expected egl or osmesa");
  auto choice = gpuChoiceFromEnvironment();
  if (!choice) return R::fail(choice.error());
  std::unique_ptr<Context> ctx(new Context());
  ctx->impl_ = std::make_unique<Impl>();
  ContextInfo& info = ctx->info_;

  if (choice->kind == GpuChoice::Kind::Device) {  // asked for by index: that device or an error
    if (want == "osmesa")
      return R::fail("GPU " + choice->text() + " (--gpu / MB_GPU): MB_GL_BACKEND=osmesa has no EGL devices");
    auto d = findEglDevice(*choice);
    if (!d) return R::fail(d.error());
    if (std::string why = startDevice(*ctx->impl_, *d, info); !why.empty())
      return R::fail("cannot create a GL 4.5 core context on EGL device " + choice->text() + ": " + why);
  } else {
    std::string eglWhy;  // why each EGL choice was passed over
    if (choice->kind == GpuChoice::Kind::Auto && want != "osmesa") {  // first hardware device
      for (const EglDevice& d : listEglDevices(nullptr)) {
        if (d.software) continue;
        const std::string why = startDevice(*ctx->impl_, d, info);
        if (why.empty()) break;
        eglWhy += "EGL device " + std::to_string(d.index) + ": " + why + "; ";
        ctx->impl_ = std::make_unique<Impl>();  // the next attempt starts from a fresh state
      }
    }
    if (info.backend.empty()) {
      // llvmpipe asked for: Mesa's surfaceless platform must not pick a hardware driver.
      if (choice->kind == GpuChoice::Kind::Llvmpipe) setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
      // Mesa's surfaceless platform (llvmpipe where no hardware driver claims it).
      const std::string why = want != "osmesa" ? startPlatform(*ctx->impl_, "EGL_MESA_platform_surfaceless",
                                                               EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                                               "surfaceless")
                                               : "skipped (MB_GL_BACKEND=osmesa)";
      eglWhy += why;
      if (why.empty()) info.backend = "egl-surfaceless";
    }
    if (info.backend.empty()) {
      ctx->impl_ = std::make_unique<Impl>();
      const std::string osWhy = want == "egl" ? "skipped (MB_GL_BACKEND=egl)" : startOsmesa(*ctx->impl_);
      if (!osWhy.empty())
        return R::fail("cannot create a GL 4.5 core context: EGL: " + eglWhy + "; OSMesa: " + osWhy);
      info.backend = "osmesa";
    }
  }
  info.renderer = glString(GL_RENDERER);
  info.version = glString(GL_VERSION);
  info.vendor = glString(GL_VENDOR);
  if (info.deviceIndex < 0) info.deviceSoftware = isSoftwareRenderer(info.renderer);
  return ctx;
}

bool ContextInfo::realGpu() const { return !deviceSoftware && !isSoftwareRenderer(renderer); }

std::string ContextInfo::deviceText() const {
  if (deviceIndex < 0) return backend;
  return backend + (deviceSoftware ? ", software" : ", hardware") + (drm.empty() ? "" : " " + drm);
}

Result<Context*> sharedContext() {
  static Context* shared = nullptr;
  static std::string failure;
  if (shared && !shared->makeCurrent()) return Result<Context*>::fail("GL context: make-current failed");
  if (!shared && failure.empty()) {
    auto created = Context::create();
    if (created) shared = created.take().release();  // intentionally kept for the process lifetime
    else failure = created.error();
  }
  if (!shared) return Result<Context*>::fail(failure);
  return shared;
}

}  // namespace mb::gl
