// Motor skinning (shaders/motor_transform.glsl run through the C++ shim) against GLM linear
// blend skinning on the cases where both must agree: a single joint, several joints carrying
// the same motion (with either sign of the double cover), and pure translations. Also the
// palette: joint world motor * inverse-bind motor equals joint world matrix * inverse bind.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_kernels.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/scene/camera_rule.h"
#include "tests/support/pga_test_support.h"

using namespace mb;
using V3 = MK::vec3;
using V4 = MK::vec4;

namespace {

// Seeded draws from tests/support/pga_test_support.h, in float.
float uni(std::mt19937& g, float lo, float hi) { return float(mbtest::uniform(g, lo, hi)); }
glm::quat randomQuat(std::mt19937& g) { return glm::quat(mbtest::randomQuat(g)); }

struct Joint {
  glm::mat4 matrix;
  Motor motor;
};

Joint randomJoint(std::mt19937& g) {
  const glm::vec3 t(uni(g, -3, 3), uni(g, -3, 3), uni(g, -3, 3));
  const glm::quat q = randomQuat(g);
  return {glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(q), companion::motorFromTRS(t, q)};
}

glm::vec4 randomWeights(std::mt19937& g) {
  glm::vec4 w(uni(g, 0, 1), uni(g, 0, 1), uni(g, 0, 1), uni(g, 0, 1));
  return w / (w.x + w.y + w.z + w.w);
}

glm::vec3 toGlm(const V3& v) { return {v.x, v.y, v.z}; }

// The skinned vertex of motor_transform.glsl: world position, normal and tangent.
struct Skinned {
  glm::vec3 position, normal, tangent;
  float w;
};
Skinned motorSkin(const Motor (&j)[4], const glm::vec4& w, const glm::vec3& p, const glm::vec4& rotor) {
  const MK::mat3x4 v = mk().motorSkinnedVertex(j[0], j[1], j[2], j[3], V4(w.x, w.y, w.z, w.w), 1.0f,
                                               V3(p.x, p.y, p.z), V4(rotor.x, rotor.y, rotor.z, rotor.w));
  return {toGlm(V3(v[0].xyz)), glm::normalize(toGlm(V3(v[1].xyz))), glm::normalize(toGlm(V3(v[2].xyz))),
          v[2].w};
}

Skinned linearBlend(const glm::mat4 (&j)[4], const glm::vec4& w, const glm::vec3& p, const glm::vec3& n,
                    const glm::vec3& t, float hand) {
  const glm::mat4 m = w.x * j[0] + w.y * j[1] + w.z * j[2] + w.w * j[3];
  const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(m)));
  return {glm::vec3(m * glm::vec4(p, 1.0f)), glm::normalize(nm * n), glm::normalize(glm::mat3(m) * t), hand};
}

void expectSame(const Skinned& a, const Skinned& b, float tol) {
  EXPECT_LT(glm::length(a.position - b.position), tol * (1.0f + glm::length(b.position)));
  EXPECT_LT(glm::length(a.normal - b.normal), tol);
  EXPECT_LT(glm::length(a.tangent - b.tangent), tol);
  EXPECT_EQ(a.w, b.w);
}

}  // namespace

TEST(MotorSkinning, RigidCasesMatchLinearBlend) {
  std::mt19937 g(4);
  for (int i = 0; i < 2000; ++i) {
    const Joint joint = randomJoint(g);
    Motor motors[4];
    glm::mat4 matrices[4];
    for (int k = 0; k < 4; ++k) {
      // Every joint carries the same motion; odd joints through the other cover (-M).
      motors[k] = (k % 2 && i % 3) ? -joint.motor : joint.motor;
      matrices[k] = joint.matrix;
    }
    glm::vec4 w = randomWeights(g);
    if (i % 4 == 0) w = glm::vec4(1, 0, 0, 0);  // single joint
    const glm::vec3 p(uni(g, -2, 2), uni(g, -2, 2), uni(g, -2, 2));
    const glm::vec3 n = glm::normalize(glm::vec3(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1)) + glm::vec3(0, 0, 0.01f));
    const glm::vec3 t = glm::normalize(glm::cross(n, glm::vec3(0.3f, 1.0f, -0.2f)));
    const float hand = (i % 2) ? -1.0f : 1.0f;
    const companion::TangentRotor r = companion::encodeTangentRotor(n, t, hand);
    expectSame(motorSkin(motors, w, p, r.rotor), linearBlend(matrices, w, p, n, t, hand), 2e-5f);
  }
}

TEST(MotorSkinning, PureTranslationsBlendLinearly) {
  std::mt19937 g(5);
  for (int i = 0; i < 500; ++i) {
    Motor motors[4];
    glm::mat4 matrices[4];
    for (int k = 0; k < 4; ++k) {
      const glm::vec3 t(uni(g, -3, 3), uni(g, -3, 3), uni(g, -3, 3));
      motors[k] = companion::translator(t);
      matrices[k] = glm::translate(glm::mat4(1.0f), t);
    }
    const glm::vec4 w = randomWeights(g);
    const glm::vec3 p(uni(g, -2, 2), uni(g, -2, 2), uni(g, -2, 2));
    const glm::vec4 rotor(1.0f, 0.0f, 0.0f, 0.0f);
    expectSame(motorSkin(motors, w, p, rotor),
               linearBlend(matrices, w, p, glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), 1.0f), 2e-5f);
  }
}

