// Geometry compression extensions, decoded on the parsed tinygltf::Model before conversion, so
// that convertMesh reads ordinary accessors and a compressed file gives the Scene its
// uncompressed original gives (up to the codec's quantisation). Errors name the bufferView or
// the primitive and the reason, without the file name (the loader prefixes it).
#pragma once
#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace tinygltf {
class Model;
}

namespace mb {

// EXT_meshopt_compression / KHR_meshopt_compression (libmeshoptimizer): every bufferView with
// the extension is decoded (ATTRIBUTES / TRIANGLES / INDICES, then the OCTAHEDRAL, QUATERNION
// or EXPONENTIAL filter) into a buffer of its own and repointed there; its fallback buffer is
// never read (it may have no data). Accessors on a filtered (lossy) view lose their min/max:
// the bounds describe the data before the filter.
Status decodeMeshoptViews(tinygltf::Model& model, CompressionStats& stats);

// KHR_draco_mesh_compression (Draco's decoder): each triangle primitive with the extension is
// decoded and its attributes (by the extension's ids) and indices become accessors of their own
// on new bufferViews; the declared accessors' count and type must match the decoded data (else
// an error naming the primitive). The declared accessors keep no min/max (their data lives in
// the extension; quantised values may lie outside the original bounds). Points/lines primitives
// are left for convertMesh to skip.
Status decodeDracoPrimitives(tinygltf::Model& model, CompressionStats& stats);

}  // namespace mb
