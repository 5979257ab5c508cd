#include "pipelines/gl/patch_geometry.h"

#include <string>

#include "pipelines/gl/upload.h"

namespace mb::gl {

RefinementPattern refinementPattern(int n) {
  RefinementPattern p;
  const uint32_t row = uint32_t(n) + 1;
  p.uv.reserve(size_t(row) * row);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.uv.push_back(glm::vec2(float(i) / float(n), float(j) / float(n)));
  p.indices.reserve(size_t(6) * size_t(n) * size_t(n));
  for (uint32_t j = 0; j < uint32_t(n); ++j)
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
      uint32_t a = i + row * j, b = a + 1, c = a + row + 1, d = a + row;
      p.indices.insert(p.indices.end(), {a, b, c, a, c, d});
    }
  return p;
}

bool hasPatches(const Scene& scene) {
  for (const Mesh& m : scene.meshes)
    for (const Primitive& p : m.primitives)
      if (!p.patchPoints.empty()) return true;
  return false;
}

Status PatchGeometry::upload(const Scene& scene, PipelineStats& stats) {
  release();
  if (!hasPatches(scene)) return {};
  if (scene.patchLevel < 1 || scene.patchLevel > kMaxPatchLevel)
    return Status::fail(scene.source + ": patch level " + std::to_string(scene.patchLevel) + " outside 1.." +
                        std::to_string(kMaxPatchLevel));
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  RefinementPattern pattern = refinementPattern(scene.patchLevel);
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  uv_ = createBuffer(GL_ARRAY_BUFFER, pattern.uv, stats.patchPatternBytes);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  indices_ = createBuffer(GL_ELEMENT_ARRAY_BUFFER, pattern.indices, stats.indexBytes);
  indexCount_ = GLsizei(pattern.indices.size());
  patternVertices_ = GLsizei(pattern.uv.size());
  glBindVertexArray(0);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    meshes_.emplace_back();
    for (size_t i = 0; i < scene.meshes[m].primitives.size(); ++i) {
      const std::vector<glm::vec3>& points = scene.meshes[m].primitives[i].patchPoints;
      Patches p;
      if (!points.empty()) {
        if (points.size() > size_t(maxTexels))
          return Status::fail(scene.source + ": mesh " + std::to_string(m) + " primitive " + std::to_string(i) + ": " +
                              std::to_string(points.size()) + " control points exceed GL_MAX_TEXTURE_BUFFER_SIZE " +
                              std::to_string(maxTexels));
        p.buffer = createBuffer(GL_TEXTURE_BUFFER, points, stats.patchBytes);
        glGenTextures(1, &p.texture);
        glBindTexture(GL_TEXTURE_BUFFER, p.texture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGB32F, p.buffer);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        p.count = GLsizei(points.size() / 16);
      }
      meshes_.back().push_back(p);
    }
  }
  return {};
}

bool PatchGeometry::has(const DrawItem& d) const {
  return size_t(d.mesh) < meshes_.size() && size_t(d.primitive) < meshes_[size_t(d.mesh)].size() &&
         meshes_[size_t(d.mesh)][size_t(d.primitive)].count > 0;
}

uint64_t PatchGeometry::draw(const DrawItem& d) const {
  const Patches& p = meshes_[size_t(d.mesh)][size_t(d.primitive)];
  glBindVertexArray(vao_);
  glActiveTexture(GL_TEXTURE0 + kUnitControlPoints);
  glBindTexture(GL_TEXTURE_BUFFER, p.texture);
  glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, p.count);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glActiveTexture(GL_TEXTURE0);
  return uint64_t(patternVertices_) * uint64_t(p.count);
}

void PatchGeometry::release() {
  for (auto& mesh : meshes_)
    for (Patches& p : mesh) {
      if (p.texture) glDeleteTextures(1, &p.texture);
      if (p.buffer) glDeleteBuffers(1, &p.buffer);
    }
  meshes_.clear();
  if (uv_) glDeleteBuffers(1, &uv_);
  if (indices_) glDeleteBuffers(1, &indices_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  vao_ = uv_ = indices_ = 0;
  indexCount_ = 0;
}

}  // namespace mb::gl
