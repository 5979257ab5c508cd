// The Vulkan loader, opened at run time (dlopen of libvulkan.so.1), so that motorbench runs on
// a machine without Vulkan and `isa` can say so instead of the program failing to start. Only
// the entry points `isa` calls are resolved.
#pragma once
#include <string>

#define VK_NO_PROTOTYPES
#include <vulkan/vulkan_core.h>

#include "pipelines/result.h"

namespace mb::isa {

struct Vulkan {
  void* library = nullptr;
  PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
  PFN_vkCreateInstance createInstance = nullptr;
  PFN_vkEnumerateInstanceVersion enumerateInstanceVersion = nullptr;
  // Instance level, filled by loadInstance().
  VkInstance instance = VK_NULL_HANDLE;
  PFN_vkDestroyInstance destroyInstance = nullptr;
  PFN_vkEnumeratePhysicalDevices enumeratePhysicalDevices = nullptr;
  PFN_vkGetPhysicalDeviceProperties2 getPhysicalDeviceProperties2 = nullptr;
  PFN_vkEnumerateDeviceExtensionProperties enumerateDeviceExtensionProperties = nullptr;
  PFN_vkGetPhysicalDeviceQueueFamilyProperties getQueueFamilyProperties = nullptr;
  PFN_vkCreateDevice createDevice = nullptr;
  PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;

  Vulkan() = default;
  Vulkan(const Vulkan&) = delete;
  Vulkan& operator=(const Vulkan&) = delete;
  ~Vulkan();
};

// Opens the loader; the error says "libvulkan.so.1 not found (install libvulkan1)".
Status openLoader(Vulkan& vk);
// Creates an instance (Vulkan 1.1: properties2) and resolves the instance-level entry points.
// The error names the loader's result, e.g. "no Vulkan driver (VK_ERROR_INCOMPATIBLE_DRIVER)".
Status createInstance(Vulkan& vk);

// "VK_ERROR_INCOMPATIBLE_DRIVER" for a VkResult.
std::string resultName(VkResult r);

}  // namespace mb::isa
