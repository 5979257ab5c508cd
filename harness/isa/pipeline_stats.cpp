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

// What every step of `compile` shares: the device, its entry points, the pipeline's name for
// errors and the destroy calls of what was created so far.
struct Builder {
  const DeviceApi& a;
  VkDevice dev;
  const std::string& name;
  Cleanup& cleanup;
  // "" when `r` is VK_SUCCESS, else "<name>: <what> failed (<result>)".
  std::string check(VkResult r, const char* what) const {
    return r == VK_SUCCESS ? "" : name + ": " + what + " failed (" + resultName(r) + ")";
  }
};

const VkShaderStageFlags kStageFlags[2] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_FRAGMENT_BIT};

// Descriptor bindings by set, then by binding.
using SetBindings = std::map<uint32_t, std::map<uint32_t, VkDescriptorSetLayoutBinding>>;

// One shader module per stage (vertex, fragment), each destroyed by the cleanup; "" or the error.
std::string createModules(const Builder& b, const StageModule* const stages[2], VkShaderModule modules[2]) {
  for (int i = 0; i < 2; ++i) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = stages[i]->spirv.size() * sizeof(uint32_t);
    info.pCode = stages[i]->spirv.data();
    if (auto e = b.check(b.a.createShaderModule(b.dev, &info, nullptr, &modules[i]), "vkCreateShaderModule");
        !e.empty())
      return e;
    b.cleanup.steps.push_back([&a = b.a, dev = b.dev, m = modules[i]] { a.destroyShaderModule(dev, m, nullptr); });
  }
  return "";
}

// The descriptor bindings of both stages merged by (set, binding); "" or the error when one
// binding has two descriptor types.
std::string mergeBindings(const StageModule* const stages[2], const std::string& name, SetBindings& sets) {
  for (int i = 0; i < 2; ++i)
    for (const Descriptor& d : stages[i]->interface.descriptors) {
      auto [it, fresh] = sets[d.set].try_emplace(d.binding);
      VkDescriptorSetLayoutBinding& bd = it->second;
      if (!fresh && bd.descriptorType != VkDescriptorType(d.type))
        return name + ": set " + std::to_string(d.set) + " binding " + std::to_string(d.binding) +
               " has two descriptor types in the two stages";
      bd.binding = d.binding;
      bd.descriptorType = VkDescriptorType(d.type);
      bd.descriptorCount = std::max(bd.descriptorCount, d.count);
      bd.stageFlags |= kStageFlags[i];
    }
  return "";
}

