// Motor pipeline, CPU side: node hierarchies converted to motors + one signed uniform scale
// per node (pipelines/motor/motor_rig.h) place points exactly where the GLM matrices of the
// same hierarchy (the matrix pipeline's worldMatrices) place them. Seeded random trees with
// uniform, negative (mirror) and non-uniform-leaf scales; plus motor animation blending.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/quaternion.hpp>

#include "pipelines/motor/motor_rig.h"
#include "pipelines/scene/camera_rule.h"
#include "tests/support/pga_test_support.h"

using namespace mb;

namespace {

// Seeded draws from tests/support/pga_test_support.h, in float.
float uni(std::mt19937& g, float lo, float hi) { return float(mbtest::uniform(g, lo, hi)); }
glm::quat randomQuat(std::mt19937& g) { return glm::quat(mbtest::randomQuat(g)); }

// A scale of the kinds the motor pipeline must handle: uniform, mirrored by one or three axes,
// a half turn in disguise (two negative axes), or (`leaf` only) non-uniform.
glm::vec3 randomScale(std::mt19937& g, bool leaf) {
  const float s = uni(g, 0.3f, 2.5f);
  switch (std::uniform_int_distribution<int>(0, leaf ? 5 : 4)(g)) {
    case 0: return glm::vec3(s);
    case 1: return glm::vec3(-s, s, s);
    case 2: return glm::vec3(-s, -s, s);
    case 3: return glm::vec3(-s);
    case 4: return glm::vec3(1.0f);
    default: return glm::vec3(uni(g, 0.3f, 2.0f), uni(g, 0.3f, 2.0f), uni(g, -2.0f, -0.3f));
  }
}

// A random tree of `count` nodes (node 0 the root; each later node's parent is an earlier one).
Scene randomTree(std::mt19937& g, int count) {
  Scene scene;
  scene.nodes.resize(size_t(count));
  for (int n = 1; n < count; ++n) {
    const int parent = std::uniform_int_distribution<int>(0, n - 1)(g);
    scene.nodes[size_t(n)].parent = parent;
    scene.nodes[size_t(parent)].children.push_back(n);
  }
  for (Node& node : scene.nodes) {
    node.local.translation = glm::vec3(uni(g, -3, 3), uni(g, -3, 3), uni(g, -3, 3));
    node.local.rotation = randomQuat(g);
    node.local.scale = randomScale(g, node.children.empty());
  }
  scene.roots = {0};
  return scene;
}

std::vector<TRS> restPose(const Scene& scene) {
  std::vector<TRS> pose;
  for (const Node& n : scene.nodes) pose.push_back(n.local);
  return pose;
}

}  // namespace

TEST(MotorHierarchy, RandomTreesMatchGlmMatrices) {
  std::mt19937 g(20240728);
  double worst = 0.0;
  for (int tree = 0; tree < 300; ++tree) {
    Scene scene = randomTree(g, 2 + tree % 12);
    const motor::Rig rig = motor::buildRig(scene);
    const std::vector<motor::ScaledMotor> world =
        motor::worldPose(scene, motor::localPose(rig, restPose(scene)));
    const std::vector<glm::mat4> reference = worldMatrices(scene, restPose(scene));
    for (size_t n = 0; n < scene.nodes.size(); ++n) {
      // Residuals live on leaves only: an inner node's world scale stays a single float.
      if (!scene.nodes[n].children.empty()) {
        EXPECT_EQ(world[n].residual, glm::vec3(1.0f));
      }
      for (int k = 0; k < 4; ++k) {
        const glm::vec3 p(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1));
        const glm::vec3 want = glm::vec3(reference[n] * glm::vec4(p, 1.0f));
        const glm::vec3 got = motor::applyToPoint(world[n], p);
        const double err = glm::length(got - want) / (1.0 + glm::length(want));
        worst = std::max(worst, err);
        ASSERT_LT(err, 2e-5) << "tree " << tree << " node " << n;
      }
    }
  }
  std::printf("worst relative position error over 300 trees: %.3g\n", worst);
}

TEST(MotorHierarchy, ScaleFactorisationIsOneFloatPerNode) {
  // Uniform scales multiply down the tree; a parent's scale multiplies the child's translation.
  Scene scene;
  scene.nodes.resize(2);
  scene.nodes[0].local.scale = glm::vec3(2.0f);
  scene.nodes[0].children = {1};
  scene.nodes[1].parent = 0;
  scene.nodes[1].local.translation = glm::vec3(1.0f, 0.0f, 0.0f);
  scene.nodes[1].local.scale = glm::vec3(-1.5f);
  const motor::Rig rig = motor::buildRig(scene);
  const auto world = motor::worldPose(scene, rig.rest);
  EXPECT_FLOAT_EQ(world[1].scale, -3.0f);
  EXPECT_LT(glm::length(motor::applyToPoint(world[1], glm::vec3(0.0f)) - glm::vec3(2, 0, 0)), 1e-6f);
  EXPECT_LT(glm::length(motor::applyToPoint(world[1], glm::vec3(1, 0, 0)) - glm::vec3(-1, 0, 0)), 1e-6f);
}

