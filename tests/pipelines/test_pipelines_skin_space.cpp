// Symmetric skinning: each pipeline draws a skinned mesh in two configurations,
// "as the references do" (SkinSpace::Reference: palette relative to the mesh node, the node's
// transform applied per vertex after the blend) and "world-space palette" (no per-vertex node
// transform). Both are the same pose: the CPU palettes differ exactly by the node's world
// transform, and the images agree within float rounding, also when the skinned mesh's node
// is moved (glTF ignores that node's transform for skinned meshes). The defaults stay what the
// goldens were made with (matrix: Reference, motor: WorldPalette).
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
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

int animationNamed(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.animations.size(); ++i)
    if (scene.animations[i].name == name) return int(i);
  ADD_FAILURE() << "no animation " << name;
  return 0;
}

struct Rendered {
  RgbaImage image;
  PipelineStats stats;
  SkinSpace space = SkinSpace::PipelineDefault;
};

// renderFrame() with pipeline options (the harness takes none yet).
Rendered render(const Scene& scene, const std::string& pipeline, SkinSpace space,
                const AnimState& anim) {
  Rendered r;
  auto ctx = gl::sharedContext();
  EXPECT_TRUE(ctx) << ctx.error();
  if (!ctx) return r;
  constexpr int kW = 128, kH = 96;
  auto fb = gl::Framebuffer::create(kW, kH);
  EXPECT_TRUE(fb) << fb.error();
  if (!fb) return r;
  std::unique_ptr<Pipeline> p = createPipeline(pipeline);
  PipelineOptions options;
  options.skinSpace = space;
  p->configure(options);
  Status ok = p->prepare(scene);
  EXPECT_TRUE(ok) << ok.error();
  p->update(anim);
  // Framed on the unmoved scene so a moved mesh node does not move the camera.
  (*fb)->clear(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
  p->render(frameScene(scene, anim, float(kW) / float(kH)));
  r.image.width = kW;
  r.image.height = kH;
  r.image.rgba = (*fb)->readRgba();
  r.stats = p->stats();
  r.space = p->skinSpace();
  return r;
}

int maxLevels(const RgbaImage& a, const RgbaImage& b) {
  auto m = compareImages(a, b);
  EXPECT_TRUE(m);
  return m ? int(std::lround(m->maxError * 255.0)) : 255;
}

// The skinned mesh node of skinned_tube turned and shifted (ignored by glTF for skinning).
Scene withMovedMeshNode(Scene scene) {
  for (Node& n : scene.nodes)
    if (n.skin >= 0 && n.mesh >= 0) {
      n.local.translation += glm::vec3(0.7f, -0.4f, 0.3f);
      n.local.rotation = glm::angleAxis(0.6f, glm::normalize(glm::vec3(1, 2, 0.5f))) * n.local.rotation;
    }
  return scene;
}

}  // namespace

TEST(SkinSpace, DefaultsAreTheGoldensConfigurations) {
  const Scene scene = load("skinned_tube");
  EXPECT_EQ(render(scene, "matrix", SkinSpace::PipelineDefault, {}).space, SkinSpace::Reference);
  EXPECT_EQ(render(scene, "motor", SkinSpace::PipelineDefault, {}).space, SkinSpace::WorldPalette);
  EXPECT_EQ(render(scene, "matrix", SkinSpace::WorldPalette, {}).space, SkinSpace::WorldPalette);
  EXPECT_EQ(render(scene, "motor", SkinSpace::Reference, {}).space, SkinSpace::Reference);
}

TEST(SkinSpace, MatrixPalettesDifferByTheMeshNodesWorldMatrix) {
  const Scene scene = withMovedMeshNode(load("skinned_tube"));
  const AnimState anim{animationNamed(scene, "candy_wrapper"), 0.7f};
  const matrix::Pose ref = matrix::poseScene(scene, anim, false);
  const matrix::Pose world = matrix::poseScene(scene, anim, true);
  ASSERT_EQ(ref.palettes.size(), 1u);
  const glm::mat4& node = ref.world[size_t(ref.palettes[0].node)];
  ASSERT_GT(glm::length(glm::vec3(node[3])), 0.5f);  // the node really moved
  for (size_t j = 0; j < ref.palettes[0].matrices.size(); j += 2) {
    const glm::mat4 expect = node * ref.palettes[0].matrices[j];
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        EXPECT_NEAR(world.palettes[0].matrices[j][c][r], expect[c][r], 1e-5f) << j << c << r;
  }
}

