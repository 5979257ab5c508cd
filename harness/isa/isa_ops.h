// `motorbench ops`'s ISA columns: each whole vertex-shader variant's counted and SPIR-V ops
// (harness/ops/ops_vertex.h) beside its AMD ISA instructions and VGPRs per family.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/isa/isa_run.h"
#include "harness/ops/ops_vertex.h"

namespace mb::isa {

// The isa vertex row of a variant on family `f` (matched by pipeline, file and defines), or nullptr.
const ShaderStats* vertexRow(const IsaRun& run, const opsv::ShaderVariant& v, size_t family);

std::string formatIsaBesideOps(const opsv::VertexOps& ops, const IsaRun& run);
// {"driver", "families": [ids], "variants": [{pipeline, variant, perFamily: {id: {instructions, vgprs, wavesPerSimd}}}]}
nlohmann::json isaBesideOpsJson(const opsv::VertexOps& ops, const IsaRun& run);

}  // namespace mb::isa
