// The interface every renderer implements (README.md), and the name -> factory registry. A
// pipeline owns its GPU representation of a Scene. Adding a variant = its class and its registry
// entry (registry.h), one line in registry.cpp.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pipelines/result.h"
#include "pipelines/update_phases.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/scene.h"

namespace mb {

// Measured counters. Byte counts are summed from the sizes actually passed to GL upload
// calls (glBufferData / glBufferSubData / glTexImage / glUniform*), never from constants.
struct PipelineStats {
  uint64_t vertexBytes = 0;        // shading attributes (position, frame, uv)
  uint64_t skinVertexBytes = 0;    // joints + weights attributes
  uint64_t extraVertexBytes = 0;   // optional streams uploaded only when present (uv1, colour)
  uint64_t indexBytes = 0;
  uint64_t textureBytes = 0;
  uint64_t uniformBytesPerFrame = 0;  // per-frame + per-draw uniforms of the last render()
  uint64_t skinBytesPerFrame = 0;     // joint palette of the last update()/render()
  uint64_t patchBytes = 0;            // Bezier patch control points (pipelines/gl/patch_geometry.h)
  uint64_t patchPatternBytes = 0;     // the patches' shared (u, v) refinement pattern: not a
                                      // vertex format, so neither in vertexBytes nor vertices
  uint64_t vertices = 0;              // vertices uploaded
  // Morph targets (pipelines/gl/morph_buffers.h): the delta storage buffers uploaded, and the
  // targets x vertices they hold (morphBytes / morphTargetVertices: bytes per vertex per target).
  uint64_t morphBytes = 0, morphTargetVertices = 0;
  int morphDraws = 0;                 // draws of the last render() that morphed (a non-zero weight)
  // Set by the harness after a render (harness/render/render_frame.cpp), not by the pipeline:
  // the drawn nodes with a non-zero morph weight when the pipeline morphed no draw, i.e. drew
  // them in their base shape (every glTF pipeline morphs: 0 unless one regresses).
  int morphNotDrawnNodes = 0;
  // Instanced draws (Node::instances, pipelines/gl/instance_stream.h): the per-instance
  // transforms of the last render() (each pipeline's per-draw transform, node world composed
  // with the instance on the CPU), streamed once per frame, and how many instances they hold.
  uint64_t instanceBytes = 0, instances = 0;
  // Vertices the last render() drew: each draw's vertices times its instances (patches: the
  // refinement pattern's vertices per patch).
  uint64_t drawnVertices = 0;
  // Of vertexBytes / vertices: the primitives whose material has a normal texture, so that
  // bytes per vertex split normal-mapped / not (the paper's 12-vs-9 floats is the former).
  uint64_t normalMappedVertexBytes = 0, normalMappedVertices = 0;
  // Floats per vertex / transform / joint, derived from the upload sizes and strides.
  double floatsPerVertex = 0, floatsPerTransform = 0, floatsPerJoint = 0;
  // Per transform with the per-draw float the transform needs (motor: 8 + u_Scale; affine: + u_Mirror;
  // a pipeline without one: floatsPerTransform), from the bytes uploaded for the same draws.
  double floatsPerTransformWithScale = 0;
  int draws = 0;                      // draw calls of the last render()
  double conversionMs = 0;            // load-time conversion inside prepare()
  double updateMs = 0;                // last update() (hierarchy, animation, palette)
  // The last update() phase by phase (update_phases.h); all 0 unless timeUpdatePhases(true).
  UpdatePhases updatePhases;
  // Fallbacks taken (counted per node / vertex as named).
  int nonUniformScaleNodes = 0;       // handled by a per-leaf fallback
  int negativeScaleNodes = 0;
  int shearMatrixNodes = 0;
  int zeroScalarFrames = 0;           // tangent rotors whose scalar part was exactly 0
  int biasedFrames = 0;               // frames whose scalar |s| (rotor) or |w| (quaternion) the
                                      // bias rule raised to 1/32767 so the handedness survives
  int scaleFallbackInstances = 0;     // motor: instances of the last render() whose scale is
                                      // non-uniform or negative (drawn as MB_SCALE_FALLBACK)
  int rotorSplitVertices = 0;         // motor_cf: vertices split so each triangle's rotors
                                      // share a hemisphere (pipelines/motor/rotor_signs.h)
  int rotorUnresolvedTriangles = 0;   // motor_cf: triangles whose frames turn > 180 degrees
  // Exact fallbacks of the motor family, of the last render(): rigid draws whose
  // world transform is not a similarity (non-uniform or sheared, inherited from an inner node),
  // drawn with a general linear part before the motor; skinned draws whose joint palette is not
  // one common uniform scale (per-joint scales, scaled or sheared joints), and the joints of
  // those palettes; the vertices all those draws drew. 0 for pipelines that need none.
  int linearFallbackDraws = 0;
  int skinFallbackDraws = 0;
  int skinFallbackJoints = 0;
  uint64_t fallbackVertices = 0;
  uint64_t skinFallbackVertices = 0;  // of fallbackVertices, those of the skinned draws
};

// Where a skinned vertex reaches world space (timing compares both pipelines in the same
// configuration). Reference: as the references do it, the joint palette relative to the mesh
// node and the node's world transform applied per vertex after the blend (glTF-Sample-Viewer:
// u_ModelMatrix after the skin; the paper's shader: gp(toWorld, blend)). WorldPalette: the
// palette is joint world * inverse bind and nothing is applied after the blend (neither
// reference does this). PipelineDefault: what the pipeline draws unless told (matrix:
// Reference, motor: WorldPalette; the goldens were made so), see Pipeline::skinSpace().
enum class SkinSpace { PipelineDefault, Reference, WorldPalette };

// How the motor family morphs its tangent rotor (shaders/motor_transform.glsl):
// Frame (a): the rotor's normal and tangent plus the glTF deltas, re-formed into a rotor per
// vertex (the default: exact); Rotor (b): rotor deltas made at load, blended and renormalised.
enum class MorphMethod { PipelineDefault, Frame, Rotor };

// Settings a pipeline takes before prepare(). A pipeline without the choice ignores it.
struct PipelineOptions {
  SkinSpace skinSpace = SkinSpace::PipelineDefault;
  MorphMethod morph = MorphMethod::PipelineDefault;
};

class Pipeline {
public:
  virtual ~Pipeline() = default;
  virtual std::string name() const = 0;
  // Applies `options` (call before prepare()). The default ignores them.
  virtual void configure(const PipelineOptions& options) { (void)options; }
  // The skinning configuration this pipeline draws with (its default resolved);
  // PipelineDefault from a pipeline that has no choice.
  virtual SkinSpace skinSpace() const { return SkinSpace::PipelineDefault; }
  // Converts and uploads `scene` (which must outlive the pipeline). Needs a current GL context.
  virtual Status prepare(const Scene& scene) = 0;
  // Poses the scene on the CPU for `state` (sampling, hierarchy, skin palette).
  virtual void update(const AnimState& state) = 0;
  // on: every later update() also times its phases into PipelineStats::updatePhases (a clock
  // read per phase, so the timing harness times whole updates with it off). Default: a
  // pipeline without phases (the curved ones) ignores it.
  virtual void timeUpdatePhases(bool on) { (void)on; }
  // Draws the posed scene into the bound framebuffer.
  virtual void render(const View& view) = 0;
  virtual PipelineStats stats() const = 0;
};

// The glTF pipelines' guard in prepare(): a curved-space scene (Scene::curved) is
// refused with a message naming the scene, its space and the pipelines that draw it.
inline Status refuseCurvedScene(const Scene& scene, const std::string& pipeline) {
  if (scene.curved.space == Space::Euclidean) return {};
  const bool s3 = scene.curved.space == Space::Spherical;
  return Status::fail(scene.source + ": pipeline " + pipeline + " draws Euclidean glTF scenes; this is a " +
                      (s3 ? "spherical (S3)" : "hyperbolic (H3)") + " scene: use " +
                      (s3 ? "s3_matrix or s3_motor" : "h3_matrix or h3_motor"));
}

// nullptr when `name` is not registered.
std::unique_ptr<Pipeline> createPipeline(const std::string& name);
// Registered names of the pipelines that draw scenes of `space`, the matrix baseline first.
// The default (Euclidean: every glTF scene) is what commands and tests run when not told.
std::vector<std::string> pipelineNames(Space space = Space::Euclidean);
// Every registered name, curved-space pipelines included.
std::vector<std::string> allPipelineNames();

}  // namespace mb
