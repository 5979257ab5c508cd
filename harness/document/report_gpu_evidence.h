// The report's GPU-relevant evidence: per scene and pipeline, what meshoptimizer's model says the
// vertex stage of a GPU fetches and transforms per frame for the pipeline's own vertex layout
// (report.json scenes[].pipelines[p].vertexFetch and scenes[].overdraw, harness/report/vertex_fetch.h).
// Modelled from the mesh and the layout, not timed.
#pragma once
#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

inline constexpr const char* kGpuEvidenceAnchor = "gpu-evidence";

void gpuEvidenceSection(Document& d, const nlohmann::json& report);

}  // namespace mb::document
