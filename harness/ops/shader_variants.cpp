#include "harness/ops/shader_variants.h"

#include "pipelines/registry.h"

namespace mb::opsv {

std::vector<ShaderVariant> shaderVariants() {
  std::vector<ShaderVariant> out;
  for (const PipelineEntry& p : registeredPipelines())
    for (const mb::ShaderVariant& v : p.variants)
      out.push_back({p.name, v.stage, v.defines, v.draws, v.kernels, v.note, v.fragment});
  return out;
}

}  // namespace mb::opsv
