// SceneGeometry::uploadPacked: gpu_geometry.cpp's upload for byte-interleaved vertices of
// mixed component types (the quantized-frame pipelines).
#include <string>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/upload.h"

namespace mb::gl {

void SceneGeometry::uploadPacked(const Scene& scene, const PackedInterleave& interleave,
                                 const std::vector<PackedAttribute>& attributes,
                                 PipelineStats& stats) {
  GLsizei stride = 0;
  for (const PackedAttribute& a : attributes) stride += GLsizei(a.bytes());
  uploadEach(scene, stats, [&](const Primitive& p, GpuPrimitive& g) {
    g.vertices = createBuffer(GL_ARRAY_BUFFER, interleave(p), stats.vertexBytes);
    GLuint loc = 0;
    size_t offset = 0;
    for (const PackedAttribute& a : attributes) {
      glEnableVertexAttribArray(loc);
      glVertexAttribPointer(loc++, a.size, a.type, a.normalized ? GL_TRUE : GL_FALSE, stride,
                            reinterpret_cast<const void*>(offset));
      offset += a.bytes();
    }
  });
}

}  // namespace mb::gl
