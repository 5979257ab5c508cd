#include "harness/ops/ops_figures.h"

#include <cctype>
#include <cmath>
#include <map>
#include <optional>

#include "harness/figures/figure.h"
#include "harness/ops/op_kernels_listings.h"
#include "harness/ops/op_kernels_pieces.h"

namespace mb::ops {
namespace {

using nlohmann::json;

// What a family of figures is: how it was obtained and where.
struct Kind {
  const char* statistic;
  const char* device;
};
const Kind kCounted{"counted once on the op-counting scalar", "op-counting scalar (mb::Counted through the GLSL shim)"};
const Kind kSpirv{"compiled: glslang, spirv-opt -O; vector and matrix instructions expanded to scalar ops",
                  "SPIR-V (glslang and SPIRV-Tools in process, harness/ops/spirv_count.h)"};

// One count's five columns (and the names of its other built-in calls, where known).
struct Columns {
  double mul = 0, add = 0, div = 0, sqrt = 0, other = 0;
  std::string otherCalls;
};
Columns columnsOf(const OpCounts& c) {
  return {double(c.mul), double(c.add), double(c.div), double(c.sqrt), double(c.other), c.otherCalls()};
}
Columns columnsOf(const spirv::Counts& c) {
  return {double(c.mul), double(c.add), double(c.div), double(c.sqrt), double(c.other), ""};
}

// The figure of one column of `prefix`: NaN with `why` when there is no count.
figures::Figure column(const std::string& prefix, const char* col, double value, const std::string& what,
                       const std::string& scope, const Kind& kind, const std::string& otherCalls) {
  static const std::map<std::string, std::string> words = {
      {"mul", "multiplications"},
      {"add", "additions (a subtraction counts as an addition, negation is free)"},
      {"div", "divisions"},
      {"sqrt", "square roots"},
      {"other", "other built-in calls"},
      {"total", "all ops: mul + add + div + sqrt + other"}};
  figures::Figure f;
  f.name = prefix + "." + col;
  f.value = value;
  f.unit = "ops";
  f.statistic = kind.statistic;
  f.kind = &kind == &kSpirv ? "compiled" : "counted";
  f.device = kind.device;
  f.scope = scope;
  f.n = std::isfinite(value) ? 1 : 0;
  f.definition = what + ": " + words.at(col) +
                 (std::string(col) == "other" && !otherCalls.empty() ? " (" + otherCalls + ")" : "");
  return f;
}

// mul, add, div, sqrt, other and total of `prefix`; without a count every one is NaN and says why.
void putColumns(json& out, const std::string& prefix, const std::optional<Columns>& c, const std::string& what,
                const std::string& scope, const Kind& kind, const std::string& why) {
  const double nan = std::nan("");
  const std::pair<const char*, double> cols[] = {
      {"mul", c ? c->mul : nan},     {"add", c ? c->add : nan},     {"div", c ? c->div : nan},
      {"sqrt", c ? c->sqrt : nan},   {"other", c ? c->other : nan},
      {"total", c ? c->mul + c->add + c->div + c->sqrt + c->other : nan}};
  for (const auto& [col, value] : cols) {
    figures::Figure f = column(prefix, col, value, what, scope, kind, c ? c->otherCalls : "");
    if (!c) f.why = why.empty() ? "not counted" : why;
    figures::put(out, f);
  }
}

template <class C> std::optional<Columns> maybe(const std::optional<C>& c) {
  return c ? std::optional<Columns>(columnsOf(*c)) : std::nullopt;
}

std::string sourceOf(const std::string& group) {
  if (group == "pga") return "shaders/pga.glsl";
  if (group == "pga-kappa") return "shaders/pga_kappa.glsl";
  if (group == "listing") return "shaders/paper_listings.glsl";
  if (group == "matrix") return "the GLSL matrix operators of the shim";
  if (group == "conversion") return "pipelines/motor/companion.h, written on the shim's types";
  if (group == "affine") return "harness/bench/affine_compose.h on the shim's types";
  if (group == "motor") return "shaders/pga.glsl and shaders/motor_transform.glsl";
  return group;
}

void putKernels(json& out, const std::string& family, const std::vector<Row>& rows) {
  for (const Row& r : rows)
    putColumns(out, family + "." + r.kernel.name, columnsOf(r.counts), r.kernel.what,
               "one call of " + r.kernel.name + " (" + sourceOf(r.kernel.group) + "), generic inputs", kCounted, "");
}

// The per-draw uniform scale per vertex: motorRigidVertex minus the same pieces without it.
void putScaleOverhead(json& out, const opsv::VertexOps& perVertex, const std::vector<Row>& pieces) {
  const opsv::KernelRow* withScale = opsv::findKernel(perVertex.kernels, "motor", "motorRigidVertex");
  const Row* without = nullptr;
  for (const Row& r : pieces)
    if (r.kernel.name == "motor_vertex_frame") without = &r;
  std::optional<Columns> c;
  if (withScale && without) c = columnsOf(withScale->counted - without->counts);
  putColumns(out, "kernel.uniform_scale_overhead", c,
             "the draw's uniform scale per vertex: motorRigidVertex (vertex.motorRigidVertex) minus the same vertex "
             "without the scale (kernel.motor_vertex_frame)",
             "per rigid vertex of the motor pipeline", kCounted, "motorRigidVertex or motor_vertex_frame not counted");
}

void putVertexKernels(json& out, const opsv::VertexOps& perVertex) {
  std::map<std::string, int> uses;
  for (const opsv::KernelRow& k : perVertex.kernels) ++uses[k.kernel.function];
  for (const opsv::KernelRow& k : perVertex.kernels) {
    const std::string fn = k.kernel.function;
    const std::string prefix = "vertex." + fn + (uses[fn] > 1 ? "." + figureLabel(k.kernel.pipeline) : "");
    const std::string what = fn + ", " + k.kernel.kernel + " (" + k.kernel.pipeline + ")";
    putColumns(out, prefix, columnsOf(k.counted), what, "one call of the per-vertex function " + fn, kCounted, "");
    putColumns(out, prefix + ".spirv", maybe(k.optimised), what,
               "a probe vertex shader calling " + fn + " once", kSpirv,
               !k.error.empty() ? k.error : perVertex.toolsProblem);
  }
}

void putVariants(json& out, const opsv::VertexOps& perVertex) {
  for (const opsv::VariantRow& v : perVertex.variants) {
    const std::string prefix = "variant." + figureLabel(v.variant.pipeline) + "." + figureLabel(v.variant.label);
    std::string kernels;
    for (const std::string& k : v.variant.kernels) kernels += (kernels.empty() ? "" : " + ") + k;
    const std::string what = v.variant.pipeline + " vertex shader variant '" + v.variant.label + "' (" + v.variant.file + ")";
    const std::string why = !v.error.empty() ? v.error : perVertex.toolsProblem;
    putColumns(out, prefix + ".counted", v.kernelsResolved ? std::optional<Columns>(columnsOf(v.counted)) : std::nullopt,
               what + ", the sum of the counted functions it calls", "the functions main() calls: " + kernels, kCounted,
               why);
    putColumns(out, prefix + ".spirv", maybe(v.shader), what + ", the whole shader (main() included)",
               "whole vertex shader " + v.variant.file, kSpirv, why);
  }
}

}  // namespace

std::string figureLabel(const std::string& label) {
  std::string out;
  for (char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

json opsFigures(const std::vector<Row>& kernels, const opsv::VertexOps& perVertex) {
  json out = json::object();
  putKernels(out, "kernel", kernels);
  const std::vector<Row> pieces = measureAll(pieceKernels());
  putKernels(out, "kernel", pieces);
  putScaleOverhead(out, perVertex, pieces);
  putKernels(out, "listing", measureAll(listingKernels()));
  putVertexKernels(out, perVertex);
  putVariants(out, perVertex);
  return out;
}

std::string formatListings(const std::vector<Row>& kernels) {
  const std::vector<Row> listings = measureAll(listingKernels());
  std::string out =
      "The paper's printed listings (shaders/paper_listings.glsl), counted the same way: where our kernel\n"
      "disagrees with the paper's figure, the listing says whether the paper's own code reaches it.\n\n";
  out += formatTable(listings);
  for (const Row& l : listings)
    for (const Row& ours : kernels) {
      if (ours.kernel.name != l.kernel.name || ours.agree() != "NO") continue;
      out += "\n" + l.kernel.name + ": ours " + std::to_string(ours.counts.mul) + "/" + std::to_string(ours.counts.add) +
             ", the paper " + l.claimText() + ", its printed listing " + std::to_string(l.counts.mul) + "/" +
             std::to_string(l.counts.add) + (l.agree() == "yes" ? " (= the paper)" : " (not the paper's figure either)");
      if (const std::string why = oursAgainstListing(l.kernel.name); !why.empty()) out += ": " + why;
    }
  return out + "\n";
}

}  // namespace mb::ops
