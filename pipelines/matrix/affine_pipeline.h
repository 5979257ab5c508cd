// The production matrix pipelines: `affine` (the matrix pipeline's 48-byte vertex,
// mat4x3 + mat3 per draw, mat4x3 per joint) and `qtangent` (the same with the frame as an
// int16x4 quaternion, 28 bytes per vertex). The class is shared with pipelines/hybrid, which
// supplies its own Poser (motors on the CPU, converted to mat4x3).
#pragma once
#include <memory>
#include <string>

#include "pipelines/matrix/affine_pose.h"
#include "pipelines/pipeline.h"
#include "pipelines/registry.h"

namespace mb {
namespace affine {

enum class FrameFormat {
  Float,     // gl::floatFrameFormat: position, normal, [tangent,] uv (48 or 32 bytes)
  QTangent,  // interleaveQTangent: position, int16x4 quaternion, uv (28 bytes)
  Compact,   // matrix_c, interleaveCompact: int16x4 position, 4-byte frame, half2 uv (16 bytes)
};

// Poses a scene for the pipeline; what differs between `affine` and `hybrid`.
class Poser {
public:
  virtual ~Poser() = default;
  // Load-time conversion (timed as part of PipelineStats::conversionMs).
  virtual Status prepare(const Scene& scene) = 0;
  // The pose for `state` into `out` (its storage reused; timed as PipelineStats::updateMs),
  // the phases lapped into `clock`; may set the fallback counters.
  virtual void pose(const Scene& scene, const AnimState& state, Pose& out, PipelineStats& stats,
                    PhaseClock& clock) = 0;
};

// `poser` null: the GLM poser (affine::poseScene); pipelines/hybrid passes its own.
std::unique_ptr<Pipeline> makePipeline(const std::string& name, FrameFormat format,
                                       std::unique_ptr<Poser> poser = nullptr);

// The programs of the int16-quaternion vertex (qtangent's, hybrid's), `also` added to each note.
std::vector<ShaderVariant> qtangentVariants(const std::string& also);

}  // namespace affine

// The registry entries of affine, qtangent and matrix_c (affine_entry.cpp).
PipelineEntry affineEntry();
PipelineEntry qtangentEntry();
PipelineEntry matrixCEntry();

}  // namespace mb
