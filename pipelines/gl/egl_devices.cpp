#include "pipelines/gl/egl_devices.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace mb::gl {
bool eglExtensionListed(const char* list, const char* ext) {
  if (!list) return false;
  const size_t n = std::strlen(ext);
  for (const char* p = list; (p = std::strstr(p, ext)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::vector<EglDevice> listEglDevices(std::string* why) {
  std::vector<EglDevice> out;
  auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return out;
  };
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (!eglExtensionListed(client, "EGL_EXT_device_enumeration") || !queryDevices || !queryString)
    return fail("EGL_EXT_device_enumeration not available");
  EGLint count = 0;
  if (!queryDevices(0, nullptr, &count) || count <= 0) return fail("eglQueryDevicesEXT lists no devices");
  std::vector<EGLDeviceEXT> handles(size_t(count), nullptr);
  if (!queryDevices(count, handles.data(), &count)) return fail("eglQueryDevicesEXT failed");
  for (int i = 0; i < count; ++i) {
    EglDevice d{.index = i, .handle = handles[size_t(i)]};
    const char* exts = queryString(d.handle, EGL_EXTENSIONS);
    d.software = eglExtensionListed(exts, "EGL_MESA_device_software");
    auto text = [&](EGLint what) {
      const char* s = queryString(d.handle, what);
      return std::string(s ? s : "");
    };
    // The render node where the driver names one (needs no DRM master), else the card node.
    if (eglExtensionListed(exts, "EGL_EXT_device_drm_render_node")) d.drm = text(EGL_DRM_RENDER_NODE_FILE_EXT);
    if (d.drm.empty() && eglExtensionListed(exts, "EGL_EXT_device_drm")) d.drm = text(EGL_DRM_DEVICE_FILE_EXT);
    if (eglExtensionListed(exts, "EGL_EXT_device_query_name")) d.name = text(EGL_RENDERER_EXT);
    eglGetError();  // a string the device lacks leaves EGL_BAD_PARAMETER behind: not ours to report
    out.push_back(d);
  }
  return out;
}

std::string describeEglDevices(const std::vector<EglDevice>& devices) {
  if (devices.empty()) return "none";
  std::string s;
  for (const EglDevice& d : devices) {
    if (!s.empty()) s += "; ";
    s += std::to_string(d.index) + (d.software ? " software (Mesa llvmpipe)" : " hardware");
    if (!d.drm.empty()) s += " " + d.drm;
    if (!d.name.empty()) s += " (" + d.name + ")";
  }
  return s;
}

Result<EglDevice> findEglDevice(const GpuChoice& choice) {
  std::string why;
  const std::vector<EglDevice> devices = listEglDevices(&why);
  if (choice.index >= 0 && choice.index < int(devices.size())) return devices[size_t(choice.index)];
  return Result<EglDevice>::fail("GPU " + choice.text() + " (--gpu / MB_GPU): no such EGL device; devices seen: " +
                                 describeEglDevices(devices) + (why.empty() ? "" : " (" + why + ")"));
}

}  // namespace mb::gl
