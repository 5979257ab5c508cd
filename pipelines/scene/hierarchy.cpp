#include "pipelines/scene/hierarchy.h"

#include <algorithm>
#include <utility>

namespace mb {

namespace {

// The same entries, stably sorted by depth (roots first, then their children, ...): each
// entry still follows its parent, and consecutive entries no longer form a parent-to-child
// chain, so the per-frame loop's products overlap in the CPU instead of each waiting for the
// previous one's result (a chain of 4 joints under an instance node was latency-bound).
HierarchyOrder byDepth(const HierarchyOrder& walk, size_t count) {
  std::vector<int> depth(count, 0);
  std::vector<std::pair<int, size_t>> keys;  // (depth, walk position)
  keys.reserve(walk.nodes.size());
  for (size_t i = 0; i < walk.nodes.size(); ++i) {
    const int parent = walk.parents[i];
    depth[size_t(walk.nodes[i])] = parent >= 0 ? depth[size_t(parent)] + 1 : 0;
    keys.emplace_back(depth[size_t(walk.nodes[i])], i);
  }
  std::stable_sort(keys.begin(), keys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  HierarchyOrder order;
  order.nodes.reserve(keys.size());
  order.parents.reserve(keys.size());
  for (const auto& key : keys) {
    order.nodes.push_back(walk.nodes[key.second]);
    order.parents.push_back(walk.parents[key.second]);
  }
  return order;
}

}  // namespace

HierarchyOrder hierarchyOrder(const Scene& scene) {
  const size_t count = scene.nodes.size();
  HierarchyOrder order;
  order.nodes.reserve(count);
  order.parents.reserve(count);
  std::vector<char> state(count, 0);  // 0 todo, 1 on the current chain (cycle guard), 2 done
  std::vector<size_t> chain;
  for (size_t start = 0; start < count; ++start) {
    // Walk up to the first finished ancestor, then emit the chain top-down.
    chain.clear();
    for (size_t n = start; n < count && state[n] == 0;) {
      state[n] = 1;
      chain.push_back(n);
      const int parent = scene.nodes[n].parent;
      if (parent < 0 || size_t(parent) >= count) break;
      n = size_t(parent);
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int parent = scene.nodes[*it].parent;
      const bool hasParent = parent >= 0 && size_t(parent) < count && state[size_t(parent)] == 2;
      order.nodes.push_back(int(*it));
      order.parents.push_back(hasParent ? parent : -1);
      state[*it] = 2;
    }
  }
  return byDepth(order, count);
}

}  // namespace mb
