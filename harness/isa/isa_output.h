// What `motorbench isa` writes: the JSON (schema motorbench-isa/1, read by report and claims),
// the text table (stdout, results/isa.txt) and one ISA text file per shader and family.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/isa/isa_run.h"
#include "pipelines/result.h"

namespace mb::isa {

nlohmann::json toJson(const IsaRun& run);
// Per pipeline and program, the vertex shader's instructions / VGPRs per family; then the
// fragment shaders; then the --device line.
std::string formatTable(const IsaRun& run);
// DIR/<pipeline>.<program>.<stage>.<family>.txt; the error names the file it could not write.
Status writeIsaText(const IsaRun& run, const std::string& dir);

}  // namespace mb::isa
