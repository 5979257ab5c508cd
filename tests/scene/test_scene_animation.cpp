// Animation sampling: LINEAR, STEP and CUBICSPLINE against hand-computed values, clamping,
// shortest-arc rotation in slerp and in blends.
#include <gtest/gtest.h>

#include <cmath>

#include "pipelines/scene/animation.h"

namespace {

constexpr float kPi = 3.14159265358979f;

mb::Scene oneNodeScene() {
  mb::Scene s;
  s.nodes.resize(1);
  s.nodes[0].local.translation = glm::vec3(7, 8, 9);
  return s;
}

mb::Channel channel(mb::AnimPath path, mb::Interpolation interp, std::vector<float> times, std::vector<float> values) {
  mb::Channel c;
  c.node = 0;
  c.path = path;
  c.interpolation = interp;
  c.times = std::move(times);
  c.values = std::move(values);
  return c;
}

void addAnimation(mb::Scene& s, mb::Channel c) {
  mb::Animation a;
  a.duration = c.times.back();
  a.channels.push_back(std::move(c));
  s.animations.push_back(std::move(a));
}

std::vector<float> quat(float angle, glm::vec3 axis) {  // glTF order x, y, z, w
  glm::quat q = glm::angleAxis(angle, axis);
  return {q.x, q.y, q.z, q.w};
}

glm::vec3 rotateX(const glm::quat& q) { return q * glm::vec3(1, 0, 0); }

void expectVec(const glm::vec3& a, const glm::vec3& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

TEST(SceneAnimation, LinearTranslationAndClamping) {
  auto s = oneNodeScene();
  addAnimation(s, channel(mb::AnimPath::Translation, mb::Interpolation::Linear, {0, 2}, {0, 0, 0, 2, 4, 6}));
  expectVec(mb::sampleAnimation(s, 0, 0.5f)[0].translation, {0.5f, 1.0f, 1.5f});
  expectVec(mb::sampleAnimation(s, 0, -1.0f)[0].translation, {0, 0, 0});
  expectVec(mb::sampleAnimation(s, 0, 5.0f)[0].translation, {2, 4, 6});
  expectVec(mb::sampleAnimation(s, -1, 0.5f)[0].translation, {7, 8, 9});  // rest pose
  expectVec(mb::sampleAnimation(s, 3, 0.5f)[0].translation, {7, 8, 9});   // no such animation
}

TEST(SceneAnimation, Step) {
  auto s = oneNodeScene();
  addAnimation(s, channel(mb::AnimPath::Scale, mb::Interpolation::Step, {0, 1, 2}, {1, 1, 1, 2, 2, 2, 3, 3, 3}));
  EXPECT_FLOAT_EQ(mb::sampleAnimation(s, 0, 0.99f)[0].scale.x, 1.0f);
  EXPECT_FLOAT_EQ(mb::sampleAnimation(s, 0, 1.0f)[0].scale.x, 2.0f);
  EXPECT_FLOAT_EQ(mb::sampleAnimation(s, 0, 1.5f)[0].scale.y, 2.0f);
  EXPECT_FLOAT_EQ(mb::sampleAnimation(s, 0, 2.5f)[0].scale.z, 3.0f);
}

TEST(SceneAnimation, CubicSplineTranslation) {
  // Keys at t=0 (value 0, out-tangent 1) and t=2 (in-tangent -1, value 1); x only.
  // glTF: p(u) = h00 v0 + dt h10 b0 + h01 v1 + dt h11 a1 with dt = 2.
  // u = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875 -> 0.53125.
  // u = 0.5:  0.25 + 0.5 + 0.25 = 1.0.
  auto s = oneNodeScene();
  addAnimation(s, channel(mb::AnimPath::Translation, mb::Interpolation::CubicSpline, {0, 2},
                          {0, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0}));
  EXPECT_NEAR(mb::sampleAnimation(s, 0, 0.5f)[0].translation.x, 0.53125f, 1e-6f);
  EXPECT_NEAR(mb::sampleAnimation(s, 0, 1.0f)[0].translation.x, 1.0f, 1e-6f);
  EXPECT_NEAR(mb::sampleAnimation(s, 0, 2.0f)[0].translation.x, 1.0f, 1e-6f);
  EXPECT_NEAR(mb::sampleAnimation(s, 0, 0.0f)[0].translation.x, 0.0f, 1e-6f);
}

TEST(SceneAnimation, CubicSplineRotationIsNormalised) {
  auto s = oneNodeScene();
  std::vector<float> v;
  for (float angle : {0.0f, kPi / 2}) {
    auto q = quat(angle, {0, 0, 1});
    v.insert(v.end(), {0, 0, 0, 0});
    v.insert(v.end(), q.begin(), q.end());
    v.insert(v.end(), {0, 0, 0, 0});
  }
  addAnimation(s, channel(mb::AnimPath::Rotation, mb::Interpolation::CubicSpline, {0, 1}, v));
  glm::quat q = mb::sampleAnimation(s, 0, 0.5f)[0].rotation;
  EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
  expectVec(rotateX(q), {std::cos(kPi / 4), std::sin(kPi / 4), 0});
}

TEST(SceneAnimation, LinearRotationSlerpTakesShortestArc) {
  auto s = oneNodeScene();
  // 0 -> 90 degrees about Z, second key stored negated (same rotation).
  auto q1 = quat(kPi / 2, {0, 0, 1});
  std::vector<float> v = quat(0.0f, {0, 0, 1});
  for (float c : q1) v.push_back(-c);
  addAnimation(s, channel(mb::AnimPath::Rotation, mb::Interpolation::Linear, {0, 1}, v));
  expectVec(rotateX(mb::sampleAnimation(s, 0, 0.5f)[0].rotation), {std::cos(kPi / 4), std::sin(kPi / 4), 0});
  expectVec(rotateX(mb::sampleAnimation(s, 0, 1.0f / 3)[0].rotation), {std::cos(kPi / 6), std::sin(kPi / 6), 0});
  // 0 -> 270 degrees is -90 the short way: halfway is -45 degrees.
  auto s2 = oneNodeScene();
  std::vector<float> v2 = quat(0.0f, {0, 0, 1});
  auto q270 = quat(1.5f * kPi, {0, 0, 1});
  v2.insert(v2.end(), q270.begin(), q270.end());
  addAnimation(s2, channel(mb::AnimPath::Rotation, mb::Interpolation::Linear, {0, 1}, v2));
  expectVec(rotateX(mb::sampleAnimation(s2, 0, 0.5f)[0].rotation), {std::cos(kPi / 4), -std::sin(kPi / 4), 0});
}

TEST(SceneAnimation, BlendShortestArcAndLerp) {
  std::vector<mb::TRS> a(1), b(1);
  a[0].rotation = glm::angleAxis(kPi * 170 / 180, glm::vec3(0, 0, 1));
  b[0].rotation = glm::angleAxis(-kPi * 170 / 180, glm::vec3(0, 0, 1));
  a[0].translation = glm::vec3(0, 0, 0);
  b[0].translation = glm::vec3(4, 0, -2);
  a[0].scale = glm::vec3(1);
  b[0].scale = glm::vec3(3);
  auto m = mb::blendPoses(a, b, 0.5f);
  expectVec(rotateX(m[0].rotation), {-1, 0, 0});  // through 180, not through 0
  expectVec(m[0].translation, {2, 0, -1});
  expectVec(m[0].scale, {2, 2, 2});
  expectVec(rotateX(mb::blendPoses(a, b, 0.0f)[0].rotation), rotateX(a[0].rotation));
  expectVec(rotateX(mb::blendPoses(a, b, 1.0f)[0].rotation), rotateX(b[0].rotation));
}

TEST(SceneAnimation, SamplePoseBlendsTwoAnimations) {
  auto s = oneNodeScene();
  addAnimation(s, channel(mb::AnimPath::Translation, mb::Interpolation::Linear, {0, 1}, {0, 0, 0, 2, 0, 0}));
  addAnimation(s, channel(mb::AnimPath::Translation, mb::Interpolation::Linear, {0, 1}, {0, 0, 0, 0, 4, 0}));
  mb::AnimState st;
  st.anim = 0;
  st.time = 1.0f;
  st.anim2 = 1;
  st.time2 = 0.5f;
  st.blend = 0.25f;
  expectVec(mb::samplePose(s, st)[0].translation, {1.5f, 0.5f, 0});
  st.anim2 = -1;
  expectVec(mb::samplePose(s, st)[0].translation, {2, 0, 0});
  st.anim = -1;
  expectVec(mb::samplePose(s, st)[0].translation, {7, 8, 9});
}
