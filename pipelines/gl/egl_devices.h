// The EGL devices of this machine (EGL_EXT_device_enumeration): what `--gpu N` picks from and
// what an error lists when the device asked for is not there.
#pragma once
#include <string>
#include <vector>

#include "pipelines/gl/gpu_choice.h"
#include "pipelines/result.h"

namespace mb::gl {

struct EglDevice {
  int index = 0;         // position in eglQueryDevicesEXT's list
  bool software = true;  // EGL_MESA_device_software (Mesa's llvmpipe device)
  std::string drm;       // DRM render node (or card node) of a hardware device; "" when none
  std::string name;      // EGL_RENDERER_EXT where the driver offers EGL_EXT_device_query_name
  void* handle = nullptr;  // the EGLDeviceEXT
};

// Whether the space-separated EGL extension string `list` names `ext` (a whole word).
bool eglExtensionListed(const char* list, const char* ext);

// Every device eglQueryDevicesEXT lists, in its order. Empty with `why` set when the client
// extensions (EGL_EXT_device_enumeration, EGL_EXT_device_query) are missing.
std::vector<EglDevice> listEglDevices(std::string* why);

// "0 software (Mesa llvmpipe); 1 hardware /dev/dri/renderD128 (NVIDIA H100)" or "none".
std::string describeEglDevices(const std::vector<EglDevice>& devices);

// The device `choice` names (kind Device), or the error that lists the devices seen:
// "GPU 7 (--gpu / MB_GPU): no such EGL device; devices seen: 0 software (Mesa llvmpipe)".
Result<EglDevice> findEglDevice(const GpuChoice& choice);

}  // namespace mb::gl
