#include "harness/isa/pipeline_stats.h"

#include <cstring>
#include <functional>
#include <map>

namespace mb::isa {

namespace {

// Device-level entry points `compile` needs.
struct DeviceApi {
  PFN_vkDestroyDevice destroyDevice;
  PFN_vkCreateShaderModule createShaderModule;
  PFN_vkDestroyShaderModule destroyShaderModule;
  PFN_vkCreateDescriptorSetLayout createSetLayout;
  PFN_vkDestroyDescriptorSetLayout destroySetLayout;
  PFN_vkCreatePipelineLayout createPipelineLayout;
  PFN_vkDestroyPipelineLayout destroyPipelineLayout;
  PFN_vkCreateRenderPass createRenderPass;
  PFN_vkDestroyRenderPass destroyRenderPass;
  PFN_vkCreateGraphicsPipelines createGraphicsPipelines;
  PFN_vkDestroyPipeline destroyPipeline;
  PFN_vkGetPipelineExecutablePropertiesKHR executableProperties;
  PFN_vkGetPipelineExecutableStatisticsKHR executableStatistics;
  PFN_vkGetPipelineExecutableInternalRepresentationsKHR internalRepresentations;
};

// Runs the destroy calls of a compile in reverse order, whatever path it leaves by.
struct Cleanup {
  std::vector<std::function<void()>> steps;
  ~Cleanup() {
    for (auto s = steps.rbegin(); s != steps.rend(); ++s) (*s)();
  }
};

VkFormat formatOf(const VertexInput& in) {
  static const VkFormat kFloat[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT,
                                    VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT};
  static const VkFormat kInt[] = {VK_FORMAT_R32_SINT, VK_FORMAT_R32G32_SINT,
                                  VK_FORMAT_R32G32B32_SINT, VK_FORMAT_R32G32B32A32_SINT};
  static const VkFormat kUint[] = {VK_FORMAT_R32_UINT, VK_FORMAT_R32G32_UINT,
                                   VK_FORMAT_R32G32B32_UINT, VK_FORMAT_R32G32B32A32_UINT};
  const uint32_t i = (in.components < 1 ? 1 : in.components > 4 ? 4 : in.components) - 1;
  return in.kind == VertexInput::Float ? kFloat[i] : in.kind == VertexInput::Int ? kInt[i] : kUint[i];
}

// Vulkan's two-call enumeration: the count, then `out` filled (every element starting as `init`).
template <class T, class Call> VkResult fetchAll(std::vector<T>& out, const T& init, Call call) {
  uint32_t n = 0;
  VkResult r = call(&n, static_cast<T*>(nullptr));
  if (r != VK_SUCCESS) return r;
  out.assign(n, init);
  r = call(&n, out.data());
  out.resize(n);
  return r;
}

std::string stageOf(VkShaderStageFlags s) {
  if (s & VK_SHADER_STAGE_FRAGMENT_BIT) return "fragment";
  if (s & VK_SHADER_STAGE_VERTEX_BIT) return "vertex";
  if (s & VK_SHADER_STAGE_GEOMETRY_BIT) return "geometry";
  return "other";
}

nlohmann::json valueOf(const VkPipelineExecutableStatisticKHR& s) {
  switch (s.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: return bool(s.value.b32);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: return s.value.i64;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: return s.value.u64;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: return s.value.f64;
    default: return nullptr;
  }
}

}  // namespace

struct StatsDevice::Impl {
  VkDevice device = VK_NULL_HANDLE;
  DeviceApi api{};
};

std::vector<std::pair<VkPhysicalDevice, DeviceInfo>> listDevices(const Vulkan& vk) {
  std::vector<std::pair<VkPhysicalDevice, DeviceInfo>> out;
  uint32_t n = 0;
  if (vk.enumeratePhysicalDevices(vk.instance, &n, nullptr) != VK_SUCCESS) return out;
  std::vector<VkPhysicalDevice> devices(n);
  if (vk.enumeratePhysicalDevices(vk.instance, &n, devices.data()) != VK_SUCCESS) return out;
  devices.resize(n);
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vk.getPhysicalDeviceProperties2(d, &props);
    DeviceInfo info;
    info.deviceName = props.properties.deviceName;
    info.driverName = driver.driverName;
    info.driverInfo = driver.driverInfo;
    info.driverId = driver.driverID;
    info.deviceType = props.properties.deviceType;
    uint32_t e = 0;
    vk.enumerateDeviceExtensionProperties(d, nullptr, &e, nullptr);
    std::vector<VkExtensionProperties> exts(e);
    vk.enumerateDeviceExtensionProperties(d, nullptr, &e, exts.data());
    for (uint32_t i = 0; i < e; ++i)
      info.executableProperties = info.executableProperties ||
          std::strcmp(exts[i].extensionName, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME) == 0;
    out.push_back({d, info});
  }
  return out;
}

