#include "harness/claims/claims_vertex_ops.h"

#include "pipelines/pipeline.h"

namespace mb::claims {

const opsv::VertexOps& vertexOps() {
  static const opsv::VertexOps ops = opsv::measureVertexOps();
  return ops;
}

std::map<std::string, double> opsPerPipeline(const std::string& label, bool spirv, std::string& zero) {
  auto total = [](const auto& c) { return double(c.mul + c.add + c.div + c.sqrt + c.other); };
  std::map<std::string, double> out;
  if (!spirv) {
    // Counted only: the variant's kernels on mb::Counted, no compiler run.
    std::map<std::string, OpCounts> kernels;
    for (const opsv::VertexKernel& k : opsv::vertexKernels()) kernels.emplace(k.function, opsv::countVertexKernel(k));
    for (const std::string& p : pipelineNames())
      for (const opsv::ShaderVariant& v : opsv::shaderVariants()) {
        if (v.pipeline != p || v.label != label) continue;
        double sum = 0;
        for (const std::string& f : v.kernels)
          if (kernels.count(f)) sum += total(kernels.at(f));
        if (sum > 0) out[p] = sum;
        else zero += (zero.empty() ? "" : ", ") + p;
        break;
      }
    return out;
  }
  for (const std::string& p : pipelineNames())
    for (const opsv::VariantRow& v : vertexOps().variants) {
      if (v.variant.pipeline != p || v.variant.label != label) continue;
      if (!v.probes) break;
      if (total(*v.probes) > 0) out[p] = total(*v.probes);
      else zero += (zero.empty() ? "" : ", ") + p;
      break;
    }
  return out;
}

}  // namespace mb::claims
