// AMD ISA statistics per family and pipeline, and where the three kinds of op evidence (counted,
// SPIR-V probe, ISA instructions) put the pipelines in different orders (issue 35 item 8).
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

// "" when counted ops, SPIR-V (probe) and ISA instructions (the median over families) order every
// two pipelines of `label` ("rigid": the rigid vertex to clip, "skinned") alike; else one line
// naming each pair they order differently.
std::string rankingLine(const nlohmann::json& isa, const std::string& label);
// The row with the table of the three (own: ops evidence).
Claim rankingClaim(const nlohmann::json& isa, const std::string& label);

}  // namespace mb::claims
