// Internal steps of the glTF loader: tinygltf::Model -> Scene parts. Each returns an error
// message without the file name (the loader prefixes it) and records what it could not
// represent in scene.unsupported.
#pragma once
#include <cstdint>
#include <string>

#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace tinygltf {
class Model;
struct Primitive;
}

namespace mb {

// Mesh `index`: decoded, validated, repaired primitives. `jointCount` bounds JOINTS_n values
// (smallest joint count of the skins used with this mesh; 65536 when none). Uses
// scene.materials (already converted) to decide where tangents are needed.
Result<Mesh> convertMesh(const tinygltf::Model& model, int index, uint32_t jointCount,
                         Scene& scene);

// Morph targets of `primitive` (gltf_morph.cpp): POSITION / NORMAL / TANGENT deltas, sparse
// accessors applied, counts checked against `vertexCount` -> p.targets; other target
// attributes are listed in scene.unsupported. `where` names the primitive in errors.
Status convertMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                           size_t vertexCount, const std::string& where, Primitive& p, Scene& scene);
// Mesh `index`'s default weights -> mesh.weights (zeros when not authored); fails when its
// primitives disagree on the target count or the weights do not match it.
Status convertMeshWeights(const tinygltf::Model& model, int index, Mesh& mesh);
// Node weights whose count is not the node's mesh's target count are listed in
// scene.unsupported and cleared (the mesh's weights apply). Call after the meshes.
void checkNodeWeights(Scene& scene);

// The MB_bezier_patches primitive extension (gltf_patches.cpp): a POINTS primitive whose
// POSITION holds 16 control points per bicubic patch -> a primitive with patchPoints.
// The glTF validator's unit-length tolerance for quaternions (just above the error of signed
// 8-bit quantization, which KHR_mesh_quantization allows for rotation outputs): keyframes and
// instance rotations.
inline constexpr float kUnitQuaternionTolerance = 0.00769f;

constexpr const char* kBezierPatchesExtension = "MB_bezier_patches";
Result<Primitive> convertPatchPrimitive(const tinygltf::Model& model,
                                        const tinygltf::Primitive& primitive, int materialCount);

// EXT_mesh_gpu_instancing on node `node` (gltf_instancing.cpp): its per-instance TRS accessors
// -> scene.nodes[node].instances (types, equal counts and finite values checked). Call after
// the node's mesh and skin are set.
constexpr const char* kInstancingExtension = "EXT_mesh_gpu_instancing";
Status convertInstancing(const tinygltf::Model& model, size_t node, Scene& scene);

// All animations (T/R/S channels and morph weights channels; call after the meshes).
Status convertAnimations(const tinygltf::Model& model, Scene& scene);

// Materials, textures, samplers and images (decoded to RGBA8).
Status convertMaterials(const tinygltf::Model& model, Scene& scene);

// Counts accessors whose declared min/max disagree with their data (accessor_bounds.cpp).
void countAccessorBoundsMismatches(const tinygltf::Model& model, Scene& scene);
// Counts accessors read past the end of their bufferView, inside its buffer (accessor_bounds.cpp).
void countAccessorsPastBufferView(const tinygltf::Model& model, Scene& scene);

// Nodes (hierarchy validated: indices in range, one parent each, no cycles), skins, cameras,
// default scene roots.
Status convertNodes(const tinygltf::Model& model, Scene& scene);

}  // namespace mb
