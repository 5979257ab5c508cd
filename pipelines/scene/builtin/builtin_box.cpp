// "textured_box": a unit box with per-face axis-aligned tangent frames, a marked checker base
// colour and a bump normal map.
#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

int addTexturedBoxMesh(GlbBuilder& b) {
  // (N, T) per face; B = cross(N, T) (w = +1). -Z and -Y are 180-degree turns of (X, Y, Z).
  const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  const glm::vec3 faces[6][2] = {{Z, X}, {-Z, -X}, {X, -Z}, {-X, Z}, {Y, X}, {-Y, -X}};
  MeshData m;
  for (const auto& f : faces) {
    glm::vec3 n = f[0], t = f[1], bt = glm::cross(n, t);
    uint32_t base = uint32_t(m.positions.size());
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& uv : uvs) {  // u grows along T, v along B
      m.positions.push_back(0.5f * n + (uv.x - 0.5f) * t + (uv.y - 0.5f) * bt);
      m.normals.push_back(n);
      m.tangents.emplace_back(t, 1.0f);
      m.uv0.push_back(uv);
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  MaterialDesc mat;
  mat.name = "box";
  mat.roughness = 0.6f;
  mat.baseColorTexture = b.addTexturePng("box_checker", 128, 128,
                                         markedChecker(128, 4, {235, 235, 225}, {60, 90, 160}));
  mat.normalTexture = b.addTexturePng("box_bumps", 128, 128, bumpNormalMap(128, 2, 3, 0.1f));
  return b.addMesh("box", m, b.addMaterial(mat));
}

void buildTexturedBox(GlbBuilder& b) {
  int node = b.addNode("box", glm::vec3(0.0f), glm::normalize(glm::quat(0.92f, 0.2f, 0.3f, 0.1f)));
  b.setMesh(node, addTexturedBoxMesh(b));
  b.addRoot(node);
}

}  // namespace mb
