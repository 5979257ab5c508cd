// The report's morph section: per morph method (matrix; motor (a) frame, the motor
// pipelines' default; motor (b) rotor deltas) its bytes per vertex and per target vertex, ops
// (the method's counted kernel, the whole morphing shader's SPIR-V beside its rigid shader's),
// AMD ISA instructions / VGPRs on two families (morphing vs rigid), and its image cost: worst
// PSNR and max error vs matrix on unskinned frames (vs the CPU skin reference on skinned ones).
// Reads report.json "morph" (`motorbench morph --json`, given to `report --morph-json`),
// "opsPerVertex" and "isa"; quotes figures by name, computes none.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

void morphSection(Document& d, const nlohmann::json& report);

// The table's rows as text, one per method (header first): also what the tests read.
std::vector<std::vector<std::string>> morphTable(const nlohmann::json& report);

// The two ISA families the table shows: the first and the last of report.json's isa families
// (the oldest and newest generation compiled), ids; empty without isa.
std::vector<std::string> morphIsaFamilies(const nlohmann::json& report);

}  // namespace mb::document
