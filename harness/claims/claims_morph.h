// Morph targets, our own rows (not claimed by the paper): does the paper's 9-float
// motor vertex survive blend shapes, what each rotor method costs per target, and which method
// is exact. Read from report.json "morph" (`motorbench morph` via `report --morph-json`): the
// figures are quoted by name, none recomputed.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"

namespace mb::claims {

// Rows morph_vertex_bytes, morph_target_bytes, morph_frame_image, morph_rotor_image; each "not
// measurable here" with the reason when the report has no morph figures.
std::vector<Claim> morphClaims(const nlohmann::json& report, const std::string& reportSource);

}  // namespace mb::claims
