// The report's ISA section: per pipeline, each vertex-shader variant's counted and SPIR-V ops
// beside AMD's compiled shader per family (instructions, VGPRs, waves per SIMD), from the
// `motorbench isa` JSON that `report --isa-json` embeds as report.json "isa".
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

void isaSection(Document& d, const nlohmann::json& report);

// The vertex-shader row of `motorbench isa` JSON `isa` for (pipeline, variant label, family
// id), or null (also used by the compact table and claims).
const nlohmann::json* isaRow(const nlohmann::json& isa, const std::string& pipeline, const std::string& label,
                             const std::string& family, const std::string& stage = "vertex");

}  // namespace mb::document
