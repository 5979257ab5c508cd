// "morph_torus": a normal-mapped torus with two morph targets and animated weights.
// Target 0 "pinch" varies the tube radius around the ring (r (1 + 0.5 cos 2 phi)); target 1
// "wave" lifts the ring (y + 0.35 sin 3 phi) and turns the tube about its centre line
// (theta + 0.8 sin phi), so its frames turn well away from the base ones. Each target's normal
// and tangent deltas come from its own surface (central differences of the parametric form,
// tangent = direction of increasing u as on the base torus), so a renderer that morphs the
// frame shades the morphed surface. Animation "morph": LINEAR weights (0,0) -> (1,0) -> (1,1)
// -> (0,1) over 3 s.
#include <cmath>

#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {
namespace {

constexpr int kMajor = 48, kMinor = 24;

// The surface of target `k` (-1: the base torus) at ring angle phi, tube angle theta.
glm::vec3 surface(int k, float phi, float theta) {
  float r = 0.35f, lift = 0.0f;
  if (k == 0) r *= 1.0f + 0.5f * std::cos(2.0f * phi);
  if (k == 1) {
    lift = 0.35f * std::sin(3.0f * phi);
    theta += 0.8f * std::sin(phi);
  }
  const float ring = 1.0f + r * std::cos(theta);
  return {ring * std::cos(phi), r * std::sin(theta) + lift, -ring * std::sin(phi)};
}

struct Frame {
  glm::vec3 position, normal, tangent;
};

// Position, outward normal and unit dP/dphi of surface k, by central differences.
Frame frameOf(int k, float phi, float theta) {
  const float h = 1e-3f;
  const glm::vec3 dphi = surface(k, phi + h, theta) - surface(k, phi - h, theta);
  const glm::vec3 dtheta = surface(k, phi, theta + h) - surface(k, phi, theta - h);
  // (dP/dtheta x dP/dphi) points outward on the base torus (its normal at theta = 0 is +x at phi = 0).
  return {surface(k, phi, theta), glm::normalize(glm::cross(dtheta, dphi)), glm::normalize(dphi)};
}

}  // namespace

void buildMorphTorus(GlbBuilder& b) {
  MeshData m;
  m.targets.resize(2);
  for (int i = 0; i <= kMajor; ++i) {
    const float phi = 2.0f * kPi * float(i) / float(kMajor);
    for (int j = 0; j <= kMinor; ++j) {
      const float theta = 2.0f * kPi * float(j) / float(kMinor);
      const Frame base = frameOf(-1, phi, theta);
      const glm::vec3 dtheta = surface(-1, phi, theta + 1e-3f) - surface(-1, phi, theta - 1e-3f);
      const float w = glm::dot(glm::cross(base.normal, base.tangent), dtheta) > 0.0f ? 1.0f : -1.0f;
      m.positions.push_back(base.position);
      m.normals.push_back(base.normal);
      m.tangents.emplace_back(base.tangent, w);
      m.uv0.emplace_back(float(i) / float(kMajor), float(j) / float(kMinor));
      for (int k = 0; k < 2; ++k) {
        const Frame f = frameOf(k, phi, theta);
        m.targets[size_t(k)].positions.push_back(f.position - base.position);
        m.targets[size_t(k)].normals.push_back(f.normal - base.normal);
        m.targets[size_t(k)].tangents.push_back(f.tangent - base.tangent);
      }
    }
  }
  for (int i = 0; i < kMajor; ++i)
    for (int j = 0; j < kMinor; ++j) {
      const uint32_t a = uint32_t(i * (kMinor + 1) + j), c = a + kMinor + 1;
      m.indices.insert(m.indices.end(), {a, c, c + 1, a, c + 1, a + 1});
    }
  m.targetWeights = {0.0f, 0.0f};
  MaterialDesc mat;
  mat.name = "morph_torus";
  mat.baseColor = glm::vec4(0.35f, 0.6f, 0.8f, 1.0f);
  mat.roughness = 0.35f;
  mat.normalTexture = b.addTexturePng("morph_bumps", 128, 128, bumpNormalMap(128, 6, 3, 0.08f));
  const int mesh = b.addMesh("morph_torus", m, b.addMaterial(mat));
  const int node = b.addNode("morph_torus", glm::vec3(0.0f), glm::angleAxis(0.6f, glm::vec3(1, 0, 0)));
  b.setMesh(node, mesh);
  b.addRoot(node);
  const int anim = b.addAnimation("morph");
  b.addChannel(anim, node, "weights", {0.0f, 1.0f, 2.0f, 3.0f}, {0, 0, 1, 0, 1, 1, 0, 1});
}

}  // namespace mb
