// Bezier patch primitives (Primitive::patchPoints) on the GPU, uploaded and drawn the same way
// by every pipeline, so pipelines differ only in their patch vertex shader's frame transform:
// one refinement-pattern mesh (a uv grid of level N = Scene::patchLevel) shared by all
// patches, each patch primitive's control points in a GL_RGB32F buffer texture (16 texels per
// patch) on texture unit kUnitControlPoints, and one instanced draw per primitive with one
// instance per patch (gl_InstanceID selects the patch's 16 texels).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/pipeline.h"

namespace mb::gl {

constexpr GLuint kUnitControlPoints = kUnitCount;  // 5: after forward.fs's units
constexpr int kMaxPatchLevel = 256;

// The refinement pattern of level n >= 1: (n+1)^2 uv vertices, index i + (n+1) j at
// (i/n, j/n), and 2 n^2 counter-clockwise triangles in (u, v), so that the front face's
// normal is dP/du x dP/dv.
struct RefinementPattern {
  std::vector<glm::vec2> uv;
  std::vector<uint32_t> indices;
};
RefinementPattern refinementPattern(int level);

// Whether any primitive of `scene` is a Bezier patch primitive (pipelines build their patch
// programs only then).
bool hasPatches(const Scene& scene);

class PatchGeometry {
public:
  PatchGeometry() = default;
  ~PatchGeometry() { release(); }
  PatchGeometry(const PatchGeometry&) = delete;
  PatchGeometry& operator=(const PatchGeometry&) = delete;

  // Does nothing for a scene without patch primitives. Otherwise uploads the pattern of
  // scene.patchLevel (uv: stats.vertexBytes and stats.vertices; indices: stats.indexBytes) and
  // every patch primitive's control points (stats.patchBytes). Fails when the level is outside
  // 1..kMaxPatchLevel or a primitive exceeds GL_MAX_TEXTURE_BUFFER_SIZE. Needs a current context.
  Status upload(const Scene& scene, PipelineStats& stats);
  // Whether draw `d` is a patch primitive.
  bool has(const DrawItem& d) const;
  // Binds the pattern and the primitive's control points and draws all its patches. The
  // caller's patch program must be in use with its uniforms set. Returns the vertices drawn.
  uint64_t draw(const DrawItem& d) const;
  void release();

private:
  struct Patches {
    GLuint buffer = 0, texture = 0;
    GLsizei count = 0;  // patches
  };
  std::vector<std::vector<Patches>> meshes_;  // [mesh][primitive]; count 0 = not patches
  GLuint vao_ = 0, uv_ = 0, indices_ = 0;
  GLsizei indexCount_ = 0;
  GLsizei patternVertices_ = 0;  // (level + 1)^2
};

}  // namespace mb::gl
