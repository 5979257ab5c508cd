// How a pipeline blends the joints of a skinned vertex, as its vertex shader does: declared in
// its registry entry (PipelineEntry::skin), where a new variant is registered. The two methods
// pose a skinned mesh differently by design, so a skinned frame is judged against its own
// method's reference (harness/render/skin_judgement.h).
#pragma once
#include <string>

namespace mb {

enum class SkinMethod {
  None,         // draws no skinned scene (the curved pipelines), or not a registered name
  LinearBlend,  // a matrix palette blended linearly (linear blend skinning: matrix.vs, affine.vs)
  MotorBlend,   // joint motors blended (dual quaternion linear blending: motor.vs)
};

SkinMethod skinMethodOf(const std::string& pipeline);

}  // namespace mb
