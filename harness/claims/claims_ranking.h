// AMD ISA statistics per family and pipeline, and the rows that say where the three kinds of op
// evidence (counted, SPIR-V probe, ISA instructions) put the pipelines in different orders
// (the ranking itself is computed once, by harness/document/ops_ranking.h).
#pragma once
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"

namespace mb::claims {

struct IsaStats {
  double instructions = 0, vgprs = 0, waves = 0;  // waves: per SIMD (occupancy)
};
// family (" (NGG)" appended in NGG mode) -> pipeline -> the vertex shader `program`'s statistics
// (its "_normalmap" form where the family has one), from a `motorbench isa` JSON.
using IsaTable = std::map<std::string, std::map<std::string, IsaStats>>;
IsaTable isaVertexTable(const nlohmann::json& isa, const std::string& program);

// The ops_ranking_<label> row ("rigid", "skinned"): one scope of report.json's "opsRanking"
// (harness/document/ops_ranking.h), printed as it is -- its line as the verdict, the table of the
// three measures as the measured value; `source` names where the ranking was read.
Claim rankingClaim(const nlohmann::json& scope, const std::string& label, const std::string& source);
// The scope's line when its measures disagree on some pair, else "".
std::string disagreementLine(const nlohmann::json& scope);

}  // namespace mb::claims
