// "scaled_hierarchy": an animated hierarchy with uniform scales at three levels (one of them
// animated, CUBICSPLINE), one non-uniformly scaled leaf and one negatively scaled (det < 0)
// node, all carrying the textured box so the effect of each scale is visible.
#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

void buildScaledHierarchy(GlbBuilder& b) {
  int box = addTexturedBoxMesh(b);
  int root = b.addNode("root", glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(2.0f));
  int arm = b.addNode("arm", glm::vec3(1.0f, 0.0f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(0.5f));
  int forearm = b.addNode("forearm", glm::vec3(2.0f, 0.0f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.5f));
  int leaf = b.addNode("stretched_leaf", glm::vec3(1.2f, 0.0f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f, 2.5f, 0.5f));
  int mirror = b.addNode("mirrored", glm::vec3(-1.5f, 0.0f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(-1.0f, 1.0f, 1.0f));
  b.addChild(root, arm);
  b.addChild(arm, forearm);
  b.addChild(forearm, leaf);
  b.addChild(root, mirror);
  for (int n : {root, arm, forearm, leaf, mirror}) b.setMesh(n, box);
  b.addRoot(root);

  int anim = b.addAnimation("animate");
  std::vector<float> spin;  // quarter turns about Y (LINEAR slerp)
  for (int k = 0; k <= 4; ++k) {
    glm::quat q = glm::angleAxis(1.57079632679f * float(k), glm::vec3(0, 1, 0));
    spin.insert(spin.end(), {q.x, q.y, q.z, q.w});
  }
  b.addChannel(anim, root, "rotation", {0, 1, 2, 3, 4}, spin);
  // Uniform scale pulse on "forearm": CUBICSPLINE [in-tangent, value, out-tangent] per key.
  b.addChannel(anim, forearm, "scale", {0, 2, 4},
               {0, 0, 0, 1.5f, 1.5f, 1.5f, 0, 0, 0,  0, 0, 0, 2, 2, 2, 0, 0, 0,  0, 0, 0, 1.5f, 1.5f, 1.5f, 0, 0, 0},
               "CUBICSPLINE");
  b.addChannel(anim, mirror, "translation", {0, 1, 2, 3},
               {-1.5f, 0, 0, -1.5f, 0.3f, 0, -1.5f, 0, 0, -1.5f, -0.3f, 0}, "STEP");
}

}  // namespace mb
