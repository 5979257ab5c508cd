#include "pipelines/gl/context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "pipelines/gl/gl_api.h"

namespace mb::gl {

// OSMesa is opened with dlopen, so the fallback costs nothing when libOSMesa is absent; the
// constants are those of <GL/osmesa.h> (that header pulls in <GL/gl.h>, which gl_api.h avoids).
namespace osmesa {
constexpr int kFormat = 0x22, kDepthBits = 0x30, kStencilBits = 0x31, kAccumBits = 0x32;
constexpr int kProfile = 0x33, kCoreProfile = 0x34, kMajor = 0x36, kMinor = 0x37;
using CreateFn = void* (*)(const int* attribs, void* share);
using MakeCurrentFn = unsigned char (*)(void* ctx, void* buffer, GLenum type, int w, int h);
using DestroyFn = void (*)(void* ctx);
using GetProcFn = void* (*)(const char* name);
GetProcFn getProc = nullptr;  // set when the OSMesa backend is in use
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
  std::vector<unsigned char> osBuffer;  // OSMesa needs a colour buffer to be current

  bool bind() {
    if (context != EGL_NO_CONTEXT)
      return eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) == EGL_TRUE;
    if (osContext) return osMakeCurrent(osContext, osBuffer.data(), GL_UNSIGNED_BYTE, 4, 4) != 0;
    return false;
  }
  // Makes the context current and (re)loads the GL pointers from its backend when needed.
  // Returns "" or what went wrong.
  std::string makeCurrent();
};

namespace {

std::string eglErrorText(const char* what) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what, eglGetError());
  return buf;
}

