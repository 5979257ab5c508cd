// Memory: bytes per vertex by kind of content (built-in scenes and real files), floats per
// transform and per joint, each against the paper's baseline and, apart, the strongest form.
#include <string>

#include "harness/claims/claim_table.h"

namespace mb::claims {
namespace {

const char* kUploads = "buffers uploaded (PipelineStats)";

Evidence bytesOf(const std::string& label, const std::string& source, const std::string& kind, const std::string& over,
                 const std::string& motor = "motor") {
  return ratioOf(label, source + ":kind.uploaded_bytes_per_vertex." + kind + ".", motor, over);
}

ClaimRow row(std::string id, std::string statement, std::string origin, Scope scope, std::string paper,
             std::vector<Evidence> evidence, Rule rule, std::string note = "") {
  return {.id = std::move(id), .section = "Memory", .statement = std::move(statement), .origin = std::move(origin),
          .scope = std::move(scope), .paper = std::move(paper), .evidence = std::move(evidence), .rule = rule,
          .note = std::move(note)};
}

}  // namespace

std::vector<ClaimRow> memoryRows() {
  const std::string normalMapped = "normal-mapped primitives: the built-in scenes' and the real files' (results/corpus)";
  std::vector<ClaimRow> rows = {
      row("floats_per_vertex", "a normal-mapped vertex takes 9 floats instead of 12", "paper",
          {"vertex data", "the paper's 4x4 (the Sample Viewer's vertex)", normalMapped}, "12 vs 9 floats/vertex (-25 %)",
          {bytesOf("built-in, motor / matrix bytes", "report", "normal_mapped", "matrix"),
           bytesOf("real files, motor / matrix bytes", "corpus", "normal_mapped", "matrix")},
          {RuleKind::AtMost, 0.75}, "uploaded bytes per drawn vertex of that kind (" + std::string(kUploads) + ")"),
      row("vertices_per_storage", "33 % more normal-mapped vertices in the same storage", "paper",
          {"vertex data", "the paper's 4x4 (the Sample Viewer's vertex)", normalMapped}, "+33 %",
          {bytesOf("built-in, matrix / motor bytes", "report", "normal_mapped", "motor", "matrix"),
           bytesOf("real files, matrix / motor bytes", "corpus", "normal_mapped", "motor", "matrix")},
          {RuleKind::AtLeast, 4.0 / 3.0 - 1e-9},
          "holds for normal-mapped vertices only: vertex_bytes_real_content gives every kind of the real files"),
      row("floats_per_vertex_not_normal_mapped", "without a normal map the matrix vertex needs no tangent",
          "not claimed by the paper", {"vertex data", "the Sample Viewer's vertex", "primitives without a normal map"}, "-",
          {bytesOf("built-in, motor / matrix bytes", "report", "not_normal_mapped", "matrix"),
           bytesOf("real files, motor / matrix bytes", "corpus", "not_normal_mapped", "matrix")},
          {RuleKind::Baseline}),
      row("vertex_bytes_real_content", "bytes per vertex over every drawn vertex of the real files", "not claimed by the paper",
          {"vertex data", "the Sample Viewer's vertex", "real files (results/corpus), every kind weighted by drawn vertices"},
          "-",
          {bytesOf("all, motor / matrix bytes", "corpus", "all", "matrix"),
           {"normal-mapped share of the drawn vertices", "corpus:kind.share_vertices.normal_mapped", ""}},
          {RuleKind::Baseline}, "the paper's 12 vs 9 needs a normal map; most real vertices have none"),
      row("floats_per_transform", "a transform takes 8 floats instead of 32", "paper",
          {"vertex data", "the paper's 4x4 (matrix and normal matrix)", "built-in scenes"}, "32 vs 8 floats/transform (-75 %)",
          {{"motor / matrix floats", "report:floats_per_transform.motor", "report:floats_per_transform.matrix"}},
          {RuleKind::AtMost, 0.25}, "the motor alone; with its per-draw scale float see floats_per_transform_with_scale"),
      row("floats_per_transform_with_scale", "the motor's per-draw uniform scale float", "our design",
          {"vertex data", "the paper's 4x4", "built-in scenes"}, "32 vs 8, the scale a per-frame global",
          {{"motor / matrix floats", "report:floats_per_transform_with_scale.motor",
            "report:floats_per_transform_with_scale.matrix"}},
          {RuleKind::Baseline}, "the 9th float keeps animated uniform scale off the vertex buffers"),
      row("floats_per_joint", "a joint of the skin palette", "not claimed by the paper",
          {"vertex data", "the paper's 4x4", "built-in scenes and real files (exact fallback included)"}, "-",
          {{"built-in, motor / matrix floats", "report:floats_per_joint.motor", "report:floats_per_joint.matrix"},
           {"real files, motor / matrix floats", "corpus:floats_per_joint.motor", "corpus:floats_per_joint.matrix"},
           {"real files, draws with the skin fallback (32 floats per joint)", "corpus:fallback.draws.motor", ""}},
          {RuleKind::Baseline}, "a skin whose joints are not one uniform scale takes the exact fallback: 32 floats per joint"),
      row("bytes_per_vertex_vs_strongest", "normal-mapped vertex against the smallest matrix vertex", "vs strongest",
          {"vertex data", "the strongest matrix form: matrix_c (16 bytes)", "normal-mapped built-in primitives"},
          "motor 36 vs matrix 48 bytes (-25 %)",
          {bytesOf("motor / matrix_c", "report", "normal_mapped", "matrix_c"),
           bytesOf("motor_c / matrix_c", "report", "normal_mapped", "matrix_c", "motor_c")},
          {RuleKind::AtMost, 1.0}),
      row("floats_per_transform_vs_strongest", "transform against the affine mat4x3", "vs strongest",
          {"vertex data", "the strongest matrix form: affine (mat4x3)", "built-in scenes"}, "32 vs 8",
          {{"motor / affine floats", "report:floats_per_transform.motor", "report:floats_per_transform.affine"}},
          {RuleKind::AtMost, 1.0}),
      row("floats_per_joint_vs_strongest", "joint against the affine palette", "vs strongest",
          {"vertex data", "the strongest matrix form: affine (mat4x3)", "built-in scenes"}, "-",
          {{"motor / affine floats", "report:floats_per_joint.motor", "report:floats_per_joint.affine"}},
          {RuleKind::AtMost, 1.0}),
  };
  return rows;
}

}  // namespace mb::claims
