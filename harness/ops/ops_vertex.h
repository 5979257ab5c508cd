// harness/ops/ops_vertex.h: ops per vertex of each pipeline, measured two ways:
//  (a) counted: the per-vertex GLSL functions (vertex_kernels.h) executed once on mb::Counted
//      through the shim;
//  (b) SPIR-V: the same function called from a small probe vertex shader, and every real
//      vertex-shader variant (shader_variants.h), compiled and counted by spirv_count.h.
// A variant's counted ops are the sum of the kernels its main() calls; pipeline_ops.h reduces
// the variants to one row per registered pipeline.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/ops/shader_variants.h"
#include "harness/ops/spirv_count.h"
#include "harness/ops/vertex_inputs.h"
#include "harness/ops/vertex_kernels.h"

namespace mb::opsv {

struct KernelRow {
  VertexKernel kernel;
  OpCounts counted;
  // The probe after inlining only, after -O without instruction folding, after spirv-opt -O.
  std::optional<spirv::Counts> inlined, noFold, optimised;
  std::string error;  // why the SPIR-V side is missing
  std::string why;    // "" when counted and optimised SPIR-V agree
};

struct VariantRow {
  ShaderVariant variant;
  OpCounts counted;                       // sum of the counted kernels it calls
  std::optional<spirv::Counts> probes;    // sum of those kernels' optimised probes
  std::optional<spirv::Counts> shader;    // the whole variant, spirv-opt -O
  std::string error, why;
  bool kernelsResolved = true;            // every kernel it names was found (findKernel)
};

struct VertexOps {
  std::vector<KernelRow> kernels;
  std::vector<VariantRow> variants;
  std::string toolsProblem;  // non-empty: no SPIR-V column
};

// The kernel a variant of `pipeline` means by `function`: the one of that pipeline, else the
// only kernel with that function (a function counted per space, such as curvedMotorVertex, is
// resolved by pipeline). nullptr when none or ambiguous.
const KernelRow* findKernel(const std::vector<KernelRow>& kernels, const std::string& pipeline,
                            const std::string& function);

// How much SPIR-V to compile: none (counted only), the optimised probe of every kernel (what
// pipeline_ops.h needs), or everything (`motorbench ops`, the report: also the inlined-only and
// no-folding probes and every whole variant).
enum class SpirvDepth { None, Probes, Full };

// Counts every kernel and, when the tools run, compiles the SPIR-V `depth` asks for. A variant
// naming a kernel findKernel cannot resolve carries an error and no counts. `step` (when set) is
// called after each kernel and variant with (done, total, what): compiling them all takes a
// minute or more, and a caller such as the report shows progress.
using OpsStep = std::function<void(size_t done, size_t total, const std::string& what)>;
VertexOps measureVertexOps(SpirvDepth depth = SpirvDepth::Full, const OpsStep& step = {});
std::string formatVertexOps(const VertexOps& ops);
nlohmann::json toJson(const VertexOps& ops);

}  // namespace mb::opsv

