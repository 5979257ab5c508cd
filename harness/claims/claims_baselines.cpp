// The baselines a reviewer would ask for beside the paper's 48/36 (three full mat4 * vec4, the
// glTF Sample Viewer's path): an affine matrix path (3x4 model, 3x3 normal matrix), the full
// object-to-clip cost of each pipeline's real vertex shader, and the cost of a skinned vertex.
// Counted through the shim and, when glslang/spirv-tools run, in the optimised SPIR-V.
#include <cstdio>

#include "harness/claims/claims_sources.h"
#include "harness/ops/ops_vertex.h"

namespace mb::claims {
namespace {

std::string spirvText(const std::optional<spirv::Counts>& c) {
  if (!c) return "SPIR-V not counted";
  return "SPIR-V " + std::to_string(c->mul) + " mul, " + std::to_string(c->add) + " add" +
         (c->div ? " + " + std::to_string(c->div) + " div" : "") +
         (c->sqrt ? " + " + std::to_string(c->sqrt) + " sqrt" : "") +
         (c->other ? " + " + std::to_string(c->other) + " other" : "");
}

nlohmann::json spirvJson(const std::optional<spirv::Counts>& c) {
  if (!c) return nullptr;
  return {{"mul", c->mul}, {"add", c->add}, {"div", c->div}, {"sqrt", c->sqrt}, {"other", c->other}};
}

std::string ratioText(const OpCounts& a, const OpCounts& b, const std::string& an, const std::string& bn) {
  char buf[160];
  const double ra = double(a.mul + a.add), rb = double(b.mul + b.add);
  std::snprintf(buf, sizeof buf, "%s / %s mul+add = %.2f", an.c_str(), bn.c_str(), rb > 0 ? ra / rb : 0.0);
  return buf;
}

}  // namespace

std::vector<Claim> baselineClaims() {
  const opsv::VertexOps ops = opsv::measureVertexOps();
  auto kernel = [&](const std::string& fn) -> const opsv::KernelRow* {
    for (const auto& k : ops.kernels)
      if (k.kernel.function == fn) return &k;
    return nullptr;
  };
  auto variant = [&](const std::string& pipeline, const std::string& label) -> const opsv::VariantRow* {
    for (const auto& v : ops.variants)
      if (v.variant.pipeline == pipeline && v.variant.label == label) return &v;
    return nullptr;
  };
  const std::string section = "Baselines (not claimed by the paper)";
  const std::string tools = ops.toolsProblem.empty() ? "" : " (SPIR-V not counted: " + ops.toolsProblem + ")";
  std::vector<Claim> out;
  auto row = [&](const std::string& id, const std::string& statement, const OpCounts& counted,
                 const std::optional<spirv::Counts>& sp, const std::string& method, const std::string& comparison) {
    Claim c{id, section, statement};
    c.paper = "-";
    c.measured = "counted " + opsText(counted) + "; " + spirvText(sp);
    c.measuredValue = {{"counted", opsJson(counted)}, {"spirv", spirvJson(sp)}};
    c.method = method + tools;
    c.verdict = Verdict::Baseline;
    c.verdictText = "baseline: " + comparison;
    out.push_back(c);
  };
  const opsv::KernelRow *affine = kernel("matrixAffineVertex"), *matrix = kernel("matrixRigidVertex"),
                        *motor = kernel("motorRigidVertex");
  if (affine && matrix && motor)
    row("affine_matrix_vertex", "affine matrix vertex with frame: 3x4 model matrix, 3x3 normal matrix",
        affine->counted, affine->optimised,
        "matrixAffineVertex (shaders/matrix_transform.glsl) counted through the shim; SPIR-V of a probe shader "
        "calling it (spirv-opt -O)",
        ratioText(motor->counted, affine->counted, "motor rigid", "affine") + "; " +
            ratioText(matrix->counted, affine->counted, "Sample-Viewer mat4", "affine"));
  struct Full { const char* pipeline; const char* label; const char* id; const char* what; };
  const Full fulls[] = {
      {"matrix", "rigid", "world_to_clip_matrix", "matrix pipeline, object to clip: rigid vertex with frame + view-projection"},
      {"motor", "rigid", "world_to_clip_motor", "motor pipeline, object to clip: rigid vertex with frame + camera motor + project()"},
      {"matrix", "rigid, no tangent", "world_to_clip_matrix_no_tangent",
       "matrix pipeline, object to clip without a tangent (no TANGENT, no normal map: the Sample Viewer's "
       "shader has no tangent input); the motor vertex has no such variant (its rotor carries the normal)"},
      // Symmetric skinning: each pipeline in the same configuration.
      {"matrix", "skinned, reference", "skinned_vertex_matrix",
       "matrix pipeline, skinned vertex (4 joints, LBS of joint and joint-normal matrices) to clip, as the Sample "
       "Viewer does it: palette relative to the mesh node, then u_ModelMatrix per vertex"},
      {"motor", "skinned, reference", "skinned_vertex_motor",
       "motor pipeline, skinned vertex (4 joints, motor blend + normalize) to clip, as the paper's listing does "
       "it: palette relative to the mesh node, then gp(toWorld, blend) per vertex"},
      {"matrix", "skinned, world palette", "skinned_vertex_matrix_world_palette",
       "matrix pipeline, skinned vertex to clip with a world-space palette (no model matrix per vertex; "
       "neither reference does this)"},
      {"motor", "skinned, world palette", "skinned_vertex_motor_world_palette",
       "motor pipeline, skinned vertex to clip with a world-space palette (no node motor per vertex; the motor "
       "pipeline's default)"},
  };
  for (const Full& f : fulls) {
    const opsv::VariantRow* v = variant(f.pipeline, f.label);
    if (!v) continue;
    // The counterpart in the same configuration; the matrix no-tangent vertex against the
    // motor's only rigid vertex.
    const std::string otherLabel = std::string(f.label) == "rigid, no tangent" ? "rigid" : f.label;
    const opsv::VariantRow* other = variant(std::string(f.pipeline) == "matrix" ? "motor" : "matrix", otherLabel);
    std::string kernels;
    for (const std::string& k : v->variant.kernels) kernels += (kernels.empty() ? "" : " + ") + k;
    row(f.id, f.what, v->counted, v->shader,
        "sum of the counted functions the vertex shader calls (" + kernels + "); SPIR-V: the whole " +
            v->variant.file + " variant '" + v->variant.label + "' compiled and optimised",
        other ? ratioText(v->counted, other->counted, f.pipeline, std::string(f.pipeline) == "matrix" ? "motor" : "matrix")
              : "no counterpart");
  }
  return out;
}

}  // namespace mb::claims
