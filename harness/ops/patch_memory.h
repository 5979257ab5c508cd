// Bytes a Bezier patch scene costs each pipeline: what the instanced tessellation
// uploads (the control points + one refinement pattern) against the same surface
// pre-tessellated into an ordinary vertex buffer at the same level. Both sides are measured:
// each pipeline prepares the scene as it is and a copy whose patch primitives were tessellated
// on the CPU (shaders/bezier_patch.glsl through the shim) into triangle primitives, and the
// byte counters of its PipelineStats (real upload sizes) are read.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/pipeline.h"
#include "pipelines/result.h"

namespace mb::opsv {

// `patches` tessellated at level n: per patch (n+1)^2 vertices (edges not shared between
// patches, as a renderer would write them), position, unit normal (dP/du x dP/dv), tangent
// (dP/du, w = +1), uv on the patch; 2 n^2 triangles per patch.
Primitive tessellatePatches(const Primitive& patches, int level);

struct PatchMemoryRow {
  std::string pipeline;
  int level = 0;
  uint64_t instancedBytes = 0;      // patchBytes + patchPatternBytes + pattern indexBytes
  uint64_t controlPointBytes = 0;   // patchBytes alone
  uint64_t pretessellatedBytes = 0; // vertexBytes + indexBytes of the tessellated copy
  uint64_t pretessellatedVertices = 0;
};

// One row per (registered pipeline, level). Needs the shared GL context (created here).
Result<std::vector<PatchMemoryRow>> measurePatchMemory(const Scene& scene, const std::vector<int>& levels);
std::string formatPatchMemory(const std::vector<PatchMemoryRow>& rows);
nlohmann::json toJson(const std::vector<PatchMemoryRow>& rows);

}  // namespace mb::opsv
