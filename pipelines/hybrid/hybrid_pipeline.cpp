#include "pipelines/hybrid/hybrid_pipeline.h"

#include "pipelines/affine/affine_pipeline.h"
#include "pipelines/motor/companion.h"
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

// The motor pipeline's CPU work, then one conversion per node and per joint.
class MotorPoser final : public affine::Poser {
public:
  Status prepare(const Scene& scene) override {
    rig_ = motor::buildRig(scene);
    return {};
  }

  affine::Pose pose(const Scene& scene, const AnimState& state, PipelineStats& stats, PhaseClock& clock) override {
    motor::RigCounts counts = rig_.bindCounts;
    const std::vector<motor::ScaledMotor> world =
        motor::worldPose(scene, motor::localForState(scene, rig_, state, &counts, clock));
    clock.lap(&UpdatePhases::hierarchyMs);
    const std::vector<motor::JointPalette> palettes = motor::jointPalettes(scene, rig_, world);
    clock.lap(&UpdatePhases::paletteMs);
    stats.nonUniformScaleNodes = counts.nonUniformScaleNodes;
    stats.negativeScaleNodes = counts.negativeScaleNodes;
    stats.shearMatrixNodes = counts.shearMatrixNodes;
    affine::Pose pose;
    pose.world.reserve(world.size());
    for (const motor::ScaledMotor& w : world) pose.world.push_back(toMatrix(w.motor, w.scale * w.residual));
    for (const motor::JointPalette& p : palettes) {
      affine::Palette out;
      out.node = p.node;
      const glm::vec3 scale(p.scale);
      for (size_t j = 0; j + 8 <= p.motors.size(); j += 8) {
        const float* f = &p.motors[j];
        const mb::Motor m(companion::Vec4(f[0], f[1], f[2], f[3]),
                             companion::Vec4(f[4], f[5], f[6], f[7]));
        out.joints.push_back(toMatrix(m, scale));
      }
      pose.palettes.push_back(std::move(out));
    }
    clock.lap(&UpdatePhases::conversionMs);
    return pose;
  }

private:
  motor::Rig rig_;
};

}  // namespace
}  // namespace hybrid

std::unique_ptr<Pipeline> makeHybridPipeline() {
  return affine::makePipeline("hybrid", affine::FrameFormat::QTangent,
                              std::make_unique<hybrid::MotorPoser>());
}

}  // namespace mb