TEST(MotorSkinning, TwistKeepsTheRadiusWhereLinearBlendCollapses) {
  // Two joints a quarter turn apart about the bone axis (y), vertex on a unit circle halfway:
  // linear blend pulls it towards the axis (radius cos(pi/4)), motor skinning keeps radius 1.
  const float half = glm::radians(90.0f);
  const glm::quat q = glm::angleAxis(half, glm::vec3(0, 1, 0));
  Motor motors[4] = {Motor(1.0f), companion::rotorFromQuat(q), Motor(1.0f), Motor(1.0f)};
  glm::mat4 matrices[4] = {glm::mat4(1.0f), glm::mat4_cast(q), glm::mat4(1.0f), glm::mat4(1.0f)};
  const glm::vec4 w(0.5f, 0.5f, 0.0f, 0.0f);
  const glm::vec3 p(1.0f, 0.0f, 0.0f);
  const Skinned m = motorSkin(motors, w, p, glm::vec4(1, 0, 0, 0));
  const Skinned l = linearBlend(matrices, w, p, glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), 1.0f);
  EXPECT_NEAR(glm::length(glm::vec2(m.position.x, m.position.z)), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(glm::vec2(l.position.x, l.position.z)), std::cos(half / 2.0f), 1e-6f);
}

TEST(MotorSkinning, PaletteMatchesMatrixPalette) {
  // Two-joint chain with uniform scale and a skinned mesh node; inverse binds from the bind
  // pose. Palette motor (with the skin scale applied first) == joint world * inverse bind.
  Scene scene;
  scene.nodes.resize(3);
  scene.nodes[0].local.translation = glm::vec3(0.5f, 1.0f, 0.0f);
  scene.nodes[0].local.rotation = glm::angleAxis(0.4f, glm::vec3(0, 0, 1));
  scene.nodes[0].local.scale = glm::vec3(1.5f);
  scene.nodes[0].children = {1};
  scene.nodes[1].parent = 0;
  scene.nodes[1].local.translation = glm::vec3(0.0f, 2.0f, 0.0f);
  scene.nodes[1].local.rotation = glm::angleAxis(-0.9f, glm::vec3(1, 0, 0));
  scene.nodes[2].mesh = 0;
  scene.nodes[2].skin = 0;
  scene.roots = {0, 2};
  std::vector<TRS> rest;
  for (const Node& n : scene.nodes) rest.push_back(n.local);
  Skin skin;
  skin.joints = {0, 1};
  const std::vector<glm::mat4> bind = worldMatrices(scene, rest);
  skin.inverseBind = {glm::inverse(bind[0]) * glm::scale(glm::mat4(1.0f), glm::vec3(0.8f)),
                      glm::inverse(bind[1])};
  scene.skins = {skin};
  scene.meshes.resize(1);

  std::vector<TRS> pose = rest;
  pose[1].rotation = glm::angleAxis(0.6f, glm::normalize(glm::vec3(1, 1, 0)));
  const motor::Rig rig = motor::buildRig(scene);
  const auto world = motor::worldPose(scene, motor::localPose(rig, pose));
  const auto palettes = motor::jointPalettes(scene, rig, world);
  ASSERT_EQ(palettes.size(), 1u);
  ASSERT_EQ(palettes[0].motors.size(), 16u);
  const std::vector<glm::mat4> worldM = worldMatrices(scene, pose);
  // Joint world scale * inverse-bind scale: 1.5 * (0.8 / 1.5) and 1.5 * (1 / 1.5).
  const float scales[2] = {0.8f, 1.0f};
  for (int j = 0; j < 2; ++j) {
    const float* f = &palettes[0].motors[size_t(j) * 8];
    const Motor m(V4(f[0], f[1], f[2], f[3]), V4(f[4], f[5], f[6], f[7]));
    const glm::mat4 want = worldM[size_t(skin.joints[size_t(j)])] * scene.skins[0].inverseBind[size_t(j)];
    const glm::vec3 p(0.3f, -0.7f, 1.1f);
    const glm::vec3 q = p * scales[j];
    const glm::vec3 got = toGlm(mk().sw_mp(m, V3(q.x, q.y, q.z)));
    EXPECT_LT(glm::length(got - glm::vec3(want * glm::vec4(p, 1.0f))), 1e-5f) << "joint " << j;
  }
  // The two joints' scales differ (0.8 vs 1): the palette takes the per-joint fallback; scale is joint 0's.
  EXPECT_TRUE(palettes[0].fallback);
  EXPECT_NEAR(palettes[0].scale, 0.8f, 1e-6f);
}
