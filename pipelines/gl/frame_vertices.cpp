#include "pipelines/gl/frame_vertices.h"

namespace mb::gl {

bool uploadsTangent(const Primitive& p) { return !p.tangents.empty(); }

std::vector<float> interleaveVertices(const Primitive& p) {
  const bool tangent = uploadsTangent(p);
  std::vector<float> out;
  out.reserve(p.positions.size() * size_t(tangent ? kFloatsWithTangent : kFloatsWithoutTangent));
  for (size_t v = 0; v < p.positions.size(); ++v) {
    glm::vec3 n = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1);
    glm::vec2 uv = v < p.uv0.size() ? p.uv0[v] : glm::vec2(0.0f);
    const glm::vec3& x = p.positions[v];
    out.insert(out.end(), {x.x, x.y, x.z, n.x, n.y, n.z});
    if (tangent) {
      // One entry per vertex when present (scene.h contract); +X if a caller broke it.
      const glm::vec4 t = v < p.tangents.size() ? p.tangents[v] : glm::vec4(1, 0, 0, 1);
      out.insert(out.end(), {t.x, t.y, t.z, t.w});
    }
    out.insert(out.end(), {uv.x, uv.y});
  }
  return out;
}

VertexFormat floatFrameFormat(const Primitive& p) {
  const bool tangent = uploadsTangent(p);
  std::vector<VertexAttribute> attributes{{0, 3}, {1, 3}};
  if (tangent) attributes.push_back({2, 4});
  attributes.push_back({3, 2});
  return VertexFormat{interleaveVertices(p), attributes, tangent ? 0 : 1};
}

}  // namespace mb::gl
