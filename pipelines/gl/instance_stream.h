// Instanced draws (Node::instances: EXT_mesh_gpu_instancing or --instances). Each pipeline
// writes per instance what its per-draw uniforms hold for a node (the node's world composed
// with the instance's TRS on the CPU, in the pipeline's own form), so an instanced vertex runs
// the same transform as a non-instanced one; the vertex shaders' MB_INSTANCED variant reads it
// as attributes with divisor 1 from kInstanceLocation on. The frame's instances of every node
// go into one vertex buffer, streamed once per frame and counted (PipelineStats::instanceBytes,
// instances). A node's instances are grouped by a pipeline-defined key (mirrored winding, scale
// fallback): one instanced draw per group.
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/pipeline.h"

namespace mb::gl {

constexpr GLuint kInstanceLocation = 8;  // after the vertex streams (locations 0..7)
constexpr int kInstanceKeys = 4;         // keys 0..3

// Whether any node of `scene` is drawn instanced (pipelines build their MB_INSTANCED programs
// only then).
bool hasInstances(const Scene& scene);

struct InstanceGroup {
  int key = 0;
  size_t offset = 0;  // bytes into the frame's buffer
  GLsizei count = 0;  // instances
};

// Per-instance attribute layout: the component count of each location from kInstanceLocation
// (a mat4 is four locations of 4).
using InstanceLayout = std::vector<GLint>;

class InstanceStream {
public:
  InstanceStream() = default;
  ~InstanceStream() { release(); }
  InstanceStream(const InstanceStream&) = delete;
  InstanceStream& operator=(const InstanceStream&) = delete;

  // Starts a frame for a scene of `nodes` nodes: last frame's groups are forgotten.
  void begin(size_t nodes);
  // Node `node`'s `count` instances: write(i, out) appends instance i's floats to `out` and
  // returns its key (0..kInstanceKeys-1). Instances of one key stay in instance order.
  template <class Write>
  void addNode(int node, size_t count, Write write) {
    for (auto& k : byKey_) k.clear();
    size_t counts[kInstanceKeys] = {};
    for (size_t i = 0; i < count; ++i) {
      scratch_.clear();
      const int key = write(i, scratch_);
      byKey_[size_t(key)].insert(byKey_[size_t(key)].end(), scratch_.begin(), scratch_.end());
      ++counts[key];
    }
    flush(node, counts);
  }
  // Uploads the frame's instances: stats.instanceBytes (bytes handed to GL), stats.instances.
  void upload(PipelineStats& stats);
  // The groups of node `node` this frame (empty: the node is not instanced).
  const std::vector<InstanceGroup>& groups(int node) const;
  // Draws `g`'s instances of primitive `p` with the per-instance attributes in `layout`;
  // returns the vertices drawn (p's vertices x instances).
  uint64_t draw(const GpuPrimitive& p, const InstanceGroup& g, const InstanceLayout& layout) const;
  void release();

private:
  void flush(int node, const size_t* counts);

  GLuint buffer_ = 0;
  std::vector<float> staging_, scratch_;
  std::vector<float> byKey_[kInstanceKeys];
  std::vector<std::vector<InstanceGroup>> groups_;  // per node
  uint64_t instances_ = 0;
};

}  // namespace mb::gl
