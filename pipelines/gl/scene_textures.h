// GPU-side scene helpers shared by every pipeline, so that shading inputs are bound the same
// way whatever the vertex path: scene textures and samplers, the uniforms of forward.fs
// (camera, lights, materials; names documented at the top of shaders/forward.fs), the
// material's GL state (culling, blending), and the draw order.
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/program.h"
#include "pipelines/result.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/scene.h"

namespace mb::gl {

// Texture units of forward.fs.
enum TextureUnit : GLuint {
  kUnitBaseColor = 0, kUnitMetallicRoughness = 1, kUnitNormal = 2, kUnitOcclusion = 3,
  kUnitEmissive = 4, kUnitCount = 5
};

class SceneTextures {
public:
  SceneTextures() = default;
  ~SceneTextures();
  SceneTextures(const SceneTextures&) = delete;
  SceneTextures& operator=(const SceneTextures&) = delete;

  // Uploads the images the materials reference, as RGBA8 with a full mipmap chain: sRGB
  // (GL_SRGB8_ALPHA8) where used as base colour or emissive, linear otherwise (an image used
  // both ways is uploaded twice). Creates one sampler object per Scene::sampler. Adds the
  // level-0 bytes handed to glTexImage2D to `counter`. Needs a current context.
  Status upload(const Scene& scene, uint64_t& counter);

  // Binds `materialIndex` (-1 = glTF default material) for forward.fs: uniforms (counted in
  // `counter`), textures and samplers on units 0..4, and its GL state: back-face culling
  // unless double-sided, blending for BLEND. `program` must be in use.
  void bindMaterial(const Program& program, int materialIndex, uint64_t& counter) const;

  void release();

private:
  GLuint textureFor(int textureIndex, bool srgb) const;
  const Scene* scene_ = nullptr;
  std::vector<GLuint> linear_, srgb_;  // per Scene::images entry; 0 = not uploaded
  std::vector<GLuint> samplers_;       // per Scene::samplers entry
  GLuint defaultSampler_ = 0;
  GLuint white_ = 0;                   // 1x1 white texture for unused units
};

// Per-frame uniforms of forward.fs: camera position and the light rig, which is fixed
// relative to the camera (key light from the upper left, fill from the right) so every
// scene and camera is lit alike. Counted in `counter`. `program` must be in use.
void setFrameUniforms(const Program& program, const View& view, uint64_t& counter);

// Front-face winding for a node: glTF says a negative determinant of the node's world
// transform flips the winding order (mirrored geometry).
void setWinding(bool mirrored);

// One draw: a primitive of a mesh instanced by a node.
struct DrawItem {
  int node = -1, mesh = -1, primitive = -1;
};

// Every (node, primitive) reachable from Scene::roots, depth first in child order, with
// OPAQUE and MASK primitives first and BLEND ones after (each group in traversal order, not
// depth-sorted), so all pipelines draw the same things in the same order.
std::vector<DrawItem> buildDrawList(const Scene& scene);

// Fixed vertex attribute locations of the streams every pipeline uploads the same way.
// Locations 0..3 belong to each pipeline's own vertex layout.
enum SharedAttribute : GLuint { kAttribUv1 = 4, kAttribColor = 5, kAttribJoints = 6,
                                kAttribWeights = 7 };

// A primitive's optional streams: TEXCOORD_1 and COLOR_0 (uploaded only when present) and
// JOINTS_0 (as unsigned ints) / WEIGHTS_0 for skinned primitives.
struct ExtraStreams {
  GLuint uv1 = 0, color = 0, joints = 0, weights = 0;
  // With the primitive's VAO bound: uploads the present streams and enables them at the
  // shared locations. uv1/colour bytes go to `extraBytes`, joints/weights to `skinBytes`.
  void upload(const Primitive& p, uint64_t& extraBytes, uint64_t& skinBytes);
  // Before drawing: constant attribute values for absent streams (uv1 = 0, colour = 1).
  void setDefaults() const;
  void release();
};

}  // namespace mb::gl
