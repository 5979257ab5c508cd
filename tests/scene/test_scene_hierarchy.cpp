// pipelines/scene/hierarchy.h: every node once, each after the parent it composes with, also
// for malformed graphs (a cycle, a parent index out of range), and world matrices composed in
// that order equal the hand-computed products.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/hierarchy.h"

using namespace mb;

namespace {

Scene withParents(const std::vector<int>& parents) {
  Scene scene;
  scene.nodes.resize(parents.size());
  for (size_t n = 0; n < parents.size(); ++n) {
    scene.nodes[n].parent = parents[n];
    scene.nodes[n].local.translation = glm::vec3(float(n + 1), 0.0f, 0.0f);
  }
  return scene;
}

}  // namespace

TEST(SceneHierarchy, ParentsComeFirst) {
  // 3 -> 0 -> 2, 1 a root, 4 -> 1, 5 has an out-of-range parent.
  const Scene scene = withParents({2, -1, -1, 0, 1, 42});
  const HierarchyOrder order = hierarchyOrder(scene);
  ASSERT_EQ(order.nodes.size(), 6u);
  std::vector<int> position(6, -1);
  for (size_t i = 0; i < order.nodes.size(); ++i) {
    ASSERT_EQ(position[size_t(order.nodes[i])], -1) << "node twice";
    position[size_t(order.nodes[i])] = int(i);
  }
  for (size_t i = 0; i < order.nodes.size(); ++i) {
    const int n = order.nodes[i], p = order.parents[i];
    const int authored = scene.nodes[size_t(n)].parent;
    EXPECT_EQ(p, authored >= 0 && authored < 6 ? authored : -1) << n;
    if (p >= 0) {
      EXPECT_LT(position[size_t(p)], int(i)) << n;
    }
  }
  // World x of node 3 = 3 (node 2) + 1 (node 0) + 4 (itself).
  const std::vector<glm::mat4> world = worldMatrices(scene, {});
  EXPECT_EQ(world[3][3].x, 8.0f);
  EXPECT_EQ(world[5][3].x, 6.0f);
}

TEST(SceneHierarchy, CycleIsCutOnce) {
  const Scene scene = withParents({1, 0});  // 0 <-> 1
  const HierarchyOrder order = hierarchyOrder(scene);
  ASSERT_EQ(order.nodes, (std::vector<int>{1, 0}));
  EXPECT_EQ(order.parents, (std::vector<int>{-1, 1}));
}
