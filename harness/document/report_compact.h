// The report's "bytes vs image cost vs unpack cost" table: per glTF pipeline the
// bytes per vertex measured from its uploads, its worst image difference against the baseline
// (the frames where both should agree), the counted ops of its frame decoding and of its rigid
// vertex, its frame-time ratios and, when report.json embeds `motorbench isa`, its rigid vertex
// shader's AMD instructions and VGPRs per family.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

void compactSection(Document& d, const nlohmann::json& report);

// The counted GLSL function that gives `pipeline`'s shading normal per fragment
// (shaders/frame_shading.glsl): from the interpolated rotor (motor_cf) or from a normal and a
// tangent, with a normal map or without one.
std::string shadingNormalKernel(const std::string& pipeline, bool normalMapped);

}  // namespace mb::document
