// Where the three kinds of op evidence order the pipelines differently: counted
// ops, SPIR-V probe ops and AMD ISA instructions of one vertex shader scope ("rigid vertex to
// clip", "skinned vertex to clip"). Computed once into report.json "opsRanking" (with each
// measure's definition and device) and the figures ops_ranking.<scope>.pairs_reversed;
// report.md's ops section and claims' ops_ranking_* rows print its "line" and the table of the
// three, never a ranking of their own.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

// {"rigid": S, "skinned": S} from the ops room's shader variants (opsv::toJson(VertexOps)
// "variants": pipeline, variant, counted, spirv_kernel_probes) and a `motorbench isa` JSON
// (null: no ISA measure). S = {"scope", "measures": [{"key", "name", "definition", "device"}],
// "table": {pipeline: {key: value or null}}, "ranks": {key: {pipeline: rank}}, "pairs" (pipeline
// pairs at least two measures order), "reversed": [{"a", "b", "cheaper": {key: pipeline}}],
// "line"}. A pair is reversed when one measure puts a strictly below b and another b strictly
// below a (a tie orders nothing). The line says "disagree" exactly when some pair is reversed.
nlohmann::json opsRanking(const nlohmann::json& opsVariants, const nlohmann::json& isa);

// report["opsRanking"] from its opsPerVertex.detail.variants and isa, and the figures
// ops_ranking.<scope>.pairs_reversed (value: reversed pairs, n: pairs compared).
void addOpsRanking(nlohmann::json& report);

// "matrix 113 / 113 / 129, motor 132 / 132 / 137 (counted ops / SPIR-V probe ops / ...)":
// one scope's table in one line ("-" where a measure lacks the pipeline).
std::string opsRankingTableText(const nlohmann::json& scope);

// For report.md's ops section: per scope its line, the measures' definitions and the table of
// the three (value and rank per measure).
void opsRankingSection(Document& d, const nlohmann::json& report);

}  // namespace mb::document
