#include "pipelines/scene/hierarchy.h"

namespace mb {

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
  return order;
}

}  // namespace mb
