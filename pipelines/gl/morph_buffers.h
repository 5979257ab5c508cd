// Morph targets on the GPU, shared by every glTF pipeline: each primitive with
// targets gets one shader storage buffer of deltas, read in the vertex shader by gl_VertexID
// (shaders/morph.glsl), and each draw the node's weights as a uniform float array.
//
// Why a storage buffer and not vertex attributes: glTF puts no bound on the target count (the
// corpus has meshes with dozens, faces with hundreds) while a vertex shader has 16 attribute
// slots, most of them taken by the vertex itself; the Sample Viewer and three.js read targets
// from a texture by vertex index for the same reason. Zero weights are skipped per target, so
// a mesh at rest reads no deltas.
//
// Layout of a primitive's buffer: float[targets][vertices][stride]; each pipeline chooses what
// a vertex's `stride` floats per target are (its own frame form) through a MorphPacker, and
// where the normal-like and tangent-like parts start (0: absent).
#pragma once
#include <functional>
#include <vector>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/pipeline.h"

namespace mb::gl {

constexpr GLuint kMorphBinding = 2;  // storage block MorphDeltas (0, 1: joint palettes)

struct MorphLayout {
  int stride = 3;         // floats per vertex per target; the position delta is at 0
  int normalOffset = 0;   // first float of the normal (or frame) delta; 0: none
  int tangentOffset = 0;  // first float of the tangent delta; 0: none
};

// A pipeline's deltas for primitive p: target-major, `layout.stride` floats per vertex.
using MorphPacker = std::function<std::vector<float>(const Primitive& p, MorphLayout& layout)>;

// The glTF deltas as they are: position, then normal (when any target has one), then tangent
// xyz (when any target has one and p has tangents), zeros where a target lacks a stream.
std::vector<float> packFrameDeltas(const Primitive& p, MorphLayout& layout);

// The most targets any mesh of `scene` has (the shaders' MB_MORPH_TARGETS); 0: no morphing.
int maxMorphTargets(const Scene& scene);

class MorphBuffers {
public:
  // Uploads every primitive's deltas packed by `pack`; bytes to stats.morphBytes and
  // targets x vertices to stats.morphTargetVertices.
  void upload(const Scene& scene, const MorphPacker& pack, PipelineStats& stats);
  // Samples every node's weights for `state` (sampleMorphWeights).
  void update(const Scene& scene, const AnimState& state);
  // True when draw d morphs: its primitive has deltas and its node a non-zero weight.
  bool active(const DrawItem& d) const;
  // Binds d's deltas and sets the MB_MORPH uniforms of `program` (counted in `uniformBytes`).
  void bind(const Program& program, const DrawItem& d, uint64_t& uniformBytes) const;
  void release();

private:
  struct Entry {
    GLuint buffer = 0;
    int targets = 0, vertices = 0;
    MorphLayout layout;
  };
  std::vector<std::vector<Entry>> entries_;  // [mesh][primitive]
  std::vector<std::vector<float>> weights_;  // per node
};

// The defines of a morphing program variant: MB_MORPH and MB_MORPH_TARGETS.
Defines morphDefines(const Scene& scene);

}  // namespace mb::gl
