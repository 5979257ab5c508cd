#include "pipelines/hybrid/hybrid_pipeline.h"

#include "pipelines/matrix/affine_pipeline.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/linear_fallback.h"
#include "pipelines/motor/motor_rig.h"

namespace mb {
namespace hybrid {

glm::mat4x3 toMatrix(const mb::Motor& m, const glm::vec3& scale) {
  glm::mat4 a = companion::motorToMatrix(m);
  a[0] *= scale.x;
  a[1] *= scale.y;
  a[2] *= scale.z;
  return glm::mat4x3(a);
}

namespace {

// World and joint motors -> mat4x3 (storage of `out` reused). flatten: motorToMatrix's sandwich
// products inlined.
// The motor pipeline's exact fallback (linear_fallback.h) as matrices: a general node takes its
// exact world, a fallback palette's joint its motor times its linear part.
[[gnu::flatten]] void toMatrices(const motor::Rig& rig, const motor::PoseWork& work, affine::Pose& out) {
  out.world.resize(work.world.size());
  for (size_t n = 0; n < work.world.size(); ++n)
    out.world[n] = rig.general[n] ? glm::mat4x3(work.exact.world[n])
                                  : toMatrix(work.world[n].motor, work.world[n].scale * work.world[n].residual);
  out.palettes.resize(work.palettes.size());
  for (size_t i = 0; i < work.palettes.size(); ++i) {
    const motor::JointPalette& p = work.palettes[i];
    affine::Palette& palette = out.palettes[i];
    palette.node = p.node;
    palette.joints.resize(p.motors.size() / 8);
    const glm::vec3 scale(p.scale);
    for (size_t j = 0; j < palette.joints.size(); ++j) {
      const float* f = &p.motors[8 * j];
      const mb::Motor m(companion::Vec4(f[0], f[1], f[2], f[3]), companion::Vec4(f[4], f[5], f[6], f[7]));
      if (p.fallback) {
        const glm::mat3 linear = motor::unpackLinear(&p.linear[24 * j]);
        palette.joints[j] = glm::mat4x3(companion::motorToMatrix(m) * glm::mat4(linear));
      } else {
        palette.joints[j] = toMatrix(m, scale);
      }
    }
  }
}

// The motor pipeline's CPU work, then one conversion per node and per joint.
class MotorPoser final : public affine::Poser {
public:
  Status prepare(const Scene& scene) override {
    rig_ = motor::buildRig(scene);
    return {};
  }

  void pose(const Scene& scene, const AnimState& state, affine::Pose& out, PipelineStats& stats,
            PhaseClock& clock) override {
    motor::RigCounts counts = rig_.bindCounts;
    motor::poseScene(scene, rig_, state, false, work_, &counts, clock);
    stats.nonUniformScaleNodes = counts.nonUniformScaleNodes;
    stats.negativeScaleNodes = counts.negativeScaleNodes;
    stats.shearMatrixNodes = counts.shearMatrixNodes;
    toMatrices(rig_, work_, out);
    clock.lap(&UpdatePhases::conversionMs);
  }

private:
  motor::Rig rig_;
  motor::PoseWork work_;
};

}  // namespace
}  // namespace hybrid

std::unique_ptr<Pipeline> makeHybridPipeline() {
  return affine::makePipeline("hybrid", affine::FrameFormat::QTangent,
                              std::make_unique<hybrid::MotorPoser>());
}

// Drawn exactly as qtangent: the same vertex and programs.
PipelineEntry hybridEntry() {
  return {.name = "hybrid", .make = makeHybridPipeline, .skin = SkinMethod::LinearBlend,
          .family = PipelineFamily::Motor, .vertexBytes = 28, .frame = {.decodeKernel = "qtangentFrame"},
          .variants = affine::qtangentVariants("; the GPU side of qtangent")};
}

}  // namespace mb
