#include "harness/isa/spirv_interface.h"

#include <algorithm>
#include <map>
#include <set>

#define VK_NO_PROTOTYPES
#include <vulkan/vulkan_core.h>

namespace mb::isa {
namespace {

// SPIR-V opcodes, decorations and storage classes used here (SPIR-V 1.6 specification, 3.x).
enum : uint32_t {
  OpTypeInt = 21, OpTypeFloat = 22, OpTypeVector = 23, OpTypeMatrix = 24, OpTypeImage = 25,
  OpTypeSampler = 26, OpTypeSampledImage = 27, OpTypeArray = 28, OpTypeRuntimeArray = 29,
  OpTypeStruct = 30, OpTypePointer = 32, OpConstant = 43, OpVariable = 59, OpDecorate = 71,
};
enum : uint32_t { DecBlock = 2, DecBufferBlock = 3, DecBuiltIn = 11, DecLocation = 30,
                  DecBinding = 33, DecDescriptorSet = 34 };
enum : uint32_t { UniformConstant = 0, Input = 1, Uniform = 2, StorageBuffer = 12 };
constexpr uint32_t kMagic = 0x07230203, kDimBuffer = 5;

struct Type {
  uint32_t op = 0;
  std::vector<uint32_t> operands;  // the words after the result id
};

struct Module {
  std::map<uint32_t, Type> types;
  std::map<uint32_t, uint32_t> constants;              // id -> 32-bit value
  std::map<uint32_t, std::map<uint32_t, uint32_t>> decorations;  // id -> decoration -> literal
  struct Var { uint32_t id, pointerType, storage; };
  std::vector<Var> variables;

  const Type* type(uint32_t id) const {
    auto t = types.find(id);
    return t == types.end() ? nullptr : &t->second;
  }
  bool decorated(uint32_t id, uint32_t dec) const {
    auto d = decorations.find(id);
    return d != decorations.end() && d->second.count(dec);
  }
  uint32_t decoration(uint32_t id, uint32_t dec) const { return decorations.at(id).at(dec); }
};

// Strips arrays (multiplying their lengths into `count`) down to the element type.
const Type* element(const Module& m, uint32_t id, uint32_t& count, uint32_t& elementId) {
  const Type* t = m.type(id);
  elementId = id;
  while (t && (t->op == OpTypeArray || t->op == OpTypeRuntimeArray)) {
    if (t->op == OpTypeArray) {
      auto c = m.constants.find(t->operands.at(1));
      count *= c == m.constants.end() ? 1 : c->second;
    }
    elementId = t->operands.at(0);
    t = m.type(elementId);
  }
  return t;
}

int descriptorType(const Module& m, const Type& t, uint32_t typeId, uint32_t storage) {
  if (storage == StorageBuffer) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  if (storage == Uniform)
    return m.decorated(typeId, DecBufferBlock) ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                               : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  if (t.op == OpTypeSampler) return VK_DESCRIPTOR_TYPE_SAMPLER;
  const Type* image = &t;
  if (t.op == OpTypeSampledImage) image = m.type(t.operands.at(0));
  if (!image || image->op != OpTypeImage) return -1;
  // OpTypeImage operands: sampled type, Dim, Depth, Arrayed, MS, Sampled (1 sampled, 2 storage).
  const bool buffer = image->operands.at(1) == kDimBuffer;
  const bool storageImage = image->operands.at(5) == 2;
  if (buffer) return storageImage ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  if (storageImage) return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  return t.op == OpTypeSampledImage ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                                    : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
}

// The locations a vertex input of type `id` takes: scalar/vector one, matrix one per column.
bool addInputs(const Module& m, uint32_t id, uint32_t location, std::vector<VertexInput>& out) {
  uint32_t count = 1, elemId = 0;
  const Type* t = element(m, id, count, elemId);
  if (!t) return false;
  uint32_t columns = 1;
  if (t->op == OpTypeMatrix) {
    columns = t->operands.at(1);
    t = m.type(t->operands.at(0));
  }
  uint32_t comps = 1;
  if (t && t->op == OpTypeVector) {
    comps = t->operands.at(1);
    t = m.type(t->operands.at(0));
  }
  if (!t || (t->op != OpTypeFloat && t->op != OpTypeInt)) return false;
  VertexInput::Kind kind = t->op == OpTypeFloat ? VertexInput::Float
                           : t->operands.at(1) ? VertexInput::Int : VertexInput::Uint;
  for (uint32_t i = 0; i < count * columns; ++i) out.push_back({location + i, kind, comps});
  return true;
}

}  // namespace

Result<ShaderInterface> readInterface(const std::vector<uint32_t>& words, const std::string& name) {
  using R = Result<ShaderInterface>;
  if (words.size() < 5 || words[0] != kMagic) return R::fail(name + ": not a SPIR-V module");
  Module m;
  for (size_t i = 5; i < words.size();) {
    const uint32_t n = words[i] >> 16, op = words[i] & 0xffff;
    if (n == 0 || i + n > words.size()) return R::fail(name + ": truncated SPIR-V instruction");
    const uint32_t* w = &words[i];
    if (op >= OpTypeInt && op <= OpTypePointer && n >= 2)
      m.types[w[1]] = Type{op, std::vector<uint32_t>(w + 2, w + n)};
    else if (op == OpConstant && n >= 4) m.constants[w[2]] = w[3];
    else if (op == OpVariable && n >= 4) m.variables.push_back({w[2], w[1], w[3]});
    else if (op == OpDecorate && n >= 3) m.decorations[w[1]][w[2]] = n >= 4 ? w[3] : 0;
    i += n;
  }
  ShaderInterface out;
  for (const auto& v : m.variables) {
    const Type* ptr = m.type(v.pointerType);
    if (!ptr || ptr->op != OpTypePointer || ptr->operands.size() < 2) continue;
    const uint32_t pointee = ptr->operands[1];
    if (v.storage == Input) {
      if (m.decorated(v.id, DecBuiltIn) || !m.decorated(v.id, DecLocation)) continue;
      if (!addInputs(m, pointee, m.decoration(v.id, DecLocation), out.inputs))
        return R::fail(name + ": vertex input %" + std::to_string(v.id) + " has an unsupported type");
      continue;
    }
    if (v.storage != UniformConstant && v.storage != Uniform && v.storage != StorageBuffer) continue;
    if (!m.decorated(v.id, DecBinding)) continue;
    Descriptor d;
    d.set = m.decorated(v.id, DecDescriptorSet) ? m.decoration(v.id, DecDescriptorSet) : 0;
    d.binding = m.decoration(v.id, DecBinding);
    uint32_t elemId = 0;
    const Type* t = element(m, pointee, d.count, elemId);
    d.type = t ? descriptorType(m, *t, elemId, v.storage) : -1;
    if (d.type < 0)
      return R::fail(name + ": resource at set " + std::to_string(d.set) + " binding " +
                     std::to_string(d.binding) + " has a type this reader does not know");
    out.descriptors.push_back(d);
  }
  std::sort(out.descriptors.begin(), out.descriptors.end(), [](const Descriptor& a, const Descriptor& b) {
    return a.set != b.set ? a.set < b.set : a.binding < b.binding;
  });
  std::sort(out.inputs.begin(), out.inputs.end(),
            [](const VertexInput& a, const VertexInput& b) { return a.location < b.location; });
  return out;
}

}  // namespace mb::isa
