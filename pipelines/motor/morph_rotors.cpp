#include "pipelines/motor/morph_rotors.h"

#include <cmath>

#include "pipelines/gl/frame_vertices.h"
#include "pipelines/motor/companion.h"

namespace mb::motor {

std::vector<float> packRotorDeltas(const Primitive& p, gl::MorphLayout& layout) {
  layout = gl::MorphLayout{7, 3, 0};
  const size_t nv = p.positions.size();
  std::vector<float> out(p.targets.size() * nv * 7, 0.0f);
  for (size_t t = 0; t < p.targets.size(); ++t) {
    const MorphTarget& d = p.targets[t];
    for (size_t v = 0; v < nv; ++v) {
      float* o = &out[(t * nv + v) * 7];
      if (v < d.positions.size()) o[0] = d.positions[v].x, o[1] = d.positions[v].y, o[2] = d.positions[v].z;
      if (d.normals.empty() && d.tangents.empty()) continue;
      const gl::VertexFrame f = gl::vertexFrame(p, v);
      const glm::vec3 n = f.normal + (v < d.normals.size() ? d.normals[v] : glm::vec3(0.0f));
      const glm::vec3 tan = glm::vec3(f.tangent) + (v < d.tangents.size() ? d.tangents[v] : glm::vec3(0.0f));
      const glm::vec4 base = companion::encodeTangentRotor(f.normal, glm::vec3(f.tangent), f.tangent.w).rotor;
      glm::vec4 morphed = companion::encodeTangentRotor(n, tan, f.tangent.w).rotor;
      if (glm::dot(morphed, base) < 0.0f) morphed = -morphed;
      const glm::vec4 delta = morphed - base;
      if (!std::isfinite(delta.x + delta.y + delta.z + delta.w)) continue;  // a degenerate morphed frame: no turn
      for (int c = 0; c < 4; ++c) o[3 + c] = delta[c];
    }
  }
  return out;
}

gl::MorphPacker morphPacker(MorphMethod method) {
  if (method == MorphMethod::Rotor) return packRotorDeltas;  // PipelineDefault: the frame method
  return gl::packFrameDeltas;
}

}  // namespace mb::motor