void* eglProc(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
void* osmesaProc(const char* name) { return osmesa::getProc(name); }

bool hasExtension(const char* list, const char* ext) {
  if (!list) return false;
  size_t n = std::strlen(ext);
  for (const char* p = list; (p = std::strstr(p, ext)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// EGL on the surfaceless platform: no window system, no pbuffer; the context is made current
// with no surface (EGL_KHR_surfaceless_context) and renders into FBOs only.
std::string startEgl(Context::Impl& s) {
  const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExts, "EGL_MESA_platform_surfaceless"))
    return "EGL_MESA_platform_surfaceless not available";
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return "eglGetPlatformDisplayEXT not available";
  s.display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (s.display == EGL_NO_DISPLAY) return eglErrorText("eglGetPlatformDisplayEXT(surfaceless)");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(s.display, &major, &minor)) return eglErrorText("eglInitialize");
  const char* exts = eglQueryString(s.display, EGL_EXTENSIONS);
  if (!hasExtension(exts, "EGL_KHR_surfaceless_context"))
    return "EGL_KHR_surfaceless_context not available";
  if (!eglBindAPI(EGL_OPENGL_API)) return eglErrorText("eglBindAPI(EGL_OPENGL_API)");

  EGLConfig config = nullptr;  // EGL_NO_CONFIG_KHR
  if (!hasExtension(exts, "EGL_KHR_no_config_context")) {
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

std::string startOsmesa(Context::Impl& s) {
  for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"})
    if ((s.osLib = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
  if (!s.osLib) return "libOSMesa not found (dlopen libOSMesa.so.8/.6/.so)";
  auto create = reinterpret_cast<osmesa::CreateFn>(dlsym(s.osLib, "OSMesaCreateContextAttribs"));
  s.osMakeCurrent = reinterpret_cast<osmesa::MakeCurrentFn>(dlsym(s.osLib, "OSMesaMakeCurrent"));
  s.osDestroy = reinterpret_cast<osmesa::DestroyFn>(dlsym(s.osLib, "OSMesaDestroyContext"));
  osmesa::getProc = reinterpret_cast<osmesa::GetProcFn>(dlsym(s.osLib, "OSMesaGetProcAddress"));
  if (!create || !s.osMakeCurrent || !s.osDestroy || !osmesa::getProc)
    return "libOSMesa lacks OSMesaCreateContextAttribs/MakeCurrent/GetProcAddress";
  const int attribs[] = {osmesa::kFormat, GL_RGBA, osmesa::kDepthBits, 24,
                         osmesa::kStencilBits, 0, osmesa::kAccumBits, 0,
                         osmesa::kProfile, osmesa::kCoreProfile,
                         osmesa::kMajor, 4, osmesa::kMinor, 5, 0};
  s.osContext = create(attribs, nullptr);
  if (!s.osContext) return "OSMesaCreateContextAttribs(GL 4.5 core) failed";
  s.osBuffer.assign(4 * 4 * 4, 0);
  return s.makeCurrent();
}

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

std::string Context::Impl::makeCurrent() {
  // After another backend was current, EGL (glvnd) may still consider this context current
  // and skip re-installing its dispatch; releasing first forces a full bind.
  if (gPointersLoadedFor != this && context != EGL_NO_CONTEXT)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (!bind()) return context != EGL_NO_CONTEXT ? eglErrorText("eglMakeCurrent(surfaceless)")
                                                : "OSMesaMakeCurrent failed";
  if (gPointersLoadedFor == this) return "";
  std::string missing = loadGlFunctions(context != EGL_NO_CONTEXT ? eglProc : osmesaProc);
  if (!missing.empty()) return "GL entry points missing: " + missing;
  gPointersLoadedFor = this;
  return "";
}

Context::~Context() {
  if (!impl_) return;
  if (impl_->context != EGL_NO_CONTEXT) {
    eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(impl_->display, impl_->context);
  }
  if (impl_->osContext) impl_->osDestroy(impl_->osContext);
  if (gPointersLoadedFor == impl_.get()) gPointersLoadedFor = nullptr;
  // The OSMesa library stays loaded: GL pointers may still refer into it.
}

bool Context::makeCurrent() { return impl_ && impl_->makeCurrent().empty(); }

Result<std::unique_ptr<Context>> Context::create() {
  const char* force = std::getenv("MB_GL_BACKEND");
  std::string want = force ? force : "";
  if (!want.empty() && want != "egl" && want != "osmesa")
    return Result<std::unique_ptr<Context>>::fail("MB_GL_BACKEND=" + want +
                                                  ": expected egl or osmesa");
  std::unique_ptr<Context> ctx(new Context());
  ctx->impl_ = std::make_unique<Impl>();
  std::string eglWhy, osWhy;
  if (want != "osmesa") eglWhy = startEgl(*ctx->impl_);
  else eglWhy = "skipped (MB_GL_BACKEND=osmesa)";
  if (!eglWhy.empty()) {
    // Drop whatever EGL got half-way, then try the fallback with a fresh state.
    if (ctx->impl_->context != EGL_NO_CONTEXT) {
      eglMakeCurrent(ctx->impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(ctx->impl_->display, ctx->impl_->context);
    }
    ctx->impl_ = std::make_unique<Impl>();
    osWhy = want == "egl" ? "skipped (MB_GL_BACKEND=egl)" : startOsmesa(*ctx->impl_);
    if (!osWhy.empty())
      return Result<std::unique_ptr<Context>>::fail("cannot create a GL 4.5 core context: EGL: " +
                                                    eglWhy + "; OSMesa: " + osWhy);
  }
  ctx->info_.backend = eglWhy.empty() ? "egl-surfaceless" : "osmesa";
  ctx->info_.eglError = eglWhy;
  ctx->info_.renderer = glString(GL_RENDERER);
  ctx->info_.version = glString(GL_VERSION);
  ctx->info_.vendor = glString(GL_VENDOR);
  return ctx;
}

Result<Context*> sharedContext() {
  static Context* shared = nullptr;
  static std::string failure;
  if (shared) {
    if (!shared->makeCurrent()) return Result<Context*>::fail("GL context: make-current failed");
    return shared;
  }
  if (!failure.empty()) return Result<Context*>::fail(failure);
  auto created = Context::create();
  if (!created) {
    failure = created.error();
    return Result<Context*>::fail(failure);
  }
  shared = created.take().release();  // intentionally kept for the process lifetime
  return shared;
}

}  // namespace mb::gl