// One set layout per set number up to the highest (empty ones included), then the pipeline
// layout over them; each destroyed by the cleanup; "" or the error.
std::string createLayout(const Builder& b, SetBindings& sets, VkPipelineLayout& layout) {
  const uint32_t setCount = sets.empty() ? 0 : sets.rbegin()->first + 1;
  std::vector<VkDescriptorSetLayout> layouts(setCount);
  for (uint32_t s = 0; s < setCount; ++s) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const auto& [_, bd] : sets[s]) bindings.push_back(bd);
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    if (auto e = b.check(b.a.createSetLayout(b.dev, &info, nullptr, &layouts[s]), "vkCreateDescriptorSetLayout");
        !e.empty())
      return e;
    b.cleanup.steps.push_back([&a = b.a, dev = b.dev, l = layouts[s]] { a.destroySetLayout(dev, l, nullptr); });
  }
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = setCount;
  layoutInfo.pSetLayouts = layouts.data();
  if (auto e = b.check(b.a.createPipelineLayout(b.dev, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
      !e.empty())
    return e;
  b.cleanup.steps.push_back([&a = b.a, dev = b.dev, layout] { a.destroyPipelineLayout(dev, layout, nullptr); });
  return "";
}

// A render pass of one colour attachment (RGBA8) and a depth buffer, as the GL pipelines draw;
// destroyed by the cleanup; "" or the error.
std::string createRenderPass(const Builder& b, VkRenderPass& pass) {
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
  if (auto e = b.check(b.a.createRenderPass(b.dev, &passInfo, nullptr, &pass), "vkCreateRenderPass"); !e.empty())
    return e;
  b.cleanup.steps.push_back([&a = b.a, dev = b.dev, pass] { a.destroyRenderPass(dev, pass, nullptr); });
  return "";
}

// The fixed-function state of the pipeline: triangles, back-face culling, depth test, one
// colour attachment written whole, viewport and scissor dynamic.
struct FixedState {
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  VkPipelineDepthStencilStateCreateInfo depthState{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  VkPipelineColorBlendAttachmentState blendAttachment{};
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  VkDynamicState dynamics[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};

  FixedState() {
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_BACK_BIT;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    depthState.depthTestEnable = VK_TRUE;
    depthState.depthWriteEnable = VK_TRUE;
    depthState.depthCompareOp = VK_COMPARE_OP_LESS;
    blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                     VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamics;
  }
  FixedState(const FixedState&) = delete;  // holds pointers into itself
};

// The graphics pipeline (statistics and internal representations captured), its vertex input one
// tightly packed binding per input location of the vertex interface; destroyed by the cleanup;
// "" or the error.
std::string createPipeline(const Builder& b, const StageModule& vertex, const VkShaderModule modules[2],
                           VkPipelineLayout layout, VkRenderPass pass, VkPipeline& pipeline) {
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const VertexInput& in : vertex.interface.inputs) {
    const uint32_t bi = uint32_t(bindings.size());
    bindings.push_back({bi, 4 * in.components, VK_VERTEX_INPUT_RATE_VERTEX});
    attributes.push_back({in.location, bi, formatOf(in), 0});
  }
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = uint32_t(bindings.size());
  vertexInput.pVertexBindingDescriptions = bindings.data();
  vertexInput.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();

  VkPipelineShaderStageCreateInfo shaderStages[2] = {};
  for (int i = 0; i < 2; ++i) {
    shaderStages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    shaderStages[i].stage = VkShaderStageFlagBits(kStageFlags[i]);
    shaderStages[i].module = modules[i];
    shaderStages[i].pName = "main";
  }
  const FixedState fixed;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR |
               VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;
  info.stageCount = 2;
  info.pStages = shaderStages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &fixed.assembly;
  info.pViewportState = &fixed.viewport;
  info.pRasterizationState = &fixed.raster;
  info.pMultisampleState = &fixed.multisample;
  info.pDepthStencilState = &fixed.depthState;
  info.pColorBlendState = &fixed.blend;
  info.pDynamicState = &fixed.dynamic;
  info.layout = layout;
  info.renderPass = pass;
  if (auto e = b.check(b.a.createGraphicsPipelines(b.dev, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
                       "vkCreateGraphicsPipelines");
      !e.empty())
    return e;
  b.cleanup.steps.push_back([&a = b.a, dev = b.dev, pipeline] { a.destroyPipeline(dev, pipeline, nullptr); });
  return "";
}

// The machine code of one executable: its internal representations named "Assembly" (RADV's
// name) or "ISA", joined, each without its trailing NUL ("" when the driver gives none); sizes
// first, then the texts into buffers of those sizes. "" or the error.
std::string readIsaText(const Builder& b, const VkPipelineExecutableInfoKHR& exec, std::string& isaText) {
  std::vector<VkPipelineExecutableInternalRepresentationKHR> ir;
  if (auto e = b.check(fetchAll(ir, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR},
                                [&](uint32_t* n, auto* p) { return b.a.internalRepresentations(b.dev, &exec, n, p); }),
                       "vkGetPipelineExecutableInternalRepresentationsKHR");
      !e.empty())
    return e;
  uint32_t reps = uint32_t(ir.size());
  std::vector<std::string> texts(reps);
  for (uint32_t r = 0; r < reps; ++r) {
    texts[r].resize(ir[r].dataSize);
    ir[r].pData = texts[r].data();
  }
  b.a.internalRepresentations(b.dev, &exec, &reps, ir.data());
  for (uint32_t r = 0; r < reps; ++r) {
    const std::string irName = ir[r].name;
    if (irName.find("Assembly") == std::string::npos && irName.find("ISA") == std::string::npos) continue;
    std::string t = texts[r];
    if (!t.empty() && t.back() == '\0') t.pop_back();
    isaText += t;
  }
  return "";
}

// Every executable of the pipeline, in the driver's order: stage, name, description, subgroup
// size, statistics and ISA text; "" or the error.
std::string readExecutables(const Builder& b, VkPipeline pipeline, std::vector<ExecutableStats>& out) {
  VkPipelineInfoKHR pipelineInfo{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  pipelineInfo.pipeline = pipeline;
  std::vector<VkPipelineExecutablePropertiesKHR> props;
  if (auto e = b.check(fetchAll(props, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR},
                                [&](uint32_t* n, auto* p) { return b.a.executableProperties(b.dev, &pipelineInfo, n, p); }),
                       "vkGetPipelineExecutablePropertiesKHR");
      !e.empty())
    return e;
  const uint32_t count = uint32_t(props.size());
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
    if (auto e = b.check(fetchAll(stats, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR},
                                  [&](uint32_t* n, auto* p) { return b.a.executableStatistics(b.dev, &exec, n, p); }),
                         "vkGetPipelineExecutableStatisticsKHR");
        !e.empty())
      return e;
    for (const auto& st : stats) x.statistics.push_back({st.name, valueOf(st)});
    if (auto e = readIsaText(b, exec, x.isaText); !e.empty()) return e;
    out.push_back(std::move(x));
  }
  return "";
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
  Cleanup cleanup;
  const Builder b{impl_->api, impl_->device, name, cleanup};
  const StageModule* stages[2] = {&vertex, &fragment};
  VkShaderModule modules[2] = {};
  if (auto e = createModules(b, stages, modules); !e.empty()) return R::fail(e);
  SetBindings sets;
  if (auto e = mergeBindings(stages, name, sets); !e.empty()) return R::fail(e);
  VkPipelineLayout layout;
  if (auto e = createLayout(b, sets, layout); !e.empty()) return R::fail(e);
  VkRenderPass pass;
  if (auto e = createRenderPass(b, pass); !e.empty()) return R::fail(e);
  VkPipeline pipeline;
  if (auto e = createPipeline(b, vertex, modules, layout, pass, pipeline); !e.empty()) return R::fail(e);
  std::vector<ExecutableStats> out;
  if (auto e = readExecutables(b, pipeline, out); !e.empty()) return R::fail(e);
  return out;
}

}  // namespace mb::isa