TEST(SkinSpace, MotorPalettesDifferByTheMeshNodesWorldMotor) {
  const Scene scene = withMovedMeshNode(load("skinned_tube"));
  const AnimState anim{animationNamed(scene, "candy_wrapper"), 0.7f};
  const motor::Rig rig = motor::buildRig(scene);
  const auto world = motor::worldPose(scene, motor::localForState(scene, rig, anim));
  const auto abs = motor::jointPalettes(scene, rig, world, false);
  const auto rel = motor::jointPalettes(scene, rig, world, true);
  ASSERT_EQ(abs.size(), 1u);
  ASSERT_EQ(rel.size(), 1u);
  EXPECT_EQ(abs[0].scale, rel[0].scale);
  const Motor node = world[size_t(abs[0].node)].motor;
  for (size_t j = 0; j < abs[0].motors.size(); j += 8) {
    Motor x;
    for (int k = 0; k < 8; ++k) x[k / 4][k % 4] = rel[0].motors[j + size_t(k)];
    const Motor back = mk().gp_mm(node, x);
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(back[k / 4][k % 4], abs[0].motors[j + size_t(k)], 1e-5f);
  }
  // And a point through each joint, against the world-space joint (independent of PGA
  // layout): the same place within rounding.
  const glm::vec3 p(0.1f, 0.8f, -0.05f);
  for (size_t j = 0; j < abs[0].motors.size(); j += 8) {
    motor::ScaledMotor a, r;
    for (int k = 0; k < 8; ++k) {
      a.motor[k / 4][k % 4] = abs[0].motors[j + size_t(k)];
      r.motor[k / 4][k % 4] = rel[0].motors[j + size_t(k)];
    }
    motor::ScaledMotor nodeOnly;
    nodeOnly.motor = node;
    const glm::vec3 viaNode = motor::applyToPoint(nodeOnly, motor::applyToPoint(r, p));
    const glm::vec3 direct = motor::applyToPoint(a, p);
    EXPECT_NEAR(glm::length(viaNode - direct), 0.0f, 1e-5f);
  }
}

TEST(SkinSpace, BothConfigurationsDrawTheSamePose) {
  const Scene plain = load("skinned_tube");
  const Scene moved = withMovedMeshNode(plain);
  for (const char* anim : {"candy_wrapper", "bend", "twist"}) {
    const AnimState state{animationNamed(plain, anim), 0.7f};
    for (const char* pipeline : {"matrix", "motor"}) {
      SCOPED_TRACE(std::string(pipeline) + " " + anim);
      const Rendered base = render(plain, pipeline, SkinSpace::PipelineDefault, state);
      for (SkinSpace s : {SkinSpace::Reference, SkinSpace::WorldPalette}) {
        // Rounding only: the palettes differ by one transform applied before or after.
        EXPECT_LE(maxLevels(base.image, render(plain, pipeline, s, state).image), 2);
        EXPECT_LE(maxLevels(base.image, render(moved, pipeline, s, state).image), 2);
      }
    }
  }
}

TEST(SkinSpace, WhatEachConfigurationUploadsPerDraw) {
  const Scene scene = load("skinned_tube");
  const AnimState state{0, 0.5f};
  // Matrix: u_ModelMatrix + u_NormalMatrix per draw as the Sample Viewer; with a world-space
  // palette the model matrix is not used by the shader (GL drops it: nothing uploaded).
  EXPECT_DOUBLE_EQ(render(scene, "matrix", SkinSpace::Reference, state).stats.floatsPerTransform, 32.0);
  EXPECT_DOUBLE_EQ(render(scene, "matrix", SkinSpace::WorldPalette, state).stats.floatsPerTransform, 16.0);
  // Motor: the reference form uploads the node's world motor for the skinned draw too.
  const Rendered ref = render(scene, "motor", SkinSpace::Reference, state);
  const Rendered world = render(scene, "motor", SkinSpace::WorldPalette, state);
  EXPECT_DOUBLE_EQ(ref.stats.floatsPerTransform, 8.0);
  EXPECT_DOUBLE_EQ(world.stats.floatsPerTransform, 0.0);  // skinned_tube: one skinned draw only
  EXPECT_EQ(ref.stats.skinBytesPerFrame, world.stats.skinBytesPerFrame);
}
