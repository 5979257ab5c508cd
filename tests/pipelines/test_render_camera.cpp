// The camera rule: automatic framing keeps the posed (and skinned) bounds inside the frustum
// between near and far; a glTF camera is used as posed.
#include <gtest/gtest.h>

#include <array>
#include <string>

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

namespace {

// Clip-space position of `p` through the View (GLM's own projection for its kind).
glm::vec3 ndcOf(const View& v, glm::vec3 p) {
  const glm::mat4 view = glm::inverse(glm::translate(glm::mat4(1.0f), v.eye) * glm::mat4_cast(v.orientation));
  const glm::mat4 proj = v.orthographic
                             ? glm::ortho(-v.ymag * v.aspect, v.ymag * v.aspect, -v.ymag, v.ymag, v.znear, v.zfar)
                             : glm::perspective(v.yfov, v.aspect, v.znear, v.zfar);
  const glm::vec4 c = proj * view * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

// A triangle pair spanning the unit square across `axis`, its front facing +axis or -axis.
Scene squareScene(int axis, int facing) {
  Scene s = cubeScene({0, 0, 0}, {1, 1, 1});
  Primitive& p = s.meshes[0].primitives[0];
  p.positions.clear();
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  for (glm::vec2 c : {glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)}) {
    glm::vec3 q(0.0f);
    q[u] = c.x, q[v] = c.y;
    p.positions.push_back(q);
  }
  p.normals.assign(4, glm::vec3(0.0f));
  p.indices = facing > 0 ? std::vector<uint32_t>{0, 1, 2, 0, 2, 3} : std::vector<uint32_t>{0, 2, 1, 0, 3, 2};
  return s;
}

}  // namespace

// Fit: the tighter frame axis has points on both edges at 95 % of the half-frame (ndc +-0.95),
// the other is centred (its extremes equal and opposite), all inside near/far.
TEST(CameraRule, FitPutsTheExtremePointsAt95PercentOfTheFrame) {
  const glm::vec3 c(10, -3, 2), half(2.0f, 0.5f, 0.25f);
  Scene s = cubeScene(c, 2.0f * half);
  ASSERT_EQ(s.framing, Framing::Fit);
  for (float aspect : {1.0f, 2.0f, 0.5f}) {
    SCOPED_TRACE(aspect);
    const View v = frameScene(s, {}, aspect);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (glm::vec3 p : boxCorners(c - half, c + half)) {
      const glm::vec3 n = ndcOf(v, p);
      lo = glm::min(lo, n), hi = glm::max(hi, n);
    }
    const bool xTight = std::abs(hi.x - 0.95f) < 1e-4f;
    const int tight = xTight ? 0 : 1, other = 1 - tight;
    EXPECT_NEAR(hi[tight], 0.95f, 1e-4f);
    EXPECT_NEAR(lo[tight], -0.95f, 1e-4f);
    EXPECT_NEAR(hi[other], -lo[other], 1e-4f);
    EXPECT_LE(hi[other], 0.95f + 1e-4f);
    EXPECT_GT(lo.z, -1.0f);
    EXPECT_LT(hi.z, 1.0f);
  }
}

// A flat scene is seen from the side its front faces face: the eye on that side of the plane,
// looking at it from 54.5 degrees above it (the fixed direction's angle to a plane facing +Z:
// asin(cos 20 cos 30)); a scene that is not flat keeps the fixed direction.
TEST(CameraRule, FlatSceneIsSeenFromItsFront) {
  const float elevation = std::asin(std::cos(glm::radians(20.0f)) * std::cos(glm::radians(30.0f)));
  for (int axis = 0; axis < 3; ++axis)
    for (int facing : {1, -1}) {
      SCOPED_TRACE(std::to_string(axis) + " " + std::to_string(facing));
      const View v = frameScene(squareScene(axis, facing), {}, 1.0f);
      const glm::vec3 back = v.orientation * glm::vec3(0, 0, 1);  // towards the eye
      EXPECT_NEAR(back[axis] * float(facing), std::sin(elevation), 1e-5f);
      EXPECT_GT(v.eye[axis] * float(facing), 0.0f);
      if (axis != 1) {
        EXPECT_NEAR((v.orientation * glm::vec3(0, 1, 0)).y, std::cos(glm::radians(20.0f)), 1e-5f)
            << "a vertical plane keeps world up";
      }
    }
  // A closed slab 6 % thick (a floor tile): flat, its area vectors cancel, seen from above.
  Scene slab = cubeScene({0, 0, 0}, {1, 0.06f, 1});
  std::vector<uint32_t>& indices = slab.meshes[0].primitives[0].indices;
  indices.clear();
  const std::vector<glm::vec3>& corners = slab.meshes[0].primitives[0].positions;
  for (std::array<uint32_t, 4> f : {std::array<uint32_t, 4>{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6},
                                    {0, 1, 3, 2}, {4, 5, 7, 6}}) {
    const glm::vec3 centre = 0.25f * (corners[f[0]] + corners[f[1]] + corners[f[2]] + corners[f[3]]);
    const glm::vec3 normal = glm::cross(corners[f[1]] - corners[f[0]], corners[f[2]] - corners[f[0]]);
    const bool outward = glm::dot(normal, centre) > 0.0f;
    for (uint32_t i : outward ? std::vector<uint32_t>{0, 1, 2, 0, 2, 3} : std::vector<uint32_t>{0, 2, 1, 0, 3, 2})
      indices.push_back(f[i]);
  }
  const View above = frameScene(slab, {}, 1.0f);
  EXPECT_NEAR((above.orientation * glm::vec3(0, 0, 1)).y, std::sin(elevation), 1e-5f);
  EXPECT_GT(above.eye.y, 0.0f);
  const View fixed = frameScene(cubeScene({0, 0, 0}, {1, 1, 1}), {}, 1.0f);
  const glm::vec3 expected = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0)) *
                             glm::angleAxis(glm::radians(-20.0f), glm::vec3(1, 0, 0)) * glm::vec3(0, 0, 1);
  EXPECT_NEAR(glm::length(fixed.orientation * glm::vec3(0, 0, 1) - expected), 0.0f, 1e-6f);
}

