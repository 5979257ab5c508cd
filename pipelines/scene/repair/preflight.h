// Container checks run before tinygltf sees the bytes: GLB header and chunk sizes, JSON
// syntax, and every bufferView against its buffer's declared byteLength. tinygltf 2.7 reads
// image bufferViews without a range check, so this is what keeps malformed files from
// causing out-of-range reads; it also yields precise messages.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"
#include "pipelines/scene/repair/conformance.h"

namespace mb {

// Returns an error (without file name) or success; *isGlb tells which container it is.
// `nameHint` (the file name) turns a non-GLB file named *.glb into "bad GLB magic".
// `conformed` (optional) receives the rewrite of a valid document tinygltf 2.7 would refuse
// (conformance.h): its bytes (empty when none is needed) and what to restore after parsing.
Status preflightGltf(const std::vector<uint8_t>& bytes, const std::string& nameHint, bool* isGlb,
                     ConformedGltf* conformed = nullptr);

// Why tinygltf 2.7 refused a document that passed preflightGltf without saying why: the first
// property the glTF 2.0 schema requires that is missing (e.g. "skin 0 has 'jointNames' but no
// 'joints': glTF 2.0 pre-release file"), or "" when none is missing.
std::string explainRefusal(const std::vector<uint8_t>& bytes);

}  // namespace mb
