// Ops per vertex for the report: the per-vertex kernels and whole vertex-shader variants of
// harness/ops/ops_vertex.h (counted through the shim and, when glslang/spirv-tools run, counted in
// the optimised SPIR-V), and per scene the average over the vertices it draws, weighted by the
// variant each vertex goes through (report_scene.h, vertexMix).
#pragma once
#include <nlohmann/json.hpp>

namespace mb::report {

// {"kernels": [...], "variants": [...], "toolsProblem": ..., "perPipeline": [...]} with, for
// every variant (one pipeline's rigid / skinned / scaled-fallback vertex shader incl. world to
// clip), "counted" and "spirv" mul/add/div/sqrt/other; "perPipeline": harness/ops/pipeline_ops.h's
// rows (rigid, skinned, to clip, patch of every registered pipeline).
// Progress goes to stderr ("report: counting ops per vertex: 23/71 (...), 20 s elapsed, about
// 40 s left") every few seconds: compiling every probe and variant takes a minute or more.
nlohmann::json measureOpsPerVertex();

// Per pipeline, the mean ops of one drawn vertex of a scene with `mix` ({"rigid", "skinned",
// "scaledFallback"} vertex counts): {"matrix": {"counted": {...}, "spirv": {...}}, ...}. The
// motor pipeline's scaled-fallback vertices use its "scaled fallback" variant; other pipelines
// have none and use "rigid". A curved scene ("curvedInstance" > 0): the "<curvedSpace>
// instance" variant ("S3 instance", "H3 instance") of each pipeline that has it. null when the
// scene draws nothing.
// `pipelines` (the scene's report entry "pipelines", or null): each pipeline's "fallbacks"
// (the most in any frame drawn); the vertices its exact fallback drew (fallbackVertices, of them
// skinFallbackVertices) are priced at its "linear fallback" and "skinned, linear fallback"
// variants instead of the rigid and skinned ones, and each row says how many ("fallbackVertices").
nlohmann::json sceneOpsPerVertex(const nlohmann::json& ops, const nlohmann::json& mix,
                                 const nlohmann::json& pipelines = nullptr);

}  // namespace mb::report
