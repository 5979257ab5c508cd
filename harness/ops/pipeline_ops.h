// Ops per vertex, one row per registered pipeline (pipelines/registry.cpp), derived from
// shader_variants.h's table and the measured kernels (ops_vertex.h): what the report, `motorbench
// ops`, the claims and the README's pipeline table quote.
//   rigid:   the transform kernel of the "rigid" variant (object to world, with frame)
//   skinned: the transform kernel of the "skinned" variant (4 joints), glTF pipelines only
//   to clip: the whole "rigid" variant (transform + world to clip)
//   patch:   the whole "bezier patch" variant where the pipeline has one
// A curved pipeline's "rigid" is its instance variant (no skinning in curved space).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/ops/ops_vertex.h"

namespace mb::opsv {

struct OpsFigure {
  OpCounts counted;
  std::optional<spirv::Counts> spirv;  // the kernels' optimised probes; none without the tools
  bool present = false;                // the pipeline has this variant
};

struct PipelineOps {
  std::string pipeline;
  OpsFigure rigid, skinned, toClip, patch;
  std::string problem;  // "" when every figure the pipeline needs is present and non-zero
};

// One row per allPipelineNames() entry, in registry order.
std::vector<PipelineOps> pipelineOps(const VertexOps& ops);

// mul + add + div + sqrt + other.
uint64_t total(const OpCounts& c);
uint64_t total(const spirv::Counts& c);

// The README pipeline table's ops cell: "rigid / skinned / to clip (SPIR-V the same)", totals
// per vertex, e.g. "85 / 393 / 113 (85 / 393 / 113)"; "-" for a figure the pipeline lacks.
std::string readmeOpsCell(const PipelineOps& row);

// `motorbench ops`' per-pipeline table (mul/add/div/sqrt/other per figure) and its JSON.
std::string formatPipelineOps(const std::vector<PipelineOps>& rows);
nlohmann::json toJson(const std::vector<PipelineOps>& rows);

}  // namespace mb::opsv
