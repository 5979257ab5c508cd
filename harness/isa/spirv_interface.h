// What a pipeline layout and a vertex input state need to know about a SPIR-V module, read
// from the module itself: every descriptor (DescriptorSet/Binding decorations and the
// variable's type) and every vertex input (Location and type). Pure data, no Vulkan calls,
// so the descriptor types are Vulkan's enum values as plain integers.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::isa {

struct Descriptor {
  uint32_t set = 0, binding = 0;
  int type = 0;        // VkDescriptorType
  uint32_t count = 1;  // array length (1 when not an array)
};

// One vertex input location: `components` 32-bit values of `kind`.
struct VertexInput {
  enum Kind { Float, Int, Uint };
  uint32_t location = 0;
  Kind kind = Float;
  uint32_t components = 4;
};

struct ShaderInterface {
  std::vector<Descriptor> descriptors;  // sorted by set, binding
  std::vector<VertexInput> inputs;      // user inputs (no built-ins), sorted by location; a
                                        // matrix takes one location per column
};

// Reads a SPIR-V binary; `name` labels errors (a truncated or non-SPIR-V file).
Result<ShaderInterface> readInterface(const std::vector<uint32_t>& words, const std::string& name);

}  // namespace mb::isa
