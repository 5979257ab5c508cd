// The motor blend's CPU reference (harness/render/skin_reference.h) against values derived by
// hand: dual quaternion blending keeps the radius where the linear blend shrinks it, the
// hemisphere rule, translations, and any single joint (scaled, sheared) reproduced exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "harness/render/skin_reference.h"

using namespace mb;

namespace {

constexpr float kEps = 1e-5f;
const glm::vec3 kZ(0, 0, 1);

void expectNear(const glm::vec3& got, const glm::vec3& want, float eps = kEps) {
  EXPECT_NEAR(got.x, want.x, eps);
  EXPECT_NEAR(got.y, want.y, eps);
  EXPECT_NEAR(got.z, want.z, eps);
}

glm::mat4 rotationZ(float degrees) { return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), kZ); }

TEST(SkinReference, HalfwayBetweenTwoRotationsKeepsTheRadius) {
  // Joints at 0 and 90 degrees about z, half each: the blend is the 45 degree rotation, so
  // (1,0,0) lands on the unit circle at 45 degrees (a linear blend gives (0.5, 0.5, 0)).
  const std::vector<glm::mat4> joints = {glm::mat4(1.0f), rotationZ(90.0f)};
  const SkinnedVertex v = dualQuaternionSkin(joints, {0, 1, 0, 0}, {0.5f, 0.5f, 0, 0}, {1, 0, 0}, kZ, {1, 0, 0});
  const float h = std::sqrt(0.5f);
  expectNear(v.position, {h, h, 0});
  expectNear(v.normal, kZ);
  expectNear(v.tangent, {h, h, 0});
}

TEST(SkinReference, TranslationsBlendLinearly) {
  const std::vector<glm::mat4> joints = {glm::translate(glm::mat4(1.0f), {2, 0, 0}),
                                         glm::translate(glm::mat4(1.0f), {0, 4, 0})};
  const SkinnedVertex v = dualQuaternionSkin(joints, {0, 1, 0, 0}, {0.25f, 0.75f, 0, 0}, {0, 0, 0}, kZ, {1, 0, 0});
  expectNear(v.position, {0.5f, 3.0f, 0});  // 0.25 (2,0,0) + 0.75 (0,4,0)
}

TEST(SkinReference, TheHemisphereRuleTakesTheShortArc) {
  // 350 degrees about z is -10 degrees the long way: its quaternion has w = cos 175 < 0, so the
  // rule negates it and the halfway pose is -5 degrees (without it, the blend is near 180).
  const std::vector<glm::mat4> joints = {glm::mat4(1.0f), rotationZ(350.0f)};
  const SkinnedVertex v = dualQuaternionSkin(joints, {0, 1, 0, 0}, {0.5f, 0.5f, 0, 0}, {1, 0, 0}, kZ, {1, 0, 0});
  const float a = glm::radians(-5.0f);
  expectNear(v.position, {std::cos(a), std::sin(a), 0});
}

TEST(SkinReference, AnyOneJointIsReproducedExactly) {
  // A rotated, non-uniformly scaled and sheared joint with weight 1: the polar split puts it
  // back together, positions by J and normals by J's inverse transpose (then unit).
  glm::mat4 j = glm::translate(glm::mat4(1.0f), {1, -2, 3}) * rotationZ(30.0f) *
                glm::scale(glm::mat4(1.0f), {2.0f, 0.5f, 3.0f});
  j[1][0] += 0.4f;  // shear: y feeds x
  const glm::vec3 p(0.3f, -1.2f, 0.7f), n = glm::normalize(glm::vec3(1, 2, 2)), t(1, 0, 0);
  const SkinnedVertex v = dualQuaternionSkin({j}, {0, 0, 0, 0}, {1, 0, 0, 0}, p, n, t);
  expectNear(v.position, glm::vec3(j * glm::vec4(p, 1.0f)), 1e-4f);
  expectNear(v.normal, glm::normalize(glm::transpose(glm::inverse(glm::mat3(j))) * n), 1e-4f);
  expectNear(v.tangent, glm::normalize(glm::mat3(j) * t), 1e-4f);
}

TEST(SkinReference, ScalesBlendLinearlyBesideTheRotation) {
  // Two joints with the same non-uniform scale diag(1, 3, 1), one turned 90 degrees: halfway,
  // the scale applies first, then the 45 degree rotation; the normal follows S^-T.
  const glm::mat4 s = glm::scale(glm::mat4(1.0f), {1.0f, 3.0f, 1.0f});
  const std::vector<glm::mat4> joints = {s, rotationZ(90.0f) * s};
  const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
  const SkinnedVertex v = dualQuaternionSkin(joints, {0, 1, 0, 0}, {0.5f, 0.5f, 0, 0}, {1, 1, 0}, n, {1, 0, 0});
  const glm::mat3 r45 = glm::mat3(rotationZ(45.0f));
  expectNear(v.position, r45 * glm::vec3(1, 3, 0));
  expectNear(v.normal, glm::normalize(r45 * glm::vec3(1, 1.0f / 3.0f, 0)));
}

}  // namespace
