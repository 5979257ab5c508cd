#include "pipelines/gl/frame_vertices.h"

#include <cmath>
#include <utility>

namespace mb::gl {

VertexFormat floatFrameFormat(const Primitive& p) {
  const bool tangent = !p.tangents.empty();
  std::vector<PackedAttribute> attributes{{0, 3}, {1, 3}};
  if (tangent) attributes.push_back({2, 4});
  attributes.push_back({3, 2});
  std::vector<float> data = interleave<float>(p, tangent ? 12 : 8, [&](auto& out, size_t v) {
    const glm::vec3 n = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1);
    const glm::vec3& x = p.positions[v];
    out.insert(out.end(), {x.x, x.y, x.z, n.x, n.y, n.z});
    if (tangent) {
      // One entry per vertex when present (scene.h contract); +X if a caller broke it.
      const glm::vec4 t = v < p.tangents.size() ? p.tangents[v] : glm::vec4(1, 0, 0, 1);
      out.insert(out.end(), {t.x, t.y, t.z, t.w});
    }
    const glm::vec2 uv = vertexUv(p, v);
    out.insert(out.end(), {uv.x, uv.y});
  });
  return VertexFormat{std::move(data), attributes, tangent ? 0 : 1};
}

VertexFrame vertexFrame(const Primitive& p, size_t v) {
  VertexFrame f;
  f.normal = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1);
  if (v < p.tangents.size()) {
    f.tangent = p.tangents[v];
    return f;
  }
  const glm::vec3 axis = std::fabs(f.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 c = glm::cross(f.normal, axis);
  const float len = glm::length(c);
  f.tangent = glm::vec4(len > 0.0f ? c / len : glm::vec3(1, 0, 0), 1.0f);
  return f;
}

}  // namespace mb::gl
