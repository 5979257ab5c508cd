#include "pipelines/matrix/matrix_c_vertices.h"

#include "pipelines/compact/compact_encoding.h"
#include "pipelines/gl/frame_vertices.h"

namespace mb::affine {

std::vector<uint8_t> interleaveCompact(const Primitive& p) {
  const compact::PositionCube cube = compact::positionCube(p.positions);
  return gl::interleave<uint8_t>(p, compact::kVertexBytes, [&](auto& out, size_t v) {
    const gl::VertexFrame f = gl::vertexFrame(p, v);
    compact::appendVertex(out, p.positions[v], cube, compact::encodeMatrixFrame(f.normal, f.tangent), gl::vertexUv(p, v));
  });
}

}  // namespace mb::affine
