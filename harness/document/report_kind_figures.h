// The answer per kind of content: figures of report.json's scenes split by the kinds the scene
// measurement records (scenes[].contentKinds, pipelines[p].vertexFetch.byKind): normal-mapped or
// not, skinned, morph, rigid (the rest), the content as a whole and the built-in scenes as
// controlled cases. "The content" is the report's file scenes (origin "file") where it has
// any, else all its scenes; the built-in scenes are a kind of their own only beside files.
// Every figure is weighted by drawn vertices; ops and ISA by the shader variant each drawn
// primitive draws with, the exact fallback included.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::document {

struct ContentKindDef {
  std::string id;     // figure key: "all", "normal_mapped", ...
  std::string label;  // as printed: "all content", "normal-mapped", ...
};

// all, normal_mapped, not_normal_mapped, skinned, morph, rigid, then built_in.
const std::vector<ContentKindDef>& contentKindDefs();

// Whether the report's scenes recorded their content kinds (a report.json made before did not).
bool kindsRecorded(const nlohmann::json& report);
// Whether the report has both file and built-in scenes (the built-in kind is then answered).
bool hasBuiltInBesideFiles(const nlohmann::json& report);

// Adds to report["figures"], for each kind K (and pipeline p, AMD family f):
//   kind.vertices.K, kind.primitives.K; kind.share_vertices.K, kind.share_primitives.K (% of
//   the content's drawn vertices / primitives);
//   kind.fetched_bytes_per_vertex.K.p, kind.uploaded_bytes_per_vertex.K.p (bytes fetched /
//   vertex bytes needed per vertex referenced), kind.fetched_over_baseline.K.p,
//   kind.uploaded_over_baseline.K.p (per frame, p / the baseline, summed over the scenes);
//   kind.ops_counted.K.p, kind.ops_spirv.K.p (mean over drawn vertices, each by its variant);
//   kind.isa_instructions.K.f.p; kind.frame_time.K (median over the timed scenes with K of
//   each scene's paired motor / matrix ratio); kind.image_worst_psnr.K.p,
//   kind.image_identical_frames.K.p (the frames of the scenes with K).
void addKindFigures(nlohmann::json& report);

}  // namespace mb::document