Result<std::unique_ptr<StatsDevice>> StatsDevice::open(const Vulkan& vk, VkPhysicalDevice physical) {
  using R = Result<std::unique_ptr<StatsDevice>>;
  uint32_t families = 0;
  vk.getQueueFamilyProperties(physical, &families, nullptr);
  if (families == 0) return R::fail("the device has no queue family");
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = 0;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR feature{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  feature.pipelineExecutableInfo = VK_TRUE;
  const char* ext = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &feature};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = &ext;
  std::unique_ptr<StatsDevice> d(new StatsDevice);
  d->impl_ = std::make_unique<Impl>();
  const VkResult r = vk.createDevice(physical, &info, nullptr, &d->impl_->device);
  if (r != VK_SUCCESS) return R::fail("vkCreateDevice failed (" + resultName(r) + ")");
  auto get = [&](const char* name) { return vk.getDeviceProcAddr(d->impl_->device, name); };
  DeviceApi& a = d->impl_->api;
#define MB_DEVICE_FN(field, name) a.field = reinterpret_cast<PFN_##name>(get(#name))
  MB_DEVICE_FN(destroyDevice, vkDestroyDevice);
  MB_DEVICE_FN(createShaderModule, vkCreateShaderModule);
  MB_DEVICE_FN(destroyShaderModule, vkDestroyShaderModule);
  MB_DEVICE_FN(createSetLayout, vkCreateDescriptorSetLayout);
  MB_DEVICE_FN(destroySetLayout, vkDestroyDescriptorSetLayout);
  MB_DEVICE_FN(createPipelineLayout, vkCreatePipelineLayout);
  MB_DEVICE_FN(destroyPipelineLayout, vkDestroyPipelineLayout);
  MB_DEVICE_FN(createRenderPass, vkCreateRenderPass);
  MB_DEVICE_FN(destroyRenderPass, vkDestroyRenderPass);
  MB_DEVICE_FN(createGraphicsPipelines, vkCreateGraphicsPipelines);
  MB_DEVICE_FN(destroyPipeline, vkDestroyPipeline);
  MB_DEVICE_FN(executableProperties, vkGetPipelineExecutablePropertiesKHR);
  MB_DEVICE_FN(executableStatistics, vkGetPipelineExecutableStatisticsKHR);
  MB_DEVICE_FN(internalRepresentations, vkGetPipelineExecutableInternalRepresentationsKHR);
#undef MB_DEVICE_FN
  if (!a.executableProperties || !a.executableStatistics || !a.internalRepresentations)
    return R::fail("the device does not resolve the VK_KHR_pipeline_executable_properties entry points");
  return d;
}

StatsDevice::~StatsDevice() {
  if (impl_ && impl_->device && impl_->api.destroyDevice) impl_->api.destroyDevice(impl_->device, nullptr);
}

