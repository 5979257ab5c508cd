// GPU plumbing every pipeline needs the same way, so pipelines differ only in what they
// convert and how their vertex shaders transform: a primitive's buffers (the pipeline's
// interleaved float vertices + the shared optional streams + indices), the joint palette
// storage buffers, frame begin/end GL state, and the stats arithmetic.
#pragma once
#include <chrono>
#include <functional>
#include <vector>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/packed_vertices.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/pipeline.h"

namespace mb::gl {

struct GpuPrimitive {
  GLuint vao = 0, vertices = 0, indices = 0;
  GLsizei indexCount = 0;
  bool skinned = false;  // drawn by a skinned node and has joints + weights
  int variant = 0;       // the pipeline's vertex-format variant (VertexFormat::variant)
  GLsizei vertexCount = 0;  // vertices uploaded (PipelineStats::drawnVertices per draw)
  ExtraStreams extra;
  // Binds the VAO, sets the defaults of absent streams, draws the triangles; returns the
  // vertices drawn.
  uint64_t draw() const { return drawRange(0, indexCount); }
  // The same for `count` indices from `first` (motor_cf's two ranges); returns the vertices the
  // range references at most (vertexCount: the primitive's, a range shares its vertices).
  uint64_t drawRange(GLsizei first, GLsizei count) const;
  // The same, `instances` times (the caller has set the per-instance attributes).
  uint64_t drawInstanced(GLsizei instances) const;
  void release();
};

// A primitive's vertex format when it may differ per primitive (e.g. the matrix pipeline
// uploads a tangent only where the glTF-Sample-Viewer would): the interleaved floats, the
// attributes in interleave order, and a pipeline-defined variant number kept on GpuPrimitive
// so the pipeline can pick the matching program.
struct VertexFormat {
  std::vector<float> data;
  std::vector<PackedAttribute> attributes;  // GL_FLOAT ones
  int variant = 0;
};

// Every primitive of every mesh on the GPU.
class SceneGeometry {
public:
  // Uploads all primitives of `scene`: format(p)'s tightly interleaved floats at its attributes
  // (stats.vertexBytes), ExtraStreams (extraVertexBytes, skinVertexBytes), indices (indexBytes);
  // counts stats.vertices and sets stats.floatsPerVertex from the bytes. Also counts the
  // normal-mapped share (PipelineStats::normalMappedVertexBytes/Vertices).
  using Format = std::function<VertexFormat(const Primitive&)>;
  void upload(const Scene& scene, const Format& format, PipelineStats& stats);
  // The same for a vertex layout of mixed component types (pipelines/gl/packed_vertices.h):
  // interleave(p) returns the bytes of p's vertices, `attributes` their formats in order. Both
  // uploads ask for the primitives once each, mesh by mesh, in order.
  using PackedInterleave = std::function<std::vector<uint8_t>(const Primitive&)>;
  void uploadPacked(const Scene& scene, const PackedInterleave& interleave,
                    const std::vector<PackedAttribute>& attributes, PipelineStats& stats);
  // The same for an interleave that counts its frames: stats.zeroScalarFrames, biasedFrames.
  void uploadPacked(const Scene& scene, PackedStream (*interleave)(const Primitive&),
                    const std::vector<PackedAttribute>& attributes, PipelineStats& stats) {
    auto bytes = [&](const Primitive& p) {
      PackedStream s = interleave(p);
      stats.zeroScalarFrames += s.zeroScalarFrames;
      stats.biasedFrames += s.biasedFrames;
      return std::move(s.bytes);
    };
    uploadPacked(scene, PackedInterleave(bytes), attributes, stats);
  }
  const GpuPrimitive& at(const DrawItem& d) const { return meshes_[size_t(d.mesh)][size_t(d.primitive)]; }
  void release();

private:
  // Both uploads: per primitive of every mesh a bound vertex array for vertices(p, g) to give its
  // vertex buffer and attributes (the bytes counted in stats.vertexBytes), then the normal-mapped
  // share, ExtraStreams, indices and counts.
  using Vertices = std::function<void(const Primitive&, GpuPrimitive&)>;
  void uploadEach(const Scene& scene, PipelineStats& stats, const Vertices& vertices);

  std::vector<std::vector<GpuPrimitive>> meshes_;  // [mesh][primitive]
};

// Points the bound vertex array's attributes at the bound GL_ARRAY_BUFFER's `attributes`,
// tightly interleaved in that order; read per instance (divisor 1) when `instanced`.
void pointAttributes(const std::vector<PackedAttribute>& attributes, bool instanced = false);

// True when `p`'s material has a normal texture (the paper's 12-vs-9-float case; the split of
// PipelineStats::normalMappedVertexBytes).
bool normalMapped(const Scene& scene, const Primitive& p);

// One shader storage buffer per joint palette, re-uploaded every frame.
class PaletteBuffers {
public:
  // Uploads palette `i` (growing the set as needed); bytes are added to `counter`.
  void upload(size_t i, const void* data, size_t bytes, uint64_t& counter);
  GLuint operator[](size_t i) const { return ids_[i]; }
  void release();

private:
  std::vector<GLuint> ids_;
};

// Fails, naming the skin, when a palette of `bytesPerJoint` per joint would not fit in
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE.
Status checkPaletteSize(const Scene& scene, size_t bytesPerJoint);

// GL state around a frame's draws: depth test on before; after, the defaults restored
// (CCW winding, depth writes on, no blending, no VAO).
void beginDraws();
void endDraws();

// bytes / 4 / count, or 0 when count is 0 (the "floats per X" stats).
double floatsPer(uint64_t bytes, uint64_t count);

// Milliseconds since `t0` (the conversion / update timers of PipelineStats).
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0);

}  // namespace mb::gl
