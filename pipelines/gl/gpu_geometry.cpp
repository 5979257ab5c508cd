#include "pipelines/gl/gpu_geometry.h"

#include <string>

#include "pipelines/gl/upload.h"

namespace mb::gl {

uint64_t GpuPrimitive::drawRange(GLsizei first, GLsizei count) const {
  glBindVertexArray(vao);
  extra.setDefaults();
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(uintptr_t(first) * sizeof(uint32_t)));
  return uint64_t(vertexCount);
}

uint64_t GpuPrimitive::drawInstanced(GLsizei instances) const {
  glBindVertexArray(vao);
  extra.setDefaults();
  glDrawElementsInstanced(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr, instances);
  return uint64_t(vertexCount) * uint64_t(instances);
}

void GpuPrimitive::release() {
  extra.release();
  if (vertices) glDeleteBuffers(1, &vertices);
  if (indices) glDeleteBuffers(1, &indices);
  if (vao) glDeleteVertexArrays(1, &vao);
  vao = vertices = indices = 0;
}

void pointAttributes(const std::vector<PackedAttribute>& attributes, bool instanced) {
  GLsizei stride = 0;
  for (const PackedAttribute& a : attributes) stride += GLsizei(a.bytes());
  size_t offset = 0;
  for (const PackedAttribute& a : attributes) {
    glEnableVertexAttribArray(a.location);
    glVertexAttribPointer(a.location, a.size, a.type, a.normalized ? GL_TRUE : GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset));
    if (instanced) glVertexAttribDivisor(a.location, 1);
    offset += a.bytes();
  }
}

bool normalMapped(const Scene& scene, const Primitive& p) {
  return p.material >= 0 && size_t(p.material) < scene.materials.size() &&
         scene.materials[size_t(p.material)].normal.texture >= 0;
}

void SceneGeometry::upload(const Scene& scene, const Format& format, PipelineStats& stats) {
  uploadEach(scene, stats, [&](const Primitive& p, GpuPrimitive& g) {
    VertexFormat f = format(p);
    g.variant = f.variant;
    g.vertices = createBuffer(GL_ARRAY_BUFFER, f.data, stats.vertexBytes);
    pointAttributes(f.attributes);
  });
}

void SceneGeometry::uploadPacked(const Scene& scene, const PackedInterleave& interleave,
                                 const std::vector<PackedAttribute>& attributes, PipelineStats& stats) {
  uploadEach(scene, stats, [&](const Primitive& p, GpuPrimitive& g) {
    g.vertices = createBuffer(GL_ARRAY_BUFFER, interleave(p), stats.vertexBytes);
    pointAttributes(attributes);
  });
}

void SceneGeometry::uploadEach(const Scene& scene, PipelineStats& stats, const Vertices& vertices) {
  release();
  // A mesh is drawn skinned when some node instancing it has a skin.
  std::vector<bool> skinnedMesh(scene.meshes.size(), false);
  for (const Node& n : scene.nodes)
    if (n.mesh >= 0 && size_t(n.mesh) < scene.meshes.size() && n.skin >= 0)
      skinnedMesh[size_t(n.mesh)] = true;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    meshes_.emplace_back();
    for (const Primitive& p : scene.meshes[m].primitives) {
      GpuPrimitive g;
      glGenVertexArrays(1, &g.vao);
      glBindVertexArray(g.vao);
      const uint64_t before = stats.vertexBytes;
      vertices(p, g);
      if (normalMapped(scene, p)) {  // the normal-mapped share
        stats.normalMappedVertexBytes += stats.vertexBytes - before;
        stats.normalMappedVertices += p.positions.size();
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

void SceneGeometry::release() {
  for (auto& mesh : meshes_)
    for (GpuPrimitive& g : mesh) g.release();
  meshes_.clear();
}

void PaletteBuffers::upload(size_t i, const void* data, size_t bytes, uint64_t& counter) {
  while (ids_.size() <= i) {
    GLuint b = 0;
    glGenBuffers(1, &b);
    ids_.push_back(b);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, ids_[i]);
  bufferData(GL_SHADER_STORAGE_BUFFER, bytes, bytes ? data : nullptr, GL_STREAM_DRAW, counter);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void PaletteBuffers::release() {
  if (!ids_.empty()) glDeleteBuffers(GLsizei(ids_.size()), ids_.data());
  ids_.clear();
}

Status checkPaletteSize(const Scene& scene, size_t bytesPerJoint) {
  GLint maxBlock = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  for (const Skin& s : scene.skins)
    if (s.joints.size() * bytesPerJoint > size_t(maxBlock))
      return Status::fail(scene.source + ": skin '" + s.name + "' has " +
                          std::to_string(s.joints.size()) + " joints; the joint palette exceeds "
                          "GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" + std::to_string(maxBlock) + ")");
  return {};
}

void beginDraws() { glEnable(GL_DEPTH_TEST); }  // GL_LESS, GL's default depth function

void endDraws() {
  glBindVertexArray(0);
  setWinding(false);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

double floatsPer(uint64_t bytes, uint64_t count) {
  return count ? double(bytes) / double(sizeof(float)) / double(count) : 0.0;
}

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace mb::gl
