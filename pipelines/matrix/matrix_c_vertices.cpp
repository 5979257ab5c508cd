#include "pipelines/matrix/matrix_c_vertices.h"

#include "pipelines/matrix/affine_vertices.h"
#include "pipelines/compact/compact_encoding.h"

namespace mb::affine {

std::vector<uint8_t> interleaveCompact(const Primitive& p) {
  const std::vector<float> f = interleaveFullFrame(p);  // pos 3, normal 3, tangent 4, uv 2
  const size_t n = p.positions.size(), stride = size_t(kFloatsPerVertex);
  std::vector<uint32_t> frames(n);
  std::vector<glm::vec2> uv(n);
  for (size_t v = 0; v < n; ++v) {
    const float* x = &f[v * stride];
    frames[v] = compact::encodeMatrixFrame({x[3], x[4], x[5]}, {x[6], x[7], x[8], x[9]});
    uv[v] = {x[10], x[11]};
  }
  return compact::interleave(p.positions, frames, uv, compact::positionCube(p.positions));
}

}  // namespace mb::affine
