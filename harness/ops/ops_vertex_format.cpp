// `motorbench ops`' text and JSON of the per-vertex counts (ops_vertex.h).
#include <cstdio>

#include "harness/ops/ops_vertex.h"
#include "harness/ops/ops_text.h"

namespace mb::opsv {

using spirv::Counts;

std::string formatVertexOps(const VertexOps& ops) {
  std::string out;
  auto line = [&](const char* fmt, auto... a) {
    char buf[1024];
    std::snprintf(buf, sizeof buf, fmt, a...);
    out += buf;
  };
  out += "Ops per vertex, measured two ways (mul/add/div/sqrt/other):\n"
         "  counted: the pipeline's GLSL function executed once on mb::Counted through the shim\n"
         "  SPIR-V:  the same function called from a probe vertex shader, glslangValidator -G,\n"
         "           spirv-opt -O, vector and matrix instructions expanded to scalar ops\n";
  if (!ops.toolsProblem.empty()) out += "  (no SPIR-V column: " + ops.toolsProblem + ")\n";
  out += "\n";
  line("%-14s %-26s %-20s %-14s %-14s %-5s %s\n", "pipeline", "kernel", "function", "counted",
       "SPIR-V", "agree", "why they differ");
  for (const KernelRow& r : ops.kernels) {
    const std::string sp = r.optimised ? spirv::shortText(*r.optimised) : "-";
    const char* agree = !r.optimised ? "-" : r.why.empty() ? "yes" : "no";
    line("%-14s %-26s %-20s %-14s %-14s %-5s %s\n", r.kernel.pipeline.c_str(),
         r.kernel.kernel.c_str(), r.kernel.function.c_str(), text(r.counted).c_str(), sp.c_str(),
         agree, r.error.empty() ? r.why.c_str() : r.error.c_str());
    if (!r.kernel.note.empty()) line("%-14s   note: %s\n", "", r.kernel.note.c_str());
  }
  out += "\nWhole vertex-shader variants (main(), spirv-opt -O) vs the counted kernels they call\n"
         "(transform + world to clip); 'int' = integer index arithmetic, not in the columns:\n\n";
  line("%-9s %-10s %-30s %-34s %-14s %-14s %4s  %s\n", "pipeline", "shader", "defines", "variant",
       "counted", "SPIR-V", "int", "difference");
  for (const VariantRow& v : ops.variants) {
    line("%-9s %-10s %-30s %-34s %-14s %-14s %4s  %s\n", v.variant.pipeline.c_str(), v.variant.file.c_str(),
         describeDefines(v.variant).c_str(), v.variant.label.c_str(), text(v.counted).c_str(),
         v.shader ? spirv::shortText(*v.shader).c_str() : "-",
         v.shader ? std::to_string(v.shader->intOps).c_str() : "-",
         !v.error.empty() ? v.error.c_str() : v.why.empty() ? "none" : v.why.c_str());
    if (!v.variant.note.empty()) line("%-20s   note: %s\n", "", v.variant.note.c_str());
  }
  return out;
}

nlohmann::json toJson(const VertexOps& ops) {
  auto counted = [](const OpCounts& c) {
    return nlohmann::json{{"mul", c.mul}, {"add", c.add}, {"div", c.div}, {"sqrt", c.sqrt},
                          {"other", c.other}, {"other_calls", c.otherCalls()}};
  };
  auto sp = [](const std::optional<Counts>& c) -> nlohmann::json {
    if (!c) return nullptr;
    return {{"mul", c->mul}, {"add", c->add}, {"div", c->div}, {"sqrt", c->sqrt},
            {"other", c->other}, {"int", c->intOps}, {"instructions", c->histogram}};
  };
  nlohmann::json kernels = nlohmann::json::array(), variants = nlohmann::json::array();
  for (const KernelRow& r : ops.kernels)
    kernels.push_back({{"pipeline", r.kernel.pipeline}, {"kernel", r.kernel.kernel},
                       {"function", r.kernel.function}, {"counted", counted(r.counted)},
                       {"spirv", sp(r.optimised)}, {"spirv_inlined_only", sp(r.inlined)},
                       {"spirv_no_folding", sp(r.noFold)},
                       {"agree", r.optimised ? nlohmann::json(r.why.empty()) : nlohmann::json()},
                       {"why", r.why}, {"note", r.kernel.note}, {"error", r.error}});
  for (const VariantRow& v : ops.variants)
    variants.push_back({{"pipeline", v.variant.pipeline}, {"shader", v.variant.file},
                        {"defines", describeDefines(v.variant)}, {"variant", v.variant.label},
                        {"kernels", v.variant.kernels}, {"counted", counted(v.counted)},
                        {"spirv", sp(v.shader)}, {"spirv_kernel_probes", sp(v.probes)},
                        {"difference", v.why}, {"note", v.variant.note}, {"error", v.error}});
  return {{"method",
           {{"counted", "per-vertex GLSL function executed on mb::Counted (shaders/shim)"},
            {"spirv", "glslangValidator -G --aml, spirv-opt -O, spirv-dis; vector/matrix "
                      "instructions expanded to scalar mul/add (harness/ops/spirv_count.h)"}}},
          {"tools_problem", ops.toolsProblem},
          {"kernels", kernels},
          {"variants", variants}};
}

}  // namespace mb::opsv
