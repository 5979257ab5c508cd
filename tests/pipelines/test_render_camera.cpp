// The camera rule: automatic framing keeps the posed (and skinned) bounds inside the frustum
// between near and far; a glTF camera is used as posed.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipelines/scene/camera_rule.h"

using namespace mb;

namespace {

// A unit cube (corners only; enough for bounds) on node 0, translated and scaled.
Scene cubeScene(glm::vec3 translation, glm::vec3 scale) {
  Scene s;
  s.source = "synthetic cube";
  Primitive p;
  for (int i = 0; i < 8; ++i)
    p.positions.push_back({i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f});
  p.normals.assign(8, {0, 0, 1});
  p.indices = {0, 1, 2};
  s.meshes.push_back({"cube", {p}});
  Node n;
  n.mesh = 0;
  n.local.translation = translation;
  n.local.scale = scale;
  s.nodes.push_back(n);
  s.roots = {0};
  return s;
}

// Every point projects inside clip space (with depth strictly between near and far).
void expectInside(const View& v, const std::vector<glm::vec3>& points) {
  glm::mat4 view = glm::inverse(glm::translate(glm::mat4(1.0f), v.eye) * glm::mat4_cast(v.orientation));
  glm::mat4 proj = glm::perspective(v.yfov, v.aspect, v.znear, v.zfar);
  for (glm::vec3 p : points) {
    glm::vec4 c = proj * view * glm::vec4(p, 1.0f);
    ASSERT_GT(c.w, 0.0f);
    glm::vec3 ndc = glm::vec3(c) / c.w;
    EXPECT_LT(std::abs(ndc.x), 1.0f) << p.x << "," << p.y << "," << p.z;
    EXPECT_LT(std::abs(ndc.y), 1.0f) << p.x << "," << p.y << "," << p.z;
    EXPECT_LT(std::abs(ndc.z), 1.0f) << p.x << "," << p.y << "," << p.z;
  }
}

std::vector<glm::vec3> boxCorners(glm::vec3 lo, glm::vec3 hi) {
  std::vector<glm::vec3> out;
  for (int i = 0; i < 8; ++i)
    out.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  return out;
}

}  // namespace

TEST(CameraRule, FramesRigidBoundsForSeveralAspects) {
  Scene s = cubeScene({10, -3, 2}, {4, 1, 0.5f});
  glm::vec3 half(2.0f, 0.5f, 0.25f), c(10, -3, 2);
  for (float aspect : {1.0f, 2.0f, 0.5f}) {
    View v = frameScene(s, {}, aspect);
    EXPECT_FLOAT_EQ(v.aspect, aspect);
    EXPECT_GT(v.znear, 0.0f);
    EXPECT_LT(v.znear, v.zfar);
    expectInside(v, boxCorners(c - half, c + half));
    // The camera looks at the scene from +Z, above and to the +X side.
    EXPECT_GT(v.eye.z, c.z);
    EXPECT_GT(v.eye.y, c.y);
    EXPECT_GT(v.eye.x, c.x);
  }
}

TEST(CameraRule, HierarchyAndWorldMatrices) {
  Scene s = cubeScene({0, 0, 0}, {1, 1, 1});
  Node parent;
  parent.local.translation = {0, 5, 0};
  parent.local.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  parent.children = {0};
  s.nodes.push_back(parent);
  s.nodes[0].parent = 1;
  s.nodes[0].local.translation = {2, 0, 0};
  s.roots = {1};
  std::vector<TRS> pose = {s.nodes[0].local, s.nodes[1].local};
  std::vector<glm::mat4> w = worldMatrices(s, pose);
  glm::vec3 t(w[0][3]);
  EXPECT_NEAR(t.x, 0.0f, 1e-5f);  // (2,0,0) rotated 90 degrees about Z, then up 5
  EXPECT_NEAR(t.y, 7.0f, 1e-5f);
  View v = frameScene(s, {}, 1.0f);
  expectInside(v, boxCorners(glm::vec3(-0.5f, 6.5f, -0.5f), glm::vec3(0.5f, 7.5f, 0.5f)));
}

TEST(CameraRule, SkinnedBoundsFollowTheJoints) {
  // Two vertices bound to a joint that sits 20 units up: the mesh's own positions are near the
  // origin, the skinned ones are not. Framing must contain the skinned positions.
  Scene s = cubeScene({0, 0, 0}, {1, 1, 1});
  Primitive& p = s.meshes[0].primitives[0];
  p.joints.assign(8, glm::u16vec4(0, 0, 0, 0));
  p.weights.assign(8, glm::vec4(1, 0, 0, 0));
  Node joint;
  joint.local.translation = {0, 20, 0};
  s.nodes.push_back(joint);
  s.roots = {0, 1};
  s.nodes[0].skin = 0;
  s.skins.push_back({"skin", {1}, {glm::mat4(1.0f)}, -1});
  View v = frameScene(s, {}, 1.0f);
  expectInside(v, boxCorners(glm::vec3(-0.5f, 19.5f, -0.5f), glm::vec3(0.5f, 20.5f, 0.5f)));
}

TEST(CameraRule, GltfCameraIsUsedAsPosed) {
  Scene s = cubeScene({0, 0, 0}, {1, 1, 1});
  Camera cam;
  cam.yfov = 0.6f;
  cam.znear = 0.5f;
  cam.zfar = 50.0f;
  s.cameras.push_back(cam);
  Node n;
  n.camera = 0;
  n.local.translation = {1, 2, 3};
  n.local.rotation = glm::angleAxis(0.3f, glm::normalize(glm::vec3(1, 1, 0)));
  n.local.scale = {2, 2, 2};  // scale must not leak into the orientation
  s.nodes.push_back(n);
  s.roots = {0, 1};
  View v = frameScene(s, {}, 1.5f, 0);
  EXPECT_NEAR(glm::length(v.eye - glm::vec3(1, 2, 3)), 0.0f, 1e-5f);
  EXPECT_NEAR(std::abs(glm::dot(v.orientation, n.local.rotation)), 1.0f, 1e-5f);
  EXPECT_FLOAT_EQ(v.yfov, 0.6f);
  EXPECT_FLOAT_EQ(v.znear, 0.5f);
  EXPECT_FLOAT_EQ(v.zfar, 50.0f);
  EXPECT_FLOAT_EQ(v.aspect, 1.5f);
  // A camera index no node carries falls back to framing.
  View framed = frameScene(s, {}, 1.0f, 5);
  expectInside(framed, boxCorners(glm::vec3(-0.5f), glm::vec3(0.5f)));
}

TEST(CameraRule, EmptySceneGivesDefaultView) {
  Scene s;
  View v = frameScene(s, {}, 1.0f);
  EXPECT_EQ(v.eye, View{}.eye);
}
