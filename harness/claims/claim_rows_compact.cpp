// Beyond the paper's vertex: the compact vertices (motor_c / matrix_c), the fragment-stage
// rotor (motor_cf), morph targets and curved space — each row a reading of the figures the
// report, morph and ops runs wrote.
#include <string>

#include "harness/claims/claim_table.h"
#include "harness/document/scope_ladder.h"

namespace mb::claims {
namespace {


ClaimRow row(std::string id, std::string section, std::string statement, std::string origin, Scope scope,
             std::string paper, std::vector<Evidence> evidence, Rule rule, std::string note = "") {
  return {.id = std::move(id), .section = std::move(section), .statement = std::move(statement),
          .origin = std::move(origin), .scope = std::move(scope), .paper = std::move(paper),
          .evidence = std::move(evidence), .rule = rule, .note = std::move(note)};
}

std::vector<ClaimRow> compact() {
  const char* s = "Compact vertices";
  const Scope vertex{"vertex data", "matrix_c, the smallest matrix vertex", "normal-mapped built-in primitives"};
  std::vector<Evidence> isa;
  for (const char* f : kIsaFamilies)
    isa.push_back(ratioOf(std::string("ISA instructions ") + f, std::string("report:isa.instructions.rigid.") + f + ".", "motor_c", "matrix_c"));
  return {
      row("compact_bytes_per_vertex", s, "the smallest motor vertex against the smallest matrix vertex", "compact", vertex,
          "- (not claimed by the paper)",
          {ratioOf("motor_c / matrix_c bytes", "report:kind.uploaded_bytes_per_vertex.normal_mapped.", "motor_c", "matrix_c")},
          {RuleKind::Baseline}),
      row("compact_image_cost", s, "the compact formats' own image cost", "compact",
          {"frame", "matrix (each format against the frames it should match)", "built-in scenes"},
          "- (not claimed by the paper)",
          {{"motor_c worst PSNR", "report:image.worst_psnr_own_format.motor_c", ""},
           {"matrix_c worst PSNR", "report:image.worst_psnr_own_format.matrix_c", ""}},
          {RuleKind::Baseline}),
      row("compact_ops", s, "decoding and transforming the compact vertex", "compact",
          {"transform to clip", "matrix_c", "built-in scenes"}, "- (not claimed by the paper)",
          {ratioOf("rigid to clip, counted", "report:ops_per_vertex.to_clip.counted.", "motor_c", "matrix_c"),
           {"frame decode, counted", "ops:vertex.compactRotor.total", "ops:vertex.compactMatrixFrame.total"}},
          {RuleKind::Baseline}),
      row("compact_isa", s, "the compact vertex shaders compiled", "compact",
          {"whole vertex shader", "matrix_c", "built-in scenes"}, "- (not claimed by the paper)", isa, {RuleKind::Baseline}),
      row("fragment_rotor", s, "interpolating the tangent rotor and shading with it costs fewer ops", "paper",
          {"fragment stage", "motor_c (the same 16-byte vertex, TBN in the fragment)", "normal-mapped built-in primitives"},
          "fewer ops per vertex, one varying less, no orthogonalisation per fragment (not counted)",
          {ratioOf("vertex to clip, counted", "report:ops_per_vertex.to_clip.counted.", "motor_cf", "motor_c"),
           {"normal-mapped shading normal, counted", "ops:vertex.rotorShadingNormal.total", "ops:vertex.tbnShadingNormal.total"}},
          {RuleKind::AtMost, 1.0},
          "without a normal map the fragment pays more (ops:vertex.rotorSurfaceNormal vs tbnSurfaceNormal), and the "
          "interpolated rotor is another frame inside a triangle: the normal map must be baked for it"),
  };
}

std::vector<ClaimRow> morph() {
  const char* s = "Morph targets";
  const Scope scope{"vertex data", "matrix", "the morph files of morph.json (built-in morph_torus and real files)"};
  return {
      row("morph_vertex_bytes", s, "the 9-float motor vertex survives morph targets", "morph", scope, "- (not claimed by the paper)",
          {ratioOf("motor / matrix bytes", "morph:morph.bytes_per_vertex.", "motor_frame", "matrix")}, {RuleKind::Baseline}),
      row("morph_target_bytes", s, "bytes per vertex of one morph target", "morph", scope, "- (not claimed by the paper)",
          {ratioOf("rotor / frame method", "morph:morph.bytes_per_target_vertex.", "motor_rotor", "motor_frame"),
           ratioOf("frame method / matrix", "morph:morph.bytes_per_target_vertex.", "motor_frame", "matrix")},
          {RuleKind::Baseline}),
      row("morph_frame_image", s, "method (a), the frame re-formed, draws rigid morph frames as matrix does", "morph",
          {"frame", "matrix", "rigid morph frames of morph.json"}, "- (not claimed by the paper)",
          {{"worst PSNR", "morph:morph.worst_psnr.rigid.motor_frame", ""}}, {RuleKind::AtLeast, 50},
          "frames at 128x128 (n in the figure), most from small test files; skinned morph frames are not exercised (no drawn node has a non-zero weight)"),
      row("morph_rotor_image", s, "method (b), rotor deltas, draws rigid morph frames as matrix does", "morph",
          {"frame", "matrix", "rigid morph frames of morph.json"}, "- (not claimed by the paper)",
          {{"worst PSNR", "morph:morph.worst_psnr.rigid.motor_rotor", ""}}, {RuleKind::AtLeast, 50},
          "a linear blend of rotors is not the rotor of the blended frame"),
  };
}

std::vector<ClaimRow> curved() {
  const char* s = "Curved space";
  return {
      row("curved_floats_per_instance", s, "a curved-space instance takes a motor (8 floats) instead of a 4x4 matrix", "curved",
          {"vertex data", "the 4x4 matrix of the same space", "s3_tiling and h3_tiling"}, "16 vs 8",
          {ratioOf("S3 motor / matrix", "report:curved.floats_per_instance.s3_tiling.", "s3_motor", "s3_matrix"),
           ratioOf("H3 motor / matrix", "report:curved.floats_per_instance.h3_tiling.", "h3_motor", "h3_matrix")},
          {RuleKind::AtMost, 0.5}),
      row("curved_ops_per_vertex", s, "the curved vertex, counted", "curved",
          {"transform to world", "the 4x4 matrix of the same space", "s3_tiling and h3_tiling"}, "-",
          {ratioOf("S3 motor / matrix", "report:ops_per_vertex.rigid.counted.", "s3_motor", "s3_matrix"),
           ratioOf("H3 motor / matrix", "report:ops_per_vertex.rigid.counted.", "h3_motor", "h3_matrix")},
          {RuleKind::Baseline}),
      row("curved_frame_time", s, "the curved scenes' frame time", "curved",
          {"frame", "the 4x4 matrix of the same space", "s3_tiling and h3_tiling, on the report's device"}, "-",
          {{"S3", "report:curved.frame_time.s3_tiling.motor_over_matrix", ""},
           {"H3", "report:curved.frame_time.h3_tiling.motor_over_matrix", ""},
           {"S3 vertex-bound", "report:curved.frame_time_vertex_bound.s3_tiling.motor_over_matrix", ""},
           {"H3 vertex-bound", "report:curved.frame_time_vertex_bound.h3_tiling.motor_over_matrix", ""}},
          {RuleKind::Baseline}, "a CPU rasterizer's frame time says nothing about a GPU"),
      row("curved_update", s, "the curved scenes' CPU update (sampling, hierarchy, instances)", "curved",
          {"CPU update", "the 4x4 matrix of the same space", "s3_tiling and h3_tiling"}, "-",
          {ratioOf("S3 motor / matrix", "report:update.s3_tiling.", "s3_motor", "s3_matrix"),
           ratioOf("H3 motor / matrix", "report:update.h3_tiling.", "h3_motor", "h3_matrix")},
          {RuleKind::Baseline}),
  };
}

}  // namespace

std::vector<ClaimRow> compactRows() {
  std::vector<ClaimRow> rows = compact();
  for (auto& part : {morph(), curved()}) rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

}  // namespace mb::claims
