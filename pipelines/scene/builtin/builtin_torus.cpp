// "normal_torus": a normal-mapped torus around +Y whose second half has mirrored u (so its
// tangents have w = -1), with analytic TANGENT and a procedural normal map.
// "dense_torus": the same torus with 256 x 192 segments (49,794 vertices): a rigid,
// normal-mapped, vertex-bound scene (>= 10 vertices per pixel at a 64x64 viewport) for the
// speed claim, beside the skinned crowd.
#include <cmath>

#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {
namespace {

constexpr float kR = 1.0f, kr = 0.35f;

// One half of the torus: phi in [phi0, phi0 + pi]; u runs 0 -> 1 (mirrored: 1 -> 0).
// kMajor / kMinor: segments around the ring / around the tube.
void addHalf(MeshData& m, float phi0, bool mirrored, int kMajor, int kMinor) {
  uint32_t base = uint32_t(m.positions.size());
  for (int i = 0; i <= kMajor / 2; ++i) {
    float phi = phi0 + kPi * float(i) / float(kMajor / 2);
    float u = float(i) / float(kMajor / 2);
    for (int j = 0; j <= kMinor; ++j) {
      float theta = 2.0f * kPi * float(j) / float(kMinor);
      float ring = kR + kr * std::cos(theta);
      // z = -ring sin(phi) makes (dP/du, dP/dv, N) right-handed on the unmirrored half.
      glm::vec3 p(ring * std::cos(phi), kr * std::sin(theta), -ring * std::sin(phi));
      glm::vec3 n(std::cos(theta) * std::cos(phi), std::sin(theta), -std::cos(theta) * std::sin(phi));
      glm::vec3 dPdphi = glm::normalize(glm::vec3(-std::sin(phi), 0.0f, -std::cos(phi)));
      glm::vec3 dPdtheta(-std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      glm::vec3 t = mirrored ? -dPdphi : dPdphi;  // tangent = direction of increasing u
      float w = glm::dot(glm::cross(n, t), dPdtheta) > 0.0f ? 1.0f : -1.0f;  // v grows with theta
      m.positions.push_back(p);
      m.normals.push_back(n);
      m.tangents.emplace_back(t, w);
      m.uv0.emplace_back(mirrored ? 1.0f - u : u, float(j) / float(kMinor));
    }
  }
  for (int i = 0; i < kMajor / 2; ++i)
    for (int j = 0; j < kMinor; ++j) {
      uint32_t a = base + uint32_t(i * (kMinor + 1) + j), b = a + kMinor + 1;
      m.indices.insert(m.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
}

void buildTorus(GlbBuilder& b, int major, int minor) {
  MeshData m;
  addHalf(m, 0.0f, false, major, minor);
  addHalf(m, kPi, true, major, minor);
  int normalTex = b.addTexturePng("torus_bumps", 128, 128, bumpNormalMap(128, 4, 4, 0.08f));
  MaterialDesc mat;
  mat.name = "torus";
  mat.baseColor = glm::vec4(0.8f, 0.55f, 0.3f, 1.0f);
  mat.roughness = 0.4f;
  mat.normalTexture = normalTex;
  int mesh = b.addMesh("torus", m, b.addMaterial(mat));
  int node = b.addNode("torus", glm::vec3(0.0f), glm::angleAxis(0.5f, glm::vec3(1, 0, 0)));
  b.setMesh(node, mesh);
  b.addRoot(node);
}

}  // namespace

void buildNormalTorus(GlbBuilder& b) { buildTorus(b, 64, 32); }
void buildDenseTorus(GlbBuilder& b) { buildTorus(b, 256, 192); }

}  // namespace mb
