// The order in which a scene's world transforms are composed, computed once per scene so that
// every pipeline's per-frame hierarchy pass is one loop with no walking and no allocation.
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb {

// Every node once, each after the parent it composes with.
struct HierarchyOrder {
  std::vector<int> nodes;    // composition order (all of scene.nodes)
  std::vector<int> parents;  // parents[i]: the node nodes[i] composes with; -1: it starts a
                             // chain (a root, an invalid parent index, or where a cycle was cut)
};

// Which parent each node composes with is the walk worldMatrices() has always done (its results
// are unchanged): for each node in index order, its chain of unvisited ancestors top-down; a
// node whose parent was still on the chain being walked (a cycle) starts the chain instead.
// Nodes unreachable from a root get the chain up to their topmost ancestor. The entries are
// then ordered by depth (stable): siblings and cousins side by side, so that consecutive
// products do not wait on each other.
HierarchyOrder hierarchyOrder(const Scene& scene);

}  // namespace mb
