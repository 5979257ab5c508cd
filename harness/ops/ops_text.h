// Short texts the ops listings share.
#pragma once
#include <string>

#include "harness/ops/shader_variants.h"
#include "shaders/shim/counted.h"

namespace mb::opsv {

// "mul/add/div/sqrt/other"
inline std::string text(const OpCounts& c) {
  return std::to_string(c.mul) + "/" + std::to_string(c.add) + "/" + std::to_string(c.div) +
         "/" + std::to_string(c.sqrt) + "/" + std::to_string(c.other);
}

// The variant's #defines, "NAME NAME=VALUE", "-" when none.
inline std::string describeDefines(const ShaderVariant& v) {
  std::string s;
  for (const auto& [name, value] : v.defines) s += (s.empty() ? "" : " ") + name + (value.empty() ? "" : "=" + value);
  return s.empty() ? "-" : s;
}

}  // namespace mb::opsv
