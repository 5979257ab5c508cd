// Valid glTF 2.0 that tinygltf 2.7 refuses, rewritten into an equivalent document it reads.
// preflightGltf runs these on the document it has parsed; the loader hands
// tinygltf ConformedGltf::bytes and then puts back what the rewrite had to take out.
//   - whole numbers written as floats ("byteLength": 4.0) where the schema wants an integer
//   - data: URIs tinygltf does not recognise (RFC 2397: percent-encoded instead of base64,
//     media type parameters, upper case): decoded and re-encoded as "...;base64,"
//   - buffers without uri that no bufferView reads (placeholders, also GLB buffer 0 without a
//     BIN chunk): given a 3-byte data: URI for tinygltf, emptied again after parsing
//   - primitive indices whose accessor has no bufferView (all zeros): taken out of the JSON
//     (tinygltf refuses them) and restored on the parsed model; accessors.cpp reads the zeros
// What stays an error, with the reason: a URI with a scheme other than data: for a buffer
// (http://, file:// ...), a buffer without uri that a bufferView reads (except GLB buffer 0
// with a BIN chunk), a data: URI with another media type or a length other than byteLength.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace tinygltf {
class Model;
}

namespace mb {

struct ConformedGltf {
  std::vector<uint8_t> bytes;  // the rewritten file; empty when the original needs no change
  struct Indices {
    int mesh = -1, primitive = -1, accessor = -1;
  };
  std::vector<Indices> indices;         // removed from the JSON, restored by applyConformance
  std::vector<int> placeholderBuffers;  // emptied by applyConformance
  std::vector<std::string> notes;       // for Scene::unsupported (e.g. an image URI not read)
  bool binChunkPadded = false;          // GLB BIN chunk length not a multiple of 4: zero-padded
};

// Whole-number floats -> integers for the properties the glTF 2.0 schema types as integers
// (by key, anywhere in the document: "count", "bufferView", "nodes": [...] ...). Floats that are
// not whole, or beyond 2^53, stay floats (and tinygltf's refusal stands). True when changed.
bool normaliseIntegers(nlohmann::json& doc);

// The URI, buffer and indices rewrites above on `doc` (already checked by preflightGltf).
// `glb`/`hasBinChunk` describe the container. Errors name the buffer or image, not the file.
// Sets *changed when `doc` was rewritten.
Status conformDocument(nlohmann::json& doc, bool glb, bool hasBinChunk, ConformedGltf* out, bool* changed);

// `doc` serialised as the container it came in: .gltf text, or a GLB whose JSON chunk is
// replaced and whose other chunks are copied from `original` (starting at `restBegin`, up to
// the header's length).
std::vector<uint8_t> serialiseDocument(const nlohmann::json& doc, bool glb, const std::vector<uint8_t>& original,
                                       size_t restBegin, size_t restEnd);

// After tinygltf parsed ConformedGltf::bytes: restores the indices and empties the placeholders.
void applyConformance(const ConformedGltf& c, tinygltf::Model& model);

// The scheme of a URI ("http" for "http://a/b"), "" for a relative path (RFC 3986: letters,
// digits, + - . before the first ':', which must come before any '/', '?' or '#').
std::string uriScheme(const std::string& uri);

}  // namespace mb
