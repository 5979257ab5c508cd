#include "pipelines/matrix/affine_vertices.h"

#include "pipelines/gl/frame_vertices.h"

namespace mb::affine {

std::vector<float> interleaveFullFrame(const Primitive& p) {
  std::vector<float> out;
  out.reserve(p.positions.size() * kFloatsPerVertex);
  for (size_t v = 0; v < p.positions.size(); ++v) {
    const auto [n, t] = gl::vertexFrame(p, v);
    const glm::vec2 uv = v < p.uv0.size() ? p.uv0[v] : glm::vec2(0.0f);
    const glm::vec3& x = p.positions[v];
    out.insert(out.end(), {x.x, x.y, x.z, n.x, n.y, n.z, t.x, t.y, t.z, t.w, uv.x, uv.y});
  }
  return out;
}

}  // namespace mb::affine
