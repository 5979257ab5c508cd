#include "harness/ops/ops_vertex.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "harness/ops/ops_text.h"
#include "pipelines/gl/shader_source.h"

namespace mb::opsv {
namespace {

namespace fs = std::filesystem;
using spirv::Counts;

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


}  // namespace

const KernelRow* findKernel(const std::vector<KernelRow>& kernels, const std::string& pipeline,
                            const std::string& function) {
  const KernelRow* only = nullptr;
  int matches = 0;
  for (const KernelRow& k : kernels) {
    if (k.kernel.function != function) continue;
    if (k.kernel.pipeline == pipeline) return &k;
    only = &k, ++matches;
  }
  return matches == 1 ? only : nullptr;
}

VertexOps measureVertexOps(SpirvDepth depth, const OpsStep& step) {
  VertexOps ops;
  // glslang and SPIRV-Tools are linked in (spirv_compile.h): only a run that asks for no SPIR-V
  // has none.
  ops.toolsProblem = depth == SpirvDepth::None ? "SPIR-V not counted in this run" : "";
  const bool full = depth == SpirvDepth::Full;
  const std::vector<VertexKernel> kernels = vertexKernels();
  const std::vector<ShaderVariant> variants = shaderVariants();
  size_t done = 0;
  auto stepDone = [&](const std::string& what) {
    if (step) step(++done, kernels.size() + variants.size(), what);
  };
  for (const VertexKernel& k : kernels) {
    KernelRow r{k, countVertexKernel(k), std::nullopt, std::nullopt, std::nullopt, "", ""};
    if (ops.toolsProblem.empty()) {
      auto optimised = countProbe(k, spirv::Optimise::Full);
      if (optimised) r.optimised = *optimised;
      else r.error = optimised.error();
      if (full) {
        if (auto inl = countProbe(k, spirv::Optimise::InlineOnly)) r.inlined = *inl;
        if (auto noFold = countProbe(k, spirv::Optimise::NoFold)) r.noFold = *noFold;
        r.why = kernelWhy(r);
      }
    }
    ops.kernels.push_back(std::move(r));
    stepDone(k.pipeline + " " + k.kernel);
  }
  for (const ShaderVariant& v : variants) {
    VariantRow row{v, {}, Counts{}, std::nullopt, "", ""};
    for (const std::string& fn : v.kernels) {
      const KernelRow* k = findKernel(ops.kernels, v.pipeline, fn);
      if (!k) {
        row.error = "no single counted kernel " + fn + " for " + v.pipeline;
        row.kernelsResolved = false;
        row.counted = {};
        row.probes.reset();
        break;
      }
      row.counted += k->counted;
      if (row.probes && k->optimised) *row.probes += *k->optimised;
      else row.probes.reset();
    }
    if (full && ops.toolsProblem.empty() && row.kernelsResolved) {
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
    if (row.shader && row.error.empty()) row.why = variantWhy(row);
    ops.variants.push_back(std::move(row));
    stepDone(v.pipeline + " " + v.label + " vertex shader");
  }
  return ops;
}

}  // namespace mb::opsv
