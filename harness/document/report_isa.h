// The report's ISA section: per pipeline, each vertex-shader variant's counted and SPIR-V ops
// beside AMD's compiled shader per family (instructions, VGPRs, waves per SIMD), from the
// `motorbench isa` JSON that `report --isa-json` embeds as report.json "isa".
#pragma once
#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::report {

void isaSection(Document& d, const nlohmann::json& report);

}  // namespace mb::report
