// The kinds of content a scene draws, as the answer splits it: by material (normal-mapped or
// not: the matrix side uploads a tangent only for the former) and by how the vertex moves
// (skinned; morph: morph targets and no skin; rigid: the rest). Counted per drawn primitive
// (each (node, primitive) of the draw list, times the node's instances), Bezier patches and
// curved-space instances left out.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "pipelines/scene/scene.h"

namespace mb::report {

struct ContentKind {
  bool normalMapped = false;
  std::string deformation;  // "rigid", "skinned" or "morph"
  bool instanced = false;
};

ContentKind contentKindOf(const Scene& scene, const Node& node, const Primitive& p);

// {"cells": [{"normalMapped", "deformation", "instanced", "vertices", "primitives"}...]}: the
// drawn vertices and primitives of each combination the scene has (vertices: the primitive's
// vertices times its node's instances, as vertexMix counts them).
nlohmann::json contentKindsJson(const Scene& scene);

// The keys a vertex-fetch split is kept under for `k`: its material kind ("normalMapped" or
// "notNormalMapped") and its deformation kind.
std::string materialKey(const ContentKind& k);

}  // namespace mb::report
