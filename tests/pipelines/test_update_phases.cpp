// The CPU update of every glTF pipeline poses into buffers reused from frame
// to frame (a pose after another one equals the same pose computed fresh, bit for bit), its
// phases are measured only on request, and the motor defaults are the identity motor.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "pipelines/gl/context.h"
#include "pipelines/matrix/matrix_pose.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

Scene load(const std::string& name) {
  auto scene = loadScene(name);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

// Two different blended states of a scene with at least two animations.
AnimState blended(float t) { return AnimState{0, t, 1, 1.7f * t, 0.3f}; }

template <class T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

// mat2x4(1.0) would put 1 on e02 too: the default must be [1, 0, 0, 0, 0, 0, 0, 0].
TEST(UpdatePhases, DefaultMotorsAreTheIdentity) {
  const Motor id = identityMotor();
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_EQ(id[c][r], c == 0 && r == 0 ? 1.0f : 0.0f) << c << "," << r;
  EXPECT_TRUE(motor::ScaledMotor{}.motor == id);
  const glm::vec3 p(0.25f, -3.0f, 7.5f);
  const glm::vec3 q = motor::applyToPoint(motor::ScaledMotor{}, p);
  EXPECT_EQ(q.x, p.x);
  EXPECT_EQ(q.y, p.y);
  EXPECT_EQ(q.z, p.z);
}

// A skin without inverse binds (glTF: identity) gets joint world * identity in its palette.
TEST(UpdatePhases, MissingInverseBindIsTheIdentity) {
  Scene scene = load("skinned_tube");
  scene.skins[0].inverseBind.clear();
  const motor::Rig rig = motor::buildRig(scene);
  const auto world = motor::worldPose(scene, motor::localForState(scene, rig, AnimState{}));
  const auto palettes = motor::jointPalettes(scene, rig, world);
  ASSERT_EQ(palettes.size(), 1u);
  for (size_t j = 0; j < scene.skins[0].joints.size(); ++j)
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ(palettes[0].motors[8 * j + size_t(k)], world[size_t(scene.skins[0].joints[j])].motor[k / 4][k % 4]);
}

// The per-frame forms reuse their buffers: state A then state B equals B posed fresh.
TEST(UpdatePhases, ReusedBuffersGiveTheFreshPose) {
  const Scene scene = load("skinned_tube");
  ASSERT_GE(scene.animations.size(), 2u);
  PhaseClock off(nullptr);
  for (bool worldPalette : {false, true}) {
    MatrixPoseWork work;
    prepareMatrixPose(scene, work);
    matrix::Pose reused;
    matrix::poseScene(scene, blended(0.4f), worldPalette, work, reused, off);
    matrix::poseScene(scene, AnimState{0, 1.1f}, worldPalette, work, reused, off);
    const matrix::Pose fresh = matrix::poseScene(scene, AnimState{0, 1.1f}, worldPalette);
    EXPECT_TRUE(sameBytes(reused.world, fresh.world));
    ASSERT_EQ(reused.palettes.size(), fresh.palettes.size());
    for (size_t i = 0; i < fresh.palettes.size(); ++i)
      EXPECT_TRUE(sameBytes(reused.palettes[i].matrices, fresh.palettes[i].matrices));
  }
  const motor::Rig rig = motor::buildRig(scene);
  for (bool relative : {false, true}) {
    motor::PoseWork work;
    motor::poseScene(scene, rig, AnimState{0, 1.1f}, relative, work, nullptr, off);
    motor::poseScene(scene, rig, blended(0.4f), relative, work, nullptr, off);
    const auto world = motor::worldPose(scene, motor::localForState(scene, rig, blended(0.4f)));
    const auto palettes = motor::jointPalettes(scene, rig, world, relative);
    ASSERT_EQ(work.world.size(), world.size());
    for (size_t n = 0; n < world.size(); ++n) EXPECT_TRUE(work.world[n].motor == world[n].motor) << n;
    ASSERT_EQ(work.palettes.size(), palettes.size());
    for (size_t i = 0; i < palettes.size(); ++i) EXPECT_TRUE(sameBytes(work.palettes[i].motors, palettes[i].motors));
  }
}

// Phases are 0 until asked for; an update without a blend laps nothing into blending.
TEST(UpdatePhases, MeasuredOnlyWhenAsked) {
  auto ctx = gl::sharedContext();
  ASSERT_TRUE(ctx) << ctx.error();
  const Scene scene = load("skinned_tube");
  for (const std::string& name : pipelineNames()) {
    SCOPED_TRACE(name);
    auto p = createPipeline(name);
    ASSERT_TRUE(p);
    ASSERT_TRUE(p->prepare(scene));
    p->update(blended(0.5f));
    EXPECT_EQ(p->stats().updatePhases.total(), 0.0);
    p->timeUpdatePhases(true);
    p->update(AnimState{0, 0.5f});
    const UpdatePhases single = p->stats().updatePhases;
    EXPECT_EQ(single.blendingMs, 0.0);
    for (double v : {single.samplingMs, single.conversionMs, single.hierarchyMs, single.paletteMs}) EXPECT_GE(v, 0.0);
    p->update(blended(0.5f));
    EXPECT_GT(p->stats().updatePhases.total(), 0.0);
  }
}

// The motor product of the per-frame loops (4-lane; without vector extensions it is gp_mm
// itself) is the shader's gp_mm, bit for bit.
TEST(UpdatePhases, MotorProductIsTheShadersBitForBit) {
  std::mt19937 g(13);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  auto random = [&] {
    Motor m;
    for (int c = 0; c < 2; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = u(g);
    return m;
  };
  for (int i = 0; i < 100000; ++i) {
    const Motor a = random(), b = random();
    const Motor fast = motor::gpMotors(a, b), shader = mk().gp_mm(a, b);
    ASSERT_EQ(std::memcmp(&fast, &shader, sizeof(Motor)), 0) << "sample " << i;
    // With b's dual half scaled in registers (the hierarchy's parent scale).
    const float s = u(g);
    Motor scaled;
    motor::gpMotors(a, b, scaled, s);
    const Motor scaledShader = mk().gp_mm(a, Motor(b[0], b[1] * s));
    ASSERT_EQ(std::memcmp(&scaled, &scaledShader, sizeof(Motor)), 0) << "sample " << i;
  }
}

// Posing one animation unblended converts only the nodes it drives (the rest from the
// load-time conversion): the same worlds and fallback counts as converting every node.
TEST(UpdatePhases, OnlyDrivenNodesConvertedGivesTheFullPose) {
  PhaseClock off(nullptr);
  for (const char* name : {"scaled_hierarchy", "skinned_tube", "teapot", "crowd"}) {
    SCOPED_TRACE(name);
    const Scene scene = load(name);
    for (int anim = -1; anim < int(scene.animations.size()); ++anim) {
      const AnimState state{anim, 0.7f};
      MatrixPoseWork work;
      prepareMatrixPose(scene, work);
      matrix::Pose pose;
      matrix::poseScene(scene, state, false, work, pose, off);
      EXPECT_TRUE(sameBytes(pose.world, worldMatrices(scene, sampleAnimation(scene, anim, 0.7f))));
      const motor::Rig rig = motor::buildRig(scene);
      motor::PoseWork mwork;
      motor::RigCounts fast, full;
      motor::poseScene(scene, rig, state, false, mwork, &fast, off);
      const auto world = motor::worldPose(scene, motor::localPose(rig, sampleAnimation(scene, anim, 0.7f), &full));
      ASSERT_EQ(mwork.world.size(), world.size());
      for (size_t n = 0; n < world.size(); ++n) {
        EXPECT_TRUE(mwork.world[n].motor == world[n].motor) << n;
        EXPECT_EQ(mwork.world[n].scale, world[n].scale) << n;
      }
      EXPECT_EQ(fast.nonUniformScaleNodes, full.nonUniformScaleNodes);
      EXPECT_EQ(fast.negativeScaleNodes, full.negativeScaleNodes);
      EXPECT_EQ(fast.shearMatrixNodes, full.shearMatrixNodes);
    }
  }
}
