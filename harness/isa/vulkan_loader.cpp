#include "harness/isa/vulkan_loader.h"

#include <dlfcn.h>

namespace mb::isa {

Vulkan::~Vulkan() {
  if (instance && destroyInstance) destroyInstance(instance, nullptr);
  if (library) dlclose(library);
}

std::string resultName(VkResult r) {
  switch (r) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
    default: return "VkResult " + std::to_string(int(r));
  }
}

Status openLoader(Vulkan& vk) {
  vk.library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
  if (!vk.library) return Status::fail("the Vulkan loader libvulkan.so.1 was not found (install libvulkan1)");
  vk.getInstanceProcAddr =
      reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(vk.library, "vkGetInstanceProcAddr"));
  if (!vk.getInstanceProcAddr) return Status::fail("libvulkan.so.1 has no vkGetInstanceProcAddr");
  vk.createInstance =
      reinterpret_cast<PFN_vkCreateInstance>(vk.getInstanceProcAddr(nullptr, "vkCreateInstance"));
  vk.enumerateInstanceVersion = reinterpret_cast<PFN_vkEnumerateInstanceVersion>(
      vk.getInstanceProcAddr(nullptr, "vkEnumerateInstanceVersion"));
  if (!vk.createInstance) return Status::fail("libvulkan.so.1 has no vkCreateInstance");
  return {};
}

Status createInstance(Vulkan& vk) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "motorbench isa";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  const VkResult r = vk.createInstance(&info, nullptr, &vk.instance);
  if (r != VK_SUCCESS) {
    vk.instance = VK_NULL_HANDLE;
    return Status::fail("vkCreateInstance failed (" + resultName(r) +
                        (r == VK_ERROR_INCOMPATIBLE_DRIVER ? ": no Vulkan driver could be loaded)" : ")"));
  }
  auto get = [&](const char* name) { return vk.getInstanceProcAddr(vk.instance, name); };
  vk.destroyInstance = reinterpret_cast<PFN_vkDestroyInstance>(get("vkDestroyInstance"));
  vk.enumeratePhysicalDevices = reinterpret_cast<PFN_vkEnumeratePhysicalDevices>(get("vkEnumeratePhysicalDevices"));
  vk.getPhysicalDeviceProperties2 =
      reinterpret_cast<PFN_vkGetPhysicalDeviceProperties2>(get("vkGetPhysicalDeviceProperties2"));
  vk.enumerateDeviceExtensionProperties = reinterpret_cast<PFN_vkEnumerateDeviceExtensionProperties>(
      get("vkEnumerateDeviceExtensionProperties"));
  vk.getQueueFamilyProperties = reinterpret_cast<PFN_vkGetPhysicalDeviceQueueFamilyProperties>(
      get("vkGetPhysicalDeviceQueueFamilyProperties"));
  vk.createDevice = reinterpret_cast<PFN_vkCreateDevice>(get("vkCreateDevice"));
  vk.getDeviceProcAddr = reinterpret_cast<PFN_vkGetDeviceProcAddr>(get("vkGetDeviceProcAddr"));
  if (!vk.enumeratePhysicalDevices || !vk.getPhysicalDeviceProperties2 || !vk.createDevice ||
      !vk.getDeviceProcAddr || !vk.enumerateDeviceExtensionProperties || !vk.getQueueFamilyProperties)
    return Status::fail("the Vulkan loader lacks a Vulkan 1.1 entry point");
  return {};
}

}  // namespace mb::isa
