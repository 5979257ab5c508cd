#include "harness/ops/ops_vertex.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "pipelines/gl/shader_source.h"

namespace mb::opsv {
namespace {

namespace fs = std::filesystem;
using spirv::Counts;

std::string text(const OpCounts& c) {
  return std::to_string(c.mul) + "/" + std::to_string(c.add) + "/" + std::to_string(c.div) +
         "/" + std::to_string(c.sqrt) + "/" + std::to_string(c.other);
}

bool same(const OpCounts& a, const Counts& b) {
  return a.mul == b.mul && a.add == b.add && a.div == b.div && a.sqrt == b.sqrt &&
         a.other == b.other;
}

OpCounts& operator+=(OpCounts& a, const OpCounts& b) {
  a.mul += b.mul, a.add += b.add, a.div += b.div, a.sqrt += b.sqrt, a.other += b.other;
  for (size_t i = 0; i < a.fn.size(); ++i) a.fn[i] += b.fn[i];
  return a;
}

// Signed per-column difference b - a, e.g. "+12 mul, +4 add, +3 div, +2 other".
template <class A, class B> std::string delta(const A& a, const B& b) {
  std::string out;
  auto one = [&](long long d, const char* what) {
    if (!d) return;
    if (!out.empty()) out += ", ";
    out += (d > 0 ? "+" : "") + std::to_string(d) + " " + what;
  };
  one((long long)b.mul - (long long)a.mul, "mul");
  one((long long)b.add - (long long)a.add, "add");
  one((long long)b.div - (long long)a.div, "div");
  one((long long)b.sqrt - (long long)a.sqrt, "sqrt");
  one((long long)b.other - (long long)a.other, "other");
  return out;
}

// Compiles a probe: the kernel's module(s) included from the shader folder, the kernel called
// once from main() with attributes and uniforms as arguments, every result written out (so
// nothing is dead code).
Result<Counts> countProbe(const VertexKernel& k, spirv::Optimise opt) {
  using R = Result<Counts>;
  std::string tmpl = (fs::temp_directory_path() / "motorbench-probe-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) return R::fail(k.function + ": cannot create a temporary folder");
  const fs::path dir = tmpl, file = dir / "probe.vert";
  {
    std::ofstream out(file);
    out << "#version 450 core\n" << k.probeDecls << "void main() {\n  " << k.probe << "\n}\n";
  }
  auto expanded = gl::expandShaderFile(file.string());
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (!expanded) return R::fail(expanded.error());
  return spirv::countSource(expanded->text, "vert", opt, "probe of " + k.function);
}

// Where the counted and the optimised SPIR-V counts part, step by step, each step measured:
// front end (counted vs inlined SPIR-V), spirv-opt's common subexpressions and dead code (vs
// -O without instruction folding), and instruction folding (vs -O).
std::string kernelWhy(const KernelRow& r) {
  if (!r.optimised || same(r.counted, *r.optimised)) return "";
  std::string why;
  auto add = [&](const std::string& s) { why += (why.empty() ? "" : "; ") + s; };
  if (r.inlined && !same(r.counted, *r.inlined))
    add("front end " + delta(r.counted, *r.inlined) + " (" +
        spirv::histogramDiff(Counts{}, *r.inlined) + ")");
  if (r.inlined && r.noFold && !r.inlined->sameArithmetic(*r.noFold))
    add("shared subexpressions/dead code " + delta(*r.inlined, *r.noFold));
  if (r.noFold && !r.noFold->sameArithmetic(*r.optimised)) {
    auto fmaOf = [](const Counts& c) {
      auto f = c.histogram.find("Fma");
      return f == c.histogram.end() ? 0ll : (long long)f->second;
    };
    const long long fma = fmaOf(*r.optimised) - fmaOf(*r.noFold);
    std::string s = "instruction folding " + delta(*r.noFold, *r.optimised);
    if (fma > 0) {
      s += ": " + std::to_string(fma) + " a*b+c fused into Fma (1 mul + 1 add each)";
      if (r.optimised->mul > r.noFold->mul) s += ", products shared by two sums re-multiplied in each Fma";
      if (r.optimised->add < r.noFold->add) s += ", equal sums merged";
    }
    add(s);
  }
  if (!r.noFold && r.inlined && !r.inlined->sameArithmetic(*r.optimised))
    add("spirv-opt -O " + delta(*r.inlined, *r.optimised) + ": " +
        spirv::histogramDiff(*r.inlined, *r.optimised));
  return why;
}

// Where a whole variant's SPIR-V parts from the counted kernels it calls: inside the kernels
// (the kernel rows say why) and in main() outside them (varyings, divides, normalisation).
std::string variantWhy(const VariantRow& v) {
  if (same(v.counted, *v.shader) && (!v.probes || v.probes->intOps == v.shader->intOps)) return "";
  std::string why;
  auto add = [&](const std::string& s) { why += (why.empty() ? "" : "; ") + s; };
  if (!v.probes) return "no SPIR-V count of the kernels";
  if (!same(v.counted, *v.probes))
    add("in the kernels " + delta(v.counted, *v.probes) + " (see the kernel rows)");
  const std::string outside = spirv::histogramDiff(*v.probes, *v.shader);
  if (!outside.empty()) {
    const std::string d = delta(*v.probes, *v.shader);
    add("in main() outside the transform functions: " + outside +
        (d.empty() ? "" : " (" + d + ")"));
  }
  if (v.shader->intOps > v.probes->intOps)
    add(v.variant.file.find("patch") != std::string::npos ? "integer ops: control-point texel indexing"
                                                           : "integer ops: joint palette indexing");
  return why;
}

std::string describeDefines(const ShaderVariant& v) {
  std::string s;
  for (const auto& [name, value] : v.defines) s += (s.empty() ? "" : " ") + name + (value.empty() ? "" : "=" + value);
  return s.empty() ? "-" : s;
}

}  // namespace

VertexOps measureVertexOps(const OpsStep& step) {
  VertexOps ops;
  const spirv::Tools tools = spirv::findTools();
  ops.toolsProblem = spirv::toolsProblem(tools);
  const std::vector<VertexKernel> kernels = vertexKernels();
  const std::vector<ShaderVariant> variants = shaderVariants();
  size_t done = 0;
  auto stepDone = [&](const std::string& what) {
    if (step) step(++done, kernels.size() + variants.size(), what);
  };
  for (const VertexKernel& k : kernels) {
    KernelRow r{k, countVertexKernel(k), std::nullopt, std::nullopt, std::nullopt, "", ""};
    if (ops.toolsProblem.empty()) {
      auto full = countProbe(k, spirv::Optimise::Full);
      auto inl = countProbe(k, spirv::Optimise::InlineOnly);
      auto noFold = countProbe(k, spirv::Optimise::NoFold);
      if (full) r.optimised = *full;
      else r.error = full.error();
      if (inl) r.inlined = *inl;
      if (noFold) r.noFold = *noFold;
      r.why = kernelWhy(r);
    }
    ops.kernels.push_back(std::move(r));
    stepDone(k.pipeline + " " + k.kernel);
  }
  for (const ShaderVariant& v : variants) {
    VariantRow row{v, {}, Counts{}, std::nullopt, "", ""};
    for (const std::string& fn : v.kernels)
      for (const KernelRow& k : ops.kernels)
        if (k.kernel.function == fn && k.kernel.pipeline == v.pipeline) {  // once each
          row.counted += k.counted;
          if (row.probes && k.optimised) *row.probes += *k.optimised;
          else row.probes.reset();
          break;
        }
    if (ops.toolsProblem.empty()) {
      auto expanded = gl::expandShaderFile(v.file, v.defines);
      if (!expanded) {
        row.error = expanded.error();
      } else {
        auto c = spirv::countSource(expanded->text, "vert", spirv::Optimise::Full,
                                    v.file + " (" + describeDefines(v) + ")");
        if (c) row.shader = *c;
        else row.error = c.error();
      }
    }
    if (row.shader) row.why = variantWhy(row);
    ops.variants.push_back(std::move(row));
    stepDone(v.pipeline + " " + v.label + " vertex shader");
  }
  return ops;
}

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
