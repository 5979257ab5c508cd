// The rounding magnitude survey's float tie probe scales its jitter by
// (harness/render/rounding_magnitude.h): hand-derived values for a scaled, a translated, an
// instanced and an undrawn primitive over two views; and the bound it stands for, on a scene
// built like a fractured model (many small cells, each centred on its own origin, away from the
// world origin and the camera): the motor vertex stage (the shader source through the shim) and
// the matrix one (GLM in float) place every vertex within one jitter amplitude of each other
// (measured: 2.1e-5 px apart at most, 0.14 of the amplitude), while a jitter scaled by the
// primitives' own coordinates would move them 8.9 times less than the two pipelines differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/render/rounding_magnitude.h"
#include "pipelines/motor/motor_camera.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/scene/transform.h"

using namespace mb;

namespace {

// The 8 corners of a cube of half side h around `centre`, as one primitive (no triangles needed).
Primitive cube(glm::vec3 centre, float h) {
  Primitive p;
  for (int i = 0; i < 8; ++i)
    p.positions.push_back(centre + h * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  return p;
}

// A root node drawing a new mesh made of `prims`.
int addMeshNode(Scene& scene, std::vector<Primitive> prims, TRS local) {
  Mesh mesh;
  mesh.primitives = std::move(prims);
  scene.meshes.push_back(std::move(mesh));
  Node node;
  node.mesh = int(scene.meshes.size()) - 1;
  node.local = local;
  scene.nodes.push_back(node);
  scene.roots.push_back(int(scene.nodes.size()) - 1);
  return int(scene.nodes.size()) - 1;
}

View lookingDownZ(glm::vec3 eye, float znear, float zfar) {
  View v;
  v.eye = eye;
  v.znear = znear, v.zfar = zfar;
  return v;
}

}  // namespace

TEST(RoundingMagnitude, LargestOfOwnWorldAndViewCoordinatesInThePrimitivesUnits) {
  Scene scene;
  // Half side 0.01, scale 2 at x = 0.5: world coordinates up to 0.52; seen from z = 3 the view
  // depth reaches 3.02, from z = 30 30.02: in the primitive's units (/ 2) 1.51 and 15.01.
  addMeshNode(scene, {cube(glm::vec3(0.0f), 0.01f)}, TRS{glm::vec3(0.5f, 0.0f, 0.0f), {}, glm::vec3(2.0f)});
  // Instanced: the instance at x = 10 with scale 0.5 draws corners x = 10 +- 0.5: |w| = 10.5 and
  // |v| = 10.5 from either eye on the z axis but depth 30.5 from z = 30: 61 in units of 0.5.
  const int instanced = addMeshNode(scene, {cube(glm::vec3(0.0f), 1.0f)}, TRS{});
  scene.nodes[size_t(instanced)].instances = {TRS{glm::vec3(10.0f, 0.0f, 0.0f), {}, glm::vec3(0.5f)}};
  // A mesh no node draws keeps its own largest coordinate.
  Mesh undrawn;
  undrawn.primitives = {cube(glm::vec3(0.0f, 0.25f, 0.0f), 0.5f)};
  scene.meshes.push_back(undrawn);

  const std::vector<double> near = roundingMagnitudes(scene, {AnimState{}}, {lookingDownZ({0, 0, 3}, 1, 10)});
  ASSERT_EQ(near.size(), 3u);
  EXPECT_NEAR(near[0], 1.51, 1e-6);
  EXPECT_NEAR(near[1], 21.0, 1e-5);
  EXPECT_NEAR(near[2], 0.75, 1e-7);
  // Two frames: the largest over both.
  const std::vector<double> both = roundingMagnitudes(scene, {AnimState{}, AnimState{}},
                                                      {lookingDownZ({0, 0, 3}, 1, 10), lookingDownZ({0, 0, 30}, 1, 50)});
  EXPECT_NEAR(both[0], 15.01, 1e-5);
  EXPECT_NEAR(both[1], 61.0, 1e-5);
  EXPECT_NEAR(both[2], 0.75, 1e-7);
  // No frame: every primitive its own coordinates.
  const std::vector<double> none = roundingMagnitudes(scene, {}, {});
  EXPECT_NEAR(none[0], 0.01, 1e-9);
  EXPECT_NEAR(none[1], 1.0, 1e-9);
}

TEST(RoundingMagnitude, JitterCoversMatrixAndMotorOnSmallCellsAwayFromTheOrigin) {
  // 32 cells of half side 0.04, each centred on its own origin, at x 0.3..1.0, y -0.15..0.15
  // (every other one turned), seen from 2.5 away: hello-fragments.glb's proportions.
  Scene scene;
  for (int i = 0; i < 32; ++i) {
    TRS t;
    t.translation = glm::vec3(0.3f + 0.1f * float(i % 8), -0.15f + 0.1f * float(i / 8), 0.0f);
    if (i % 2) t.rotation = glm::angleAxis(0.3f + 0.1f * float(i), glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)));
    addMeshNode(scene, {cube(glm::vec3(0.0f), 0.04f)}, t);
  }
  const View view = lookingDownZ({0.65f, 0.0f, 2.5f}, 2.0f, 3.0f);
  const double height = 128, focal = 0.5 * height / std::tan(0.5 * double(view.yfov));
  const std::vector<double> rounding = roundingMagnitudes(scene, {AnimState{}}, {view});

  // Matrix: model then view-projection, in float (matrix.vs).
  std::vector<TRS> pose;
  for (const Node& n : scene.nodes) pose.push_back(n.local);
  const std::vector<glm::mat4> world = worldMatrices(scene, pose);
  const glm::mat4 viewProjection = glm::perspective(view.yfov, view.aspect, view.znear, view.zfar) *
                                   glm::inverse(glm::translate(glm::mat4(1.0f), view.eye) * glm::mat4_cast(view.orientation));
  // Motor: the world motors of the rig, the camera motor and the shader's vertex stage (motor.vs).
  const motor::Rig rig = motor::buildRig(scene);
  const std::vector<motor::ScaledMotor> motors = motor::worldPose(scene, motor::localPose(rig, pose));
  const Motor worldToView = motor::worldToViewMotor(view);
  MK& k = mk();
  const MK::vec4 constants = k.motorProjectionConstants(view.znear, view.zfar, view.yfov, view.aspect);

  double worstNew = 0, worstOld = 0, largestApart = 0;
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    for (const glm::vec3& p : scene.meshes[n].primitives[0].positions) {
      const glm::vec4 a = viewProjection * (world[n] * glm::vec4(p, 1.0f));
      const MK::mat3x4 v = k.motorRigidVertex(motors[n].motor, motors[n].scale, MK::vec3(p.x, p.y, p.z), MK::vec4(1, 0, 0, 0));
      const MK::vec4 b = k.motorWorldToClipConstants(worldToView, MK::vec3(v[0].x, v[0].y, v[0].z), constants);
      // Window pixels apart (the viewport maps NDC 1 to height / 2 pixels).
      const double apart = 0.5 * height * std::max(std::abs(double(a.x) / a.w - double(b.x) / b.w),
                                                   std::abs(double(a.y) / a.w - double(b.y) / b.w));
      // One jitter amplitude along a screen axis at this depth (sigma 1), with the rounding
      // magnitude and with the primitive's own largest coordinate (0.04).
      const double depth = double(view.eye.z) - double((world[n] * glm::vec4(p, 1.0f)).z);
      const double amplitude = kFloatTieJitter * rounding[n] * focal / depth;
      const double own = kFloatTieJitter * 0.04 * focal / depth;
      worstNew = std::max(worstNew, apart / amplitude);
      worstOld = std::max(worstOld, apart / own);
      largestApart = std::max(largestApart, apart);
    }
  // The two pipelines do differ (by float roundings: a few 1e-5 px), by less than the jitter...
  EXPECT_GT(largestApart, 1e-6);
  EXPECT_LT(largestApart, 1e-3);
  EXPECT_LT(worstNew, 1.0) << "matrix and motor " << largestApart << " px apart";
  // ... and by more than the primitives' own coordinates would have moved them.
  EXPECT_GT(worstOld, 3.0);
  for (double r : rounding) EXPECT_GT(r, 2.4);  // the view depth, about 2.5, not 0.04
}