// Framing::BoundingSphere (the built-in scenes): the box's bounding sphere from the fixed
// direction at radius / sin(yfov / 2), near 0.9 (d - r), far 1.1 (d + r).
TEST(CameraRule, BoundingSphereFramingAsTheBuiltinScenesHaveIt) {
  Scene s = cubeScene({1, 2, 3}, {2, 2, 2});
  s.framing = Framing::BoundingSphere;
  const View v = frameScene(s, {}, 1.0f);
  const float r = std::sqrt(3.0f), d = r / std::sin(0.4f);
  EXPECT_NEAR(glm::length(v.eye - glm::vec3(1, 2, 3)), d, 1e-4f);
  EXPECT_NEAR(v.znear, 0.9f * (d - r), 1e-4f);
  EXPECT_NEAR(v.zfar, 1.1f * (d + r), 1e-4f);
}

// A glTF orthographic camera: glTF 2.0's projection with xmag = ymag * aspect, depth -1..1.
TEST(CameraRule, OrthographicCameraProjectsAsTheSpecSays) {
  Scene s = cubeScene({0, 0, 0}, {1, 1, 1});
  Camera cam;
  cam.perspective = false;
  cam.xmag = 3.0f, cam.ymag = 2.0f, cam.znear = 0.0f, cam.zfar = 8.0f;
  s.cameras.push_back(cam);
  Node n;
  n.camera = 0;
  n.local.translation = {0, 0, 4};
  s.nodes.push_back(n);
  s.roots = {0, 1};
  const View v = frameScene(s, {}, 1.5f, 0);
  ASSERT_TRUE(v.orthographic);
  EXPECT_FLOAT_EQ(v.ymag, 2.0f);
  EXPECT_FLOAT_EQ(v.znear, 0.0f);
  EXPECT_FLOAT_EQ(v.zfar, 8.0f);
  // glTF 2.0 3.10.3: rows (1/xmag, 0, 0, 0), (0, 1/ymag, 0, 0), (0, 0, 2/(n-f), (f+n)/(n-f)), (0, 0, 0, 1).
  const glm::mat4 p = projectionMatrix(v);
  const glm::mat4 spec(glm::vec4(1.0f / 3.0f, 0, 0, 0), glm::vec4(0, 0.5f, 0, 0), glm::vec4(0, 0, 2.0f / -8.0f, 0),
                       glm::vec4(0, 0, 8.0f / -8.0f, 1));
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) EXPECT_NEAR(p[col][row], spec[col][row], 1e-6f) << col << "," << row;
  // The corner (0.5, 0.5, 0.5), 3.5 in front of the eye: x 0.5 / 3, y 0.5 / 2, depth 2 * 3.5 / 8 - 1.
  const glm::vec3 corner = ndcOf(v, glm::vec3(0.5f));
  EXPECT_NEAR(corner.x, 0.5f / 3.0f, 1e-6f);
  EXPECT_NEAR(corner.y, 0.25f, 1e-6f);
  EXPECT_NEAR(corner.z, 2.0f * 3.5f / 8.0f - 1.0f, 1e-6f);
  // Shading looks along the view axis: its viewpoint far behind the camera, on the axis.
  const glm::vec3 eye = shadingEye(v);
  EXPECT_NEAR(eye.x, 0.0f, 1e-3f);
  EXPECT_GT(eye.z, 1e4f);
  EXPECT_EQ(shadingEye(frameScene(s, {}, 1.5f)), frameScene(s, {}, 1.5f).eye) << "perspective: the eye";
  // ymag 0 (glTF forbids it): xmag / aspect; the loader's repaired zfar (0): znear + 1e4 ymag.
  s.cameras[0].ymag = 0.0f;
  s.cameras[0].zfar = 0.0f;
  const View repaired = frameScene(s, {}, 1.5f, 0);
  EXPECT_FLOAT_EQ(repaired.ymag, 2.0f);
  EXPECT_FLOAT_EQ(repaired.zfar, 2e4f);
}
