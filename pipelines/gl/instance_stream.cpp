#include "pipelines/gl/instance_stream.h"

#include <numeric>

#include "pipelines/gl/upload.h"

namespace mb::gl {

bool hasInstances(const Scene& scene) {
  for (const Node& n : scene.nodes)
    if (!n.instances.empty()) return true;
  return false;
}

void InstanceStream::begin(size_t nodes) {
  staging_.clear();
  for (auto& g : groups_) g.clear();
  groups_.resize(nodes);
  instances_ = 0;
}

void InstanceStream::flush(int node, const size_t* counts) {
  for (int key = 0; key < kInstanceKeys; ++key) {
    if (!counts[key]) continue;
    groups_[size_t(node)].push_back({key, staging_.size() * sizeof(float), GLsizei(counts[key])});
    staging_.insert(staging_.end(), byKey_[key].begin(), byKey_[key].end());
    instances_ += counts[key];
  }
}

void InstanceStream::upload(PipelineStats& stats) {
  stats.instanceBytes = 0;
  stats.instances = instances_;
  if (staging_.empty()) return;
  if (!buffer_) glGenBuffers(1, &buffer_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  bufferData(GL_ARRAY_BUFFER, staging_.size() * sizeof(float), staging_.data(), GL_STREAM_DRAW, stats.instanceBytes);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

const std::vector<InstanceGroup>& InstanceStream::groups(int node) const {
  static const std::vector<InstanceGroup> none;
  return node >= 0 && size_t(node) < groups_.size() ? groups_[size_t(node)] : none;
}

uint64_t InstanceStream::draw(const GpuPrimitive& p, const InstanceGroup& g, const InstanceLayout& layout) const {
  glBindVertexArray(p.vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  const GLsizei stride = GLsizei(std::accumulate(layout.begin(), layout.end(), 0) * sizeof(float));
  size_t offset = g.offset;
  for (size_t k = 0; k < layout.size(); ++k) {
    const GLuint location = kInstanceLocation + GLuint(k);
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, layout[k], GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    glVertexAttribDivisor(location, 1);
    offset += size_t(layout[k]) * sizeof(float);
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const uint64_t vertices = p.drawInstanced(g.count);
  // The VAO is shared with the primitive's non-instanced draws: leave no array enabled there.
  for (size_t k = 0; k < layout.size(); ++k) glDisableVertexAttribArray(kInstanceLocation + GLuint(k));
  return vertices;
}

void InstanceStream::release() {
  if (buffer_) glDeleteBuffers(1, &buffer_);
  buffer_ = 0;
  staging_.clear();
  groups_.clear();
}

}  // namespace mb::gl
