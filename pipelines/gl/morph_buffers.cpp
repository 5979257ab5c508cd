#include "pipelines/gl/morph_buffers.h"

#include <algorithm>
#include <utility>

#include "pipelines/gl/upload.h"

namespace mb::gl {

std::vector<float> packFrameDeltas(const Primitive& p, MorphLayout& layout) {
  bool normals = false, tangents = false;
  for (const MorphTarget& t : p.targets) {
    normals |= !t.normals.empty();
    tangents |= !t.tangents.empty() && !p.tangents.empty();
  }
  layout = MorphLayout{};
  if (normals) layout.normalOffset = std::exchange(layout.stride, layout.stride + 3);
  if (tangents) layout.tangentOffset = std::exchange(layout.stride, layout.stride + 3);
  const size_t nv = p.positions.size(), stride = size_t(layout.stride);
  std::vector<float> out(p.targets.size() * nv * stride, 0.0f);
  auto put = [&](size_t t, const std::vector<glm::vec3>& deltas, int offset) {
    for (size_t v = 0; v < deltas.size() && v < nv; ++v)
      for (int c = 0; c < 3; ++c) out[(t * nv + v) * stride + size_t(offset + c)] = deltas[v][c];
  };
  for (size_t t = 0; t < p.targets.size(); ++t) {
    put(t, p.targets[t].positions, 0);
    if (normals) put(t, p.targets[t].normals, layout.normalOffset);
    if (tangents) put(t, p.targets[t].tangents, layout.tangentOffset);
  }
  return out;
}

int maxMorphTargets(const Scene& scene) {
  size_t most = 0;
  for (const Mesh& m : scene.meshes) most = std::max(most, morphTargetCount(m));
  return int(most);
}

Defines morphDefines(const Scene& scene) {
  return {{"MB_MORPH", ""}, {"MB_MORPH_TARGETS", std::to_string(std::max(1, maxMorphTargets(scene)))}};
}

void MorphBuffers::upload(const Scene& scene, const MorphPacker& pack, PipelineStats& stats) {
  release();
  for (const Mesh& m : scene.meshes) {
    entries_.emplace_back();
    for (const Primitive& p : m.primitives) {
      Entry e;
      if (!p.targets.empty() && !p.positions.empty()) {
        std::vector<float> data = pack(p, e.layout);
        e.buffer = createBuffer(GL_SHADER_STORAGE_BUFFER, data, stats.morphBytes);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
        e.targets = int(p.targets.size());
        e.vertices = int(p.positions.size());
        stats.morphTargetVertices += uint64_t(e.targets) * uint64_t(e.vertices);
      }
      entries_.back().push_back(e);
    }
  }
  weights_.assign(scene.nodes.size(), {});
}

void MorphBuffers::update(const Scene& scene, const AnimState& state) {
  weights_ = sampleMorphWeights(scene, state);
}

bool MorphBuffers::active(const DrawItem& d) const {
  if (size_t(d.mesh) >= entries_.size() || size_t(d.primitive) >= entries_[size_t(d.mesh)].size()) return false;
  if (!entries_[size_t(d.mesh)][size_t(d.primitive)].buffer || size_t(d.node) >= weights_.size()) return false;
  const std::vector<float>& w = weights_[size_t(d.node)];
  return std::any_of(w.begin(), w.end(), [](float x) { return x != 0.0f; });
}

void MorphBuffers::bind(const Program& program, const DrawItem& d, uint64_t& uniformBytes) const {
  const Entry& e = entries_[size_t(d.mesh)][size_t(d.primitive)];
  const std::vector<float>& w = weights_[size_t(d.node)];
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMorphBinding, e.buffer);
  uniform1i(program.uniform("u_MorphTargetCount"), std::min(e.targets, int(w.size())), uniformBytes);
  uniform1i(program.uniform("u_MorphVertices"), e.vertices, uniformBytes);
  uniform1i(program.uniform("u_MorphStride"), e.layout.stride, uniformBytes);
  uniform1i(program.uniform("u_MorphNormal"), e.layout.normalOffset, uniformBytes);
  uniform1i(program.uniform("u_MorphTangent"), e.layout.tangentOffset, uniformBytes);
  uniform1fv(program.uniform("u_MorphWeights[0]"), int(w.size()), w.data(), uniformBytes);
}

void MorphBuffers::release() {
  for (auto& mesh : entries_)
    for (Entry& e : mesh)
      if (e.buffer) glDeleteBuffers(1, &e.buffer);
  entries_.clear();
  weights_.clear();
}

}  // namespace mb::gl
