// GPU plumbing every pipeline needs the same way, so pipelines differ only in what they
// convert and how their vertex shaders transform: a primitive's buffers (the pipeline's
// interleaved float vertices + the shared optional streams + indices), the joint palette
// storage buffers, frame begin/end GL state, and the stats arithmetic.
#pragma once
#include <chrono>
#include <functional>
#include <initializer_list>
#include <vector>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/pipeline.h"

namespace mb::gl {

struct GpuPrimitive {
  GLuint vao = 0, vertices = 0, indices = 0;
  GLsizei indexCount = 0;
  bool skinned = false;  // drawn by a skinned node and has joints + weights
  ExtraStreams extra;
  // Binds the VAO, sets the defaults of absent streams, draws the triangles.
  void draw() const;
  void release();
};

// Every primitive of every mesh on the GPU.
class SceneGeometry {
public:
  // The pipeline's vertex layout of a primitive: tightly interleaved floats.
  using Interleave = std::function<std::vector<float>(const Primitive&)>;
  // Uploads all primitives of `scene`: interleave(p) at float attributes of the given sizes on
  // locations 0, 1, ... (stats.vertexBytes), ExtraStreams (extraVertexBytes, skinVertexBytes),
  // indices (indexBytes); counts stats.vertices and sets stats.floatsPerVertex from the bytes.
  void upload(const Scene& scene, const Interleave& interleave,
              std::initializer_list<GLint> attributeSizes, PipelineStats& stats);
  const GpuPrimitive& at(const DrawItem& d) const { return meshes_[size_t(d.mesh)][size_t(d.primitive)]; }
  void release();

private:
  std::vector<std::vector<GpuPrimitive>> meshes_;  // [mesh][primitive]
};

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
