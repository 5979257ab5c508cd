// SceneGeometry::uploadPacked: gpu_geometry.cpp's upload for byte-interleaved vertices of
// mixed component types (the quantized-frame pipelines).
#include <string>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/upload.h"

namespace mb::gl {

void SceneGeometry::uploadPacked(const Scene& scene, const PackedInterleave& interleave,
                                 const std::vector<PackedAttribute>& attributes,
                                 PipelineStats& stats) {
  release();
  // A mesh is drawn skinned when some node instancing it has a skin.
  std::vector<bool> skinnedMesh(scene.meshes.size(), false);
  for (const Node& n : scene.nodes)
    if (n.mesh >= 0 && size_t(n.mesh) < scene.meshes.size() && n.skin >= 0)
      skinnedMesh[size_t(n.mesh)] = true;
  GLsizei stride = 0;
  for (const PackedAttribute& a : attributes) stride += GLsizei(a.bytes());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    meshes_.emplace_back();
    for (const Primitive& p : scene.meshes[m].primitives) {
      GpuPrimitive g;
      glGenVertexArrays(1, &g.vao);
      glBindVertexArray(g.vao);
      const uint64_t before = stats.vertexBytes;
      g.vertices = createBuffer(GL_ARRAY_BUFFER, interleave(p), stats.vertexBytes);
      countNormalMappedShare(scene, p, stats.vertexBytes - before, stats);
      GLuint loc = 0;
      size_t offset = 0;
      for (const PackedAttribute& a : attributes) {
        glEnableVertexAttribArray(loc);
        glVertexAttribPointer(loc++, a.size, a.type, a.normalized ? GL_TRUE : GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset));
        offset += a.bytes();
      }
      g.extra.upload(p, stats.extraVertexBytes, stats.skinVertexBytes);
      g.skinned = skinnedMesh[m] && g.extra.joints != 0;
      g.indices = createBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices, stats.indexBytes);
      g.indexCount = GLsizei(p.indices.size());
      glBindVertexArray(0);
      stats.vertices += p.positions.size();
      g.vertexCount = GLsizei(p.positions.size());
      meshes_.back().push_back(g);
    }
  }
  stats.floatsPerVertex = floatsPer(stats.vertexBytes, stats.vertices);
}

}  // namespace mb::gl
