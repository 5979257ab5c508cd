#include "pipelines/matrix/affine_vertices.h"

#include <cmath>

namespace mb::affine {

std::vector<float> interleaveFullFrame(const Primitive& p) {
  std::vector<float> out;
  out.reserve(p.positions.size() * kFloatsPerVertex);
  for (size_t v = 0; v < p.positions.size(); ++v) {
    const glm::vec3 n = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1);
    glm::vec4 t;
    if (v < p.tangents.size()) {
      t = p.tangents[v];
    } else {
      // The motor pipeline's rule too (motor_vertices.cpp), so every pipeline shades one frame.
      const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
      const glm::vec3 perp = glm::cross(n, axis);
      const float len = glm::length(perp);
      t = glm::vec4(len > 0.0f ? perp / len : glm::vec3(1, 0, 0), 1.0f);
    }
    const glm::vec2 uv = v < p.uv0.size() ? p.uv0[v] : glm::vec2(0.0f);
    const glm::vec3& x = p.positions[v];
    out.insert(out.end(), {x.x, x.y, x.z, n.x, n.y, n.z, t.x, t.y, t.z, t.w, uv.x, uv.y});
  }
  return out;
}

}  // namespace mb::affine
