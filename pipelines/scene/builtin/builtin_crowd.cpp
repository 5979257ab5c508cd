// "crowd": one skinned tube mesh drawn by 256 nodes in a 16 x 16 grid, for vertex-bound
// timing. Each instance has its own skin and joint chain: a skinned mesh is placed by its
// joints' world transforms (glTF ignores the mesh node's own transform), so one shared skin
// would stack every instance in one place. The mesh and the inverse-bind accessor are shared;
// the instance offset is a parent node above the joint chain. Animation "wave" swings the
// joints with 8 phase variants (outputs shared between instances).
#include <cmath>

#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

void buildCrowd(GlbBuilder& b) {
  constexpr int kGrid = 16, kJoints = 4, kVariants = 8, kKeys = 9;
  constexpr float kLength = 2.0f, kPeriod = 2.0f;
  float spacing = kLength / float(kJoints - 1);
  MaterialDesc mat;
  mat.name = "crowd";
  mat.baseColor = glm::vec4(0.75f, 0.4f, 0.5f, 1.0f);
  mat.normalTexture = b.addTexturePng("crowd_bumps", 64, 64, bumpNormalMap(64, 4, 6, 0.05f));  // full TBN work per vertex
  int mesh = b.addMesh("crowd_tube", makeSkinnedTube(24, 16, kLength, 0.2f, kJoints), b.addMaterial(mat));
  std::vector<glm::mat4> ibm;
  for (int j = 0; j < kJoints; ++j) {
    glm::mat4 inv(1.0f);
    inv[3] = glm::vec4(0.0f, -spacing * float(j), 0.0f, 1.0f);
    ibm.push_back(inv);
  }
  int ibmAccessor = b.addInverseBindMatrices(ibm);

  std::vector<float> times;
  for (int k = 0; k < kKeys; ++k) times.push_back(kPeriod * float(k) / float(kKeys - 1));
  int timeAccessor = b.addFloatAccessor(times.data(), times.size(), 1, true);
  std::vector<int> outputs;
  for (int v = 0; v < kVariants; ++v) {
    std::vector<float> q;
    for (float t : times) {
      glm::quat r = glm::angleAxis(0.3f * std::sin(2.0f * kPi * (t / kPeriod + float(v) / kVariants)), glm::vec3(0, 0, 1));
      q.insert(q.end(), {r.x, r.y, r.z, r.w});
    }
    outputs.push_back(b.addFloatAccessor(q.data(), times.size(), 4));
  }

  int wave = b.addAnimation("wave");
  for (int i = 0; i < kGrid * kGrid; ++i) {
    glm::vec3 at(1.2f * float(i % kGrid - kGrid / 2), 0.0f, 1.2f * float(i / kGrid - kGrid / 2));
    int inst = b.addNode("instance" + std::to_string(i), at);
    std::vector<int> joints;
    for (int j = 0; j < kJoints; ++j) {
      joints.push_back(b.addNode("i" + std::to_string(i) + "_joint" + std::to_string(j),
                                 glm::vec3(0.0f, j ? spacing : 0.0f, 0.0f)));
      b.addChild(j ? joints[size_t(j - 1)] : inst, joints.back());
      if (j) b.addChannel(wave, joints.back(), "rotation", {}, {}, "LINEAR", timeAccessor, outputs[size_t((i + j) % kVariants)]);
    }
    int node = b.addNode("crowd" + std::to_string(i));
    b.setMesh(node, mesh, b.addSkin("skin" + std::to_string(i), joints, ibmAccessor));
    b.addChild(inst, node);
    b.addRoot(inst);
  }
}

}  // namespace mb
