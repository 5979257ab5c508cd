// Speed: "as fast as matrices" on each scope of the ladder (harness/document/scope_ladder.h:
// the same figures, the same rule), the skinned vertex, the CPU update and the scene graph,
// each against the paper's 4x4 and, in rows of their own, against the strongest matrix form.
#include <string>

#include "harness/claims/claim_table.h"
#include "harness/document/scope_ladder.h"

namespace mb::claims {
namespace {

using document::kAsCheapLimit;

// motor / `base` of the report figure `prefix` + pipeline.
Evidence vs(const std::string& label, const std::string& prefix, const std::string& base) {
  return ratioOf(label, "report:" + prefix, "motor", base);
}

// One evidence per ISA family of `measure` ("instructions", "inverse_throughput") of `variant`.
std::vector<Evidence> perFamily(const std::string& label, const std::string& measure, const std::string& variant,
                                const std::string& base, const std::string& motor = "motor") {
  std::vector<Evidence> out;
  for (const char* f : kIsaFamilies)
    out.push_back(ratioOf(label + " " + f, "report:isa." + measure + "." + variant + "." + f + ".", motor, base));
  return out;
}

std::vector<Evidence> joined(std::vector<std::vector<Evidence>> parts) {
  std::vector<Evidence> out;
  for (auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

const Rule kAsCheap{RuleKind::AtMost, kAsCheapLimit};
const char* kBuiltIn = "built-in scenes (the shaders and kernels, independent of content)";

ClaimRow asFastRow() {
  return {.id = "as_fast_as_matrices",
          .section = "Speed",
          .statement = "transforming a vertex with its tangent frame to world costs what the 4x4 matrix costs",
          .origin = "paper",
          .quote = "\"PGA motors can be just as fast as 4x4 matrices to transform your mesh vertices\" (Tangent frames)",
          .scope = {"transform to world", "the paper's 4x4", kBuiltIn},
          .paper = "as fast (47/38 vs 48/36 mul/add per vertex)",
          .evidence = {vs("counted ops", "ops_per_vertex.rigid.counted.", "matrix"),
                       vs("SPIR-V probe", "ops_per_vertex.rigid.spirv_probe.", "matrix"),
                       {"CPU kernel vertex_frame in cache (motor vs 4x4 shader source)",
                        "report:kernel_time.vertex_frame/in_cache.shim_motor_over_shim_matrix", ""},
                       {"CPU kernel vertex_frame out of cache (motor vs 4x4 shader source)",
                        "report:kernel_time.vertex_frame/out_of_cache.shim_motor_over_shim_matrix", ""}},
          .rule = kAsCheap,
          .note = "the paper's scope only: the same cells as the scope ladder's first row; to clip and the whole shader "
                  "are vertex_shader_no_cost's scopes"};
}

ClaimRow noCostRow() {
  return {.id = "vertex_shader_no_cost",
          .section = "Speed",
          .statement = "the whole vertex shader costs what the matrix one costs",
          .origin = "paper",
          .quote = "\"at virtually no cost on the vertex shader\" (Conclusion)",
          .scope = {"whole vertex shader", "the paper's 4x4", kBuiltIn},
          .paper = "virtually no cost",
          .evidence = joined({{vs("SPIR-V whole shader", "ops_per_vertex.rigid.spirv_whole_shader.", "matrix"),
                               vs("counted ops to clip", "ops_per_vertex.to_clip.counted.", "matrix")},
                              perFamily("ISA instructions", "instructions", "rigid", "matrix"),
                              perFamily("ACO inverse throughput", "inverse_throughput", "rigid", "matrix")}),
          .rule = kAsCheap,
          .note = "compiled on RADV's null device and counted, not timed; the matrix shader also normalises normal "
                  "and tangent in main(), the motor one leaves that to the fragment stage"};
}

ClaimRow skinnedRow() {
  return {.id = "as_fast_as_matrices_skinned",
          .section = "Speed",
          .statement = "the skinned vertex (4 joints) costs what the matrix one costs",
          .origin = "beyond the paper",
          .scope = {"transform to world", "the paper's 4x4", kBuiltIn},
          .paper = "(not claimed: the sentence is about the rigid vertex)",
          .evidence = joined({{vs("counted ops", "ops_per_vertex.skinned.counted.", "matrix"),
                               vs("SPIR-V probe", "ops_per_vertex.skinned.spirv_probe.", "matrix"),
                               {"CPU kernel skinned_vertex in cache (motor vs 4x4 shader source)",
                                "report:kernel_time.skinned_vertex/in_cache.shim_motor_over_shim_matrix", ""}},
                              perFamily("ISA instructions (whole shader)", "instructions", "skinned", "matrix")}),
          .rule = kAsCheap};
}

ClaimRow strongestRow(const std::string& id, const std::string& statement, const Scope& scope,
                      std::vector<Evidence> evidence) {
  return {.id = id, .section = "Against the strongest baseline", .statement = statement, .origin = "vs strongest",
          .scope = scope, .paper = "as fast as matrices", .evidence = std::move(evidence), .rule = kAsCheap};
}

std::vector<ClaimRow> strongestRows() {
  const Scope world{"transform to world", "the strongest matrix form: affine (mat4x3)", kBuiltIn};
  const Scope clip{"transform to clip", "the strongest matrix form: affine (mat4x3)", kBuiltIn};
  const Scope whole{"whole vertex shader", "the strongest matrix form: affine (mat4x3)", kBuiltIn};
  const Scope cpu{"CPU kernel", "the fastest matrix implementation measured, whatever its form", kBuiltIn};
  ClaimRow frame = strongestRow("cpu_vertex_frame_vs_strongest", "the vertex_frame kernel, fastest implementation of each side", cpu,
                   {{"in cache", "report:kernel_time.vertex_frame/in_cache.fastest_motor_over_fastest_matrix", ""},
                    {"out of cache", "report:kernel_time.vertex_frame/out_of_cache.fastest_motor_over_fastest_matrix", ""}});
  frame.note = "the fastest matrix side here is the affine form (simd_matrix runs matrixAffineVertex); out of cache a "
               "kernel's time follows the bytes it streams per vertex more than its ops";
  return {
      frame,
      strongestRow("ops_rigid_vs_strongest", "rigid vertex to world, counted", world,
                   {vs("counted ops", "ops_per_vertex.rigid.counted.", "affine"),
                    vs("SPIR-V probe", "ops_per_vertex.rigid.spirv_probe.", "affine")}),
      strongestRow("ops_clip_vs_strongest", "rigid vertex to clip, counted", clip,
                   {vs("counted ops", "ops_per_vertex.to_clip.counted.", "affine"),
                    vs("SPIR-V probe", "ops_per_vertex.to_clip.spirv_probe.", "affine")}),
      strongestRow("ops_skinned_vs_strongest", "skinned vertex, counted", world,
                   {vs("counted ops", "ops_per_vertex.skinned.counted.", "affine"),
                    vs("SPIR-V probe", "ops_per_vertex.skinned.spirv_probe.", "affine")}),
      strongestRow("ops_clip_vs_strongest_isa", "whole rigid vertex shader, compiled", whole,
                   joined({perFamily("ISA instructions", "instructions", "rigid", "affine"),
                           perFamily("ACO inverse throughput", "inverse_throughput", "rigid", "affine")})),
      strongestRow("ops_skinned_vs_strongest_isa", "whole skinned vertex shader, compiled", whole,
                   perFamily("ISA instructions", "instructions", "skinned", "affine")),
      strongestRow("cpu_skinned_vertex_vs_strongest", "the skinned_vertex kernel, fastest implementation of each side", cpu,
                   {{"in cache", "report:kernel_time.skinned_vertex/in_cache.fastest_motor_over_fastest_matrix", ""},
                    {"out of cache", "report:kernel_time.skinned_vertex/out_of_cache.fastest_motor_over_fastest_matrix", ""}}),
  };
}

// Timed rows on the CPU rasterizer and the CPU update. The frame-time figures are medians over
// scenes; fewer than 5 scenes carry no verdict.
std::vector<ClaimRow> timedRows() {
  const Scope frame{"frame", "the paper's 4x4 (the Sample Viewer's pipeline)", "built-in scenes, on the report's device"};
  const Scope update{"CPU update", "the strongest matrix form: affine and qtangent", "crowd, the built-in scene with real update work"};
  ClaimRow ft = strongestRow("frame_time_vs_strongest", "frame time, every Euclidean built-in scene", frame,
                             {{"motor / matrix", "report:frame_time.motor_over_matrix", ""},
                              {"motor / affine (the ratio of the two medians over scenes, not paired)",
                               "report:frame_time.motor_over_matrix", "report:frame_time.affine_over_matrix"},
                              {"motor / qtangent (the ratio of the two medians over scenes, not paired)",
                               "report:frame_time.motor_over_matrix", "report:frame_time.qtangent_over_matrix"}});
  ft.rule.minN = 5;
  ft.rule.gpuTimed = true;
  ft.note = "judged only when a GPU timed it; on a CPU rasterizer the ratios are printed, not judged";
  ClaimRow vb = strongestRow("frame_time_vertex_bound_vs_strongest", "frame time, vertex-bound viewport", frame,
                             {{"motor / matrix", "report:frame_time_vertex_bound.motor_over_matrix", ""}});
  vb.rule.minN = 5;
  vb.rule.gpuTimed = true;
  vb.note = ft.note;
  ClaimRow cpu = strongestRow("cpu_update_vs_strongest", "Pipeline::update on crowd, the one built-in scene with real update work", update,
                              {vs("motor / affine", "update.crowd.", "affine"),
                               vs("motor / qtangent", "update.crowd.", "qtangent"),
                               vs("motor / matrix", "update.crowd.", "matrix")});
  cpu.note = "the other built-in scenes update in under a microsecond (one to few nodes): timer-floor readings, not evidence";
  return {ft, vb, cpu};
}

ClaimRow sceneGraphRow() {
  return {.id = "scene_graph_update",
          .section = "Composition (table 1)",
          .statement = "a scene graph updates faster with motors",
          .origin = "paper",
          .quote = "\"a substantial optimization\" ... \"the gain of switching to motors is obvious\" (Composition)",
          .scope = {"CPU update", "the paper's 4x4 (the shader sources' mat4 product)",
                    "the bench's hierarchies (deep, skeleton, wide) and crowd"},
          .paper = "a substantial gain (no figure)",
          .evidence = {{"hierarchy kernel, deep", "report:kernel_time.hierarchy.shim_motor_over_shim_matrix", ""},
                       {"hierarchy kernel, humanoid skeleton", "report:kernel_time.hierarchy_skeleton.shim_motor_over_shim_matrix", ""},
                       {"hierarchy kernel, wide", "report:kernel_time.hierarchy_wide.shim_motor_over_shim_matrix", ""},
                       vs("hierarchy phase on crowd", "update.hierarchy.crowd.", "matrix")},
          .rule = {RuleKind::AtMost, document::kCheaperLimit},
          .note = "a gain beyond the 10 % timing tolerance (motor / matrix <= 0.9); scenes of one to few nodes are "
                  "left out: their hierarchy phase reads the timer floor"};
}

ClaimRow sceneGraphStrongestRow() {
  return strongestRow("scene_graph_update_vs_strongest", "scene-graph update, fastest implementation of each side",
                      {"CPU kernel", "the fastest matrix implementation measured (GLM, SIMD)", "the bench's hierarchies"},
                      {{"deep", "report:kernel_time.hierarchy.fastest_motor_over_fastest_matrix", ""},
                       {"humanoid skeleton", "report:kernel_time.hierarchy_skeleton.fastest_motor_over_fastest_matrix", ""},
                       {"wide", "report:kernel_time.hierarchy_wide.fastest_motor_over_fastest_matrix", ""}});
}

ClaimRow rankingRow(const std::string& kind) {
  return {.id = "ops_ranking_" + kind,
          .section = "Speed",
          .statement = "counted ops, SPIR-V and ISA order the pipelines the same way (" + kind + " vertex to clip)",
          .origin = "ops evidence",
          .scope = {"transform to clip", "every pipeline pair", kBuiltIn},
          .paper = "(not claimed)",
          .evidence = {{"pipeline pairs ordered both ways", "report:ops_ranking." + kind + ".pairs_reversed", ""}},
          .rule = {RuleKind::Baseline},
          .note = "the pairs are listed in report.md's ops ranking"};
}

}  // namespace

std::vector<ClaimRow> speedRows() {
  std::vector<ClaimRow> rows = {asFastRow(), noCostRow(), skinnedRow(), rankingRow("rigid"), rankingRow("skinned"),
                                sceneGraphRow(), sceneGraphStrongestRow()};
  for (auto& part : {strongestRows(), timedRows()}) rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

}  // namespace mb::claims