TEST(MotorHierarchy, CountsFallbacks) {
  Scene scene;
  scene.nodes.resize(3);
  scene.nodes[0].children = {1, 2};
  scene.nodes[1].parent = scene.nodes[2].parent = 0;
  scene.nodes[1].local.scale = glm::vec3(1.0f, 2.0f, 0.5f);   // non-uniform leaf: residual
  scene.nodes[2].local.scale = glm::vec3(-1.0f, 1.0f, 1.0f);  // mirror
  motor::RigCounts counts;
  const motor::Rig rig = motor::buildRig(scene);
  motor::localPose(rig, restPose(scene), &counts);
  EXPECT_EQ(counts.nonUniformScaleNodes, 1);
  EXPECT_EQ(counts.negativeScaleNodes, 1);
  EXPECT_EQ(rig.rest[1].residual, glm::vec3(1.0f, 2.0f, 0.5f));
  EXPECT_FLOAT_EQ(rig.rest[2].scale, -1.0f);
}

TEST(MotorHierarchy, MatrixNodesMatchTheirMatrix) {
  std::mt19937 g(7);
  for (int i = 0; i < 200; ++i) {
    Scene scene;
    scene.nodes.resize(1);
    Node& node = scene.nodes[0];
    node.hasMatrix = true;
    const float s = uni(g, 0.2f, 3.0f) * (i % 3 == 0 ? -1.0f : 1.0f);
    node.matrix = glm::translate(glm::mat4(1.0f), glm::vec3(uni(g, -4, 4), uni(g, -4, 4), uni(g, -4, 4))) *
                  glm::mat4_cast(randomQuat(g)) * glm::scale(glm::mat4(1.0f), glm::vec3(s));
    const motor::Rig rig = motor::buildRig(scene);
    EXPECT_EQ(rig.restFlags[0].negative, s < 0.0f);
    const glm::vec3 p(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1));
    const glm::vec3 want = glm::vec3(node.matrix * glm::vec4(p, 1.0f));
    EXPECT_LT(glm::length(motor::applyToPoint(rig.rest[0], p) - want), 2e-5f * (1.0f + glm::length(want)));
  }
}

TEST(MotorBlend, EndpointsAndShortestArc) {
  std::mt19937 g(11);
  for (int i = 0; i < 200; ++i) {
    TRS a, b;
    a.translation = glm::vec3(uni(g, -2, 2), uni(g, -2, 2), uni(g, -2, 2));
    b.translation = glm::vec3(uni(g, -2, 2), uni(g, -2, 2), uni(g, -2, 2));
    a.rotation = randomQuat(g);
    b.rotation = randomQuat(g);
    a.scale = glm::vec3(uni(g, 0.5f, 2.0f));
    b.scale = glm::vec3(uni(g, 0.5f, 2.0f));
    motor::ScaledMotor ma = motor::fromTRS(a, true), mb_ = motor::fromTRS(b, true);
    // -M is the same motion: the blend must not care which cover it gets.
    motor::ScaledMotor mbNeg = mb_;
    mbNeg.motor = -mbNeg.motor;
    const glm::vec3 p(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1));
    EXPECT_LT(glm::length(motor::applyToPoint(motor::blend(ma, mb_, 0.0f), p) - motor::applyToPoint(ma, p)), 1e-5f);
    EXPECT_LT(glm::length(motor::applyToPoint(motor::blend(ma, mbNeg, 1.0f), p) - motor::applyToPoint(mb_, p)), 1e-5f);
    const motor::ScaledMotor half = motor::blend(ma, mb_, 0.5f), halfNeg = motor::blend(ma, mbNeg, 0.5f);
    EXPECT_LT(glm::length(motor::applyToPoint(half, p) - motor::applyToPoint(halfNeg, p)), 1e-5f);
    EXPECT_FLOAT_EQ(half.scale, 0.5f * (ma.scale + mb_.scale));
  }
}

TEST(MotorBlend, SameRotationBlendsTranslationLinearly) {
  // With equal rotations the blended motor's translation is the lerp of the translations, the
  // result TRS blending (blendPoses) gives as well.
  TRS a, b;
  a.rotation = b.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  a.translation = glm::vec3(1, 0, 0);
  b.translation = glm::vec3(0, 3, -1);
  const motor::ScaledMotor m = motor::blend(motor::fromTRS(a, true), motor::fromTRS(b, true), 0.25f);
  const std::vector<TRS> trs = blendPoses({a}, {b}, 0.25f);
  EXPECT_LT(glm::length(motor::applyToPoint(m, glm::vec3(0.0f)) - trs[0].translation), 1e-6f);
}
