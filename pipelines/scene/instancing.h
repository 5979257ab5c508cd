// Instances of a node's mesh (Node::instances): the instance matrices, the mesh bounds that
// frame them, and `--instances N`'s synthesised grid (the same draw path as
// EXT_mesh_gpu_instancing, so a scene can be made vertex-bound on any GPU).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb {

// Object-space bounds of a mesh (positions, morphed by `weights` when given, and Bezier control
// points); lo > hi when empty.
struct MeshBounds {
  glm::vec3 lo{1e30f}, hi{-1e30f};
  bool empty() const { return lo.x > hi.x; }
};
MeshBounds meshBounds(const Mesh& mesh, const std::vector<float>& weights = {});

// Whether node `n` can be drawn instanced: it has a mesh, no skin (the extension allows one;
// what its instances would mean differs between viewers, so it is drawn once) and no Bezier
// patch primitive (those are already drawn instanced, one instance per patch).
bool instanceable(const Scene& scene, const Node& node);

// Clears Node::instances where !instanceable (drawn once); returns the number of nodes
// (LoadStats::instancingDrawnOnce) and lists each in scene.unsupported.
int dropUndrawableInstances(Scene& scene);

// Every instanceable mesh node is drawn `count` times (count >= 1; 1 changes nothing):
// its instances (or the node itself) repeated on a square grid in the node's own space,
// centred on it, spaced by 1.25 x the mesh's bounds. Returns the mesh nodes left drawn once
// (not instanceable).
int addGridInstances(Scene& scene, int count);

}  // namespace mb