Result<std::vector<ExecutableStats>> StatsDevice::compile(const StageModule& vertex,
                                                         const StageModule& fragment,
                                                         const std::string& name) {
  using R = Result<std::vector<ExecutableStats>>;
  const DeviceApi& a = impl_->api;
  VkDevice dev = impl_->device;
  Cleanup cleanup;
  auto check = [&](VkResult r, const char* what) -> std::string {
    return r == VK_SUCCESS ? "" : name + ": " + what + " failed (" + resultName(r) + ")";
  };

  VkShaderModule modules[2] = {};
  const StageModule* stages[2] = {&vertex, &fragment};
  for (int i = 0; i < 2; ++i) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = stages[i]->spirv.size() * sizeof(uint32_t);
    info.pCode = stages[i]->spirv.data();
    if (auto e = check(a.createShaderModule(dev, &info, nullptr, &modules[i]), "vkCreateShaderModule"); !e.empty())
      return R::fail(e);
    cleanup.steps.push_back([&a, dev, m = modules[i]] { a.destroyShaderModule(dev, m, nullptr); });
  }

  // Descriptor sets: the bindings of both stages, merged by (set, binding).
  std::map<uint32_t, std::map<uint32_t, VkDescriptorSetLayoutBinding>> sets;
  const VkShaderStageFlags flags[2] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_FRAGMENT_BIT};
  for (int i = 0; i < 2; ++i)
    for (const Descriptor& d : stages[i]->interface.descriptors) {
      auto [it, fresh] = sets[d.set].try_emplace(d.binding);
      VkDescriptorSetLayoutBinding& b = it->second;
      if (!fresh && b.descriptorType != VkDescriptorType(d.type))
        return R::fail(name + ": set " + std::to_string(d.set) + " binding " + std::to_string(d.binding) +
                       " has two descriptor types in the two stages");
      b.binding = d.binding;
      b.descriptorType = VkDescriptorType(d.type);
      b.descriptorCount = std::max(b.descriptorCount, d.count);
      b.stageFlags |= flags[i];
    }
  const uint32_t setCount = sets.empty() ? 0 : sets.rbegin()->first + 1;
  std::vector<VkDescriptorSetLayout> layouts(setCount);
  for (uint32_t s = 0; s < setCount; ++s) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const auto& [_, b] : sets[s]) bindings.push_back(b);
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    if (auto e = check(a.createSetLayout(dev, &info, nullptr, &layouts[s]), "vkCreateDescriptorSetLayout"); !e.empty())
      return R::fail(e);
    cleanup.steps.push_back([&a, dev, l = layouts[s]] { a.destroySetLayout(dev, l, nullptr); });
  }
  VkPipelineLayout layout;
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = setCount;
  layoutInfo.pSetLayouts = layouts.data();
  if (auto e = check(a.createPipelineLayout(dev, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout"); !e.empty())
    return R::fail(e);
  cleanup.steps.push_back([&a, dev, layout] { a.destroyPipelineLayout(dev, layout, nullptr); });

  // One colour attachment (RGBA8) and a depth buffer, as the GL pipelines draw.
  VkAttachmentDescription attachments[2] = {};
  attachments[0].format = VK_FORMAT_R8G8B8A8_UNORM;
  attachments[1].format = VK_FORMAT_D32_SFLOAT;
  for (auto& at : attachments) {
    at.samples = VK_SAMPLE_COUNT_1_BIT;
    at.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    at.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    at.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    at.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  }
  attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth;
  VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  passInfo.attachmentCount = 2;
  passInfo.pAttachments = attachments;
  passInfo.subpassCount = 1;
  passInfo.pSubpasses = &subpass;
  VkRenderPass pass;
  if (auto e = check(a.createRenderPass(dev, &passInfo, nullptr, &pass), "vkCreateRenderPass"); !e.empty())
    return R::fail(e);
  cleanup.steps.push_back([&a, dev, pass] { a.destroyRenderPass(dev, pass, nullptr); });

  // Vertex input: one tightly packed binding per input location.
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const VertexInput& in : vertex.interface.inputs) {
    const uint32_t b = uint32_t(bindings.size());
    bindings.push_back({b, 4 * in.components, VK_VERTEX_INPUT_RATE_VERTEX});
    attributes.push_back({in.location, b, formatOf(in), 0});
  }
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = uint32_t(bindings.size());
  vertexInput.pVertexBindingDescriptions = bindings.data();
  vertexInput.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();

  VkPipelineShaderStageCreateInfo shaderStages[2] = {};
  for (int i = 0; i < 2; ++i) {
    shaderStages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    shaderStages[i].stage = VkShaderStageFlagBits(flags[i]);
    shaderStages[i].module = modules[i];
    shaderStages[i].pName = "main";
  }
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depthState{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depthState.depthTestEnable = VK_TRUE;
  depthState.depthWriteEnable = VK_TRUE;
  depthState.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                   VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamics;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR |
               VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;
  info.stageCount = 2;
  info.pStages = shaderStages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depthState;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  info.renderPass = pass;
  VkPipeline pipeline;
  if (auto e = check(a.createGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
                     "vkCreateGraphicsPipelines");
      !e.empty())
    return R::fail(e);
  cleanup.steps.push_back([&a, dev, pipeline] { a.destroyPipeline(dev, pipeline, nullptr); });

  VkPipelineInfoKHR pipelineInfo{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  pipelineInfo.pipeline = pipeline;
  std::vector<VkPipelineExecutablePropertiesKHR> props;
  if (auto e = check(fetchAll(props, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR},
                              [&](uint32_t* n, auto* p) { return a.executableProperties(dev, &pipelineInfo, n, p); }),
                     "vkGetPipelineExecutablePropertiesKHR");
      !e.empty())
    return R::fail(e);
  const uint32_t count = uint32_t(props.size());

  std::vector<ExecutableStats> out;
  for (uint32_t i = 0; i < count; ++i) {
    ExecutableStats x;
    x.stage = stageOf(props[i].stages);
    x.name = props[i].name;
    x.description = props[i].description;
    x.subgroupSize = props[i].subgroupSize;
    VkPipelineExecutableInfoKHR exec{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
    exec.pipeline = pipeline;
    exec.executableIndex = i;
    std::vector<VkPipelineExecutableStatisticKHR> stats;
    if (auto e = check(fetchAll(stats, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR},
                                [&](uint32_t* n, auto* p) { return a.executableStatistics(dev, &exec, n, p); }),
                       "vkGetPipelineExecutableStatisticsKHR");
        !e.empty())
      return R::fail(e);
    for (const auto& st : stats) x.statistics.push_back({st.name, valueOf(st)});

    // Sizes first, then the text into buffers of those sizes.
    std::vector<VkPipelineExecutableInternalRepresentationKHR> ir;
    if (auto e = check(fetchAll(ir, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR},
                                [&](uint32_t* n, auto* p) { return a.internalRepresentations(dev, &exec, n, p); }),
                       "vkGetPipelineExecutableInternalRepresentationsKHR");
        !e.empty())
      return R::fail(e);
    uint32_t reps = uint32_t(ir.size());
    std::vector<std::string> texts(reps);
    for (uint32_t r = 0; r < reps; ++r) {
      texts[r].resize(ir[r].dataSize);
      ir[r].pData = texts[r].data();
    }
    a.internalRepresentations(dev, &exec, &reps, ir.data());
    for (uint32_t r = 0; r < reps; ++r) {
      // The machine code: RADV names it "Assembly"; other drivers may give none.
      const std::string irName = ir[r].name;
      if (irName.find("Assembly") == std::string::npos && irName.find("ISA") == std::string::npos) continue;
      std::string t = texts[r];
      if (!t.empty() && t.back() == '\0') t.pop_back();
      x.isaText += t;
    }
    out.push_back(std::move(x));
  }
  return out;
}

}  // namespace mb::isa
