// "skinned_tube": a normal-mapped tube skinned to a 5-joint chain, with the animations
// "bend" (index 0), "twist" (index 1, 180 degrees from base to tip, 45 degrees per joint) and
// "candy_wrapper" (index 2: the middle joint alone turns 180 degrees about the tube's axis, the
// classic case where linear blend skinning collapses the half-weighted ring to the axis).
#include <cmath>

#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

MeshData makeSkinnedTube(int rings, int sides, float length, float radius, int joints) {
  const float kTwoPi = 6.28318530718f;
  float spacing = length / float(joints - 1);
  MeshData m;
  for (int r = 0; r <= rings; ++r) {
    float y = length * float(r) / float(rings);
    float jf = y / spacing;
    int j0 = std::min(int(jf), joints - 2);
    float f = jf - float(j0);
    for (int s = 0; s <= sides; ++s) {
      float a = kTwoPi * float(s) / float(sides);
      glm::vec3 n(std::sin(a), 0.0f, std::cos(a));
      m.positions.emplace_back(radius * n.x, y, radius * n.z);
      m.normals.push_back(n);
      m.tangents.emplace_back(std::cos(a), 0.0f, -std::sin(a), 1.0f);  // dP/du; dP/dv = +Y
      m.uv0.emplace_back(float(s) / float(sides), float(r) / float(rings));
      m.joints.emplace_back(j0, j0 + 1, 0, 0);
      m.weights.emplace_back(1.0f - f, f, 0.0f, 0.0f);
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sides; ++s) {
      uint32_t a = uint32_t(r * (sides + 1) + s), c = a + uint32_t(sides + 1);
      m.indices.insert(m.indices.end(), {a, a + 1, c + 1, a, c + 1, c});
    }
  return m;
}

void buildSkinnedTube(GlbBuilder& b) {
  constexpr int kJoints = 5;
  constexpr float kLength = 4.0f;
  float spacing = kLength / float(kJoints - 1);
  MaterialDesc mat;
  mat.name = "tube";
  mat.baseColor = glm::vec4(0.35f, 0.7f, 0.45f, 1.0f);
  mat.normalTexture = b.addTexturePng("tube_bumps", 64, 64, bumpNormalMap(64, 6, 8, 0.05f));
  int mesh = b.addMesh("tube", makeSkinnedTube(32, 24, kLength, 0.3f, kJoints), b.addMaterial(mat));

  std::vector<int> joints;
  std::vector<glm::mat4> ibm;
  for (int j = 0; j < kJoints; ++j) {
    joints.push_back(b.addNode("joint" + std::to_string(j), glm::vec3(0.0f, j ? spacing : 0.0f, 0.0f)));
    if (j) b.addChild(joints[size_t(j - 1)], joints.back());
    glm::mat4 inv(1.0f);
    inv[3] = glm::vec4(0.0f, -spacing * float(j), 0.0f, 1.0f);
    ibm.push_back(inv);
  }
  int node = b.addNode("tube");
  b.setMesh(node, mesh, b.addSkin("tube_skin", joints, b.addInverseBindMatrices(ibm)));
  b.addRoot(node);
  b.addRoot(joints[0]);

  auto rotations = [](const std::vector<float>& angles, glm::vec3 axis) {
    std::vector<float> v;
    for (float a : angles) {
      glm::quat q = glm::angleAxis(a, axis);
      v.insert(v.end(), {q.x, q.y, q.z, q.w});
    }
    return v;
  };
  int bend = b.addAnimation("bend");
  for (int j = 1; j < kJoints; ++j)
    b.addChannel(bend, joints[size_t(j)], "rotation", {0.0f, 1.0f, 2.0f}, rotations({0.0f, 0.35f, 0.0f}, {0, 0, 1}));
  int twist = b.addAnimation("twist");  // each joint adds pi/4: the tip turns pi relative to the base
  for (int j = 1; j < kJoints; ++j)
    b.addChannel(twist, joints[size_t(j)], "rotation", {0.0f, 2.0f},
                 rotations({0.0f, kPi / float(kJoints - 1)}, {0, 1, 0}));
  int wrap = b.addAnimation("candy_wrapper");
  b.addChannel(wrap, joints[size_t(kJoints / 2)], "rotation", {0.0f, 1.0f, 2.0f},
               rotations({0.0f, 0.5f * kPi, kPi}, {0, 1, 0}));
}

}  // namespace mb
