// Transforms real exporters write that are not one similarity per draw, drawn exactly
// by every pipeline (the motor family through its exact fallback, pipelines/motor/linear_fallback.h)
// and counted. Each case is built from a built-in scene the way the files that broke were made:
// a skin whose joint 0 carries another scale than the rest; a 100x-scaled armature under a
// matrix-given ancestor (an FBX export); a skin without `skeleton`, joints listed out of order and
// split over two roots; a non-uniform scale on an inner node above a rotated mesh; the same through
// a sheared matrix; a mesh of two primitives; joint scales with exporter noise below the similarity
// tolerance (the fast path) and a joint stretched by 1 % (the fallback). Reference: the matrix pipeline (GLM), at rest
// (bind pose = rest pose, so every skinning method must give the same image).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/linear_fallback.h"
#include "pipelines/motor/rotor_signs.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/transform.h"

using namespace mb;

namespace {

glm::mat4 localMatrix(const Node& n) { return n.hasMatrix ? n.matrix : trsMatrix(n.local); }

// World matrices by walking parents (independent of the pipelines' hierarchy passes).
glm::mat4 worldOf(const Scene& s, int n) {
  glm::mat4 m = localMatrix(s.nodes[size_t(n)]);
  for (int p = s.nodes[size_t(n)].parent; p >= 0; p = s.nodes[size_t(p)].parent)
    m = localMatrix(s.nodes[size_t(p)]) * m;
  return m;
}

int addNode(Scene& s, const std::string& name, int parent) {
  Node n;
  n.name = name;
  n.parent = parent;
  s.nodes.push_back(n);
  const int i = int(s.nodes.size()) - 1;
  if (parent >= 0) s.nodes[size_t(parent)].children.push_back(i);
  else s.roots.push_back(i);
  return i;
}

void reparent(Scene& s, int n, int parent) {
  const int old = s.nodes[size_t(n)].parent;
  auto drop = [n](std::vector<int>& v) { v.erase(std::remove(v.begin(), v.end(), n), v.end()); };
  if (old >= 0) drop(s.nodes[size_t(old)].children);
  else drop(s.roots);
  s.nodes[size_t(n)].parent = parent;
  if (parent >= 0) s.nodes[size_t(parent)].children.push_back(n);
  else s.roots.push_back(n);
}

// Bind pose = rest pose: inverse bind = inverse(joint world) * mesh node world.
void rebind(Scene& s) {
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (s.nodes[n].skin < 0) continue;
    Skin& skin = s.skins[size_t(s.nodes[n].skin)];
    skin.inverseBind.resize(skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j)
      skin.inverseBind[j] = glm::inverse(worldOf(s, skin.joints[j])) * worldOf(s, int(n));
  }
}

Scene load(const std::string& name) {
  auto s = loadScene(name);
  EXPECT_TRUE(s) << s.error();
  return s ? s.take() : Scene{};
}

int tubeNode(const Scene& s) {
  for (size_t n = 0; n < s.nodes.size(); ++n)
    if (s.nodes[n].skin >= 0) return int(n);
  return -1;
}

// A root joint at scale 100 listed first, influencing no vertex (exporters list the armature's
// root that way): joint 0's scale is not the skin's.
Scene perJointScales() {
  Scene s = load("skinned_tube");
  const Skin& skin = s.skins[0];
  const int root = addNode(s, "armature_root", -1);
  s.nodes[size_t(root)].local.scale = glm::vec3(100.0f);
  reparent(s, skin.joints[0], root);
  s.nodes[size_t(skin.joints[0])].local.scale = glm::vec3(0.01f);
  s.skins[0].joints.insert(s.skins[0].joints.begin(), root);
  for (Mesh& m : s.meshes)
    for (Primitive& p : m.primitives)
      for (glm::u16vec4& j : p.joints) j += glm::u16vec4(1);
  rebind(s);
  s.skins[0].inverseBind[0] = glm::mat4(1.0f);  // the unused root keeps the identity
  return s;
}

// An FBX-style export: a matrix-given ancestor turning -90 degrees about x and scaling by 0.01
// above an armature scaled 100x (turned back) that holds the joints and the mesh node.
Scene scaledArmature() {
  Scene s = load("skinned_tube");
  const int fbx = addNode(s, "fbx_root", -1);
  Node& f = s.nodes[size_t(fbx)];
  f.hasMatrix = true;
  f.matrix = glm::rotate(glm::mat4(1.0f), -1.5707963f, glm::vec3(1, 0, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.01f));
  f.local.rotation = glm::angleAxis(-1.5707963f, glm::vec3(1, 0, 0));
  f.local.scale = glm::vec3(0.01f);
  const int armature = addNode(s, "armature", fbx);
  s.nodes[size_t(armature)].local.scale = glm::vec3(100.0f);
  s.nodes[size_t(armature)].local.rotation = glm::angleAxis(1.5707963f, glm::vec3(1, 0, 0));
  reparent(s, s.skins[0].joints[0], armature);
  reparent(s, tubeNode(s), armature);
  rebind(s);
  return s;
}

// No skeleton; the joints listed tip first; the chain cut in two under a second root placed
// where the cut joint's parent was (so the rest shape is unchanged).
Scene twoRoots() {
  Scene s = load("skinned_tube");
  Skin& skin = s.skins[0];
  skin.skeleton = -1;
  const int cut = skin.joints[3];
  const glm::mat4 parentWorld = worldOf(s, s.nodes[size_t(cut)].parent);
  const int root2 = addNode(s, "second_root", -1);
  s.nodes[size_t(root2)].local.translation = glm::vec3(parentWorld[3]);
  reparent(s, cut, root2);
  std::vector<int> reversed(skin.joints.rbegin(), skin.joints.rend());
  const size_t count = skin.joints.size();
  skin.joints = reversed;
  for (Mesh& m : s.meshes)
    for (Primitive& p : m.primitives)
      for (glm::u16vec4& j : p.joints)
        for (int c = 0; c < 4; ++c) j[c] = uint16_t(count - 1 - j[c]);
  rebind(s);
  return s;
}

// The tube's mesh node and joints under an armature with a non-uniform scale, the mesh node and
// the first joint turned 30 degrees about z below it: every joint world and the mesh node's world
// are not similarities.
Scene skinUnderNonUniform() {
  Scene s = load("skinned_tube");
  const int armature = addNode(s, "armature", -1);
  s.nodes[size_t(armature)].local.scale = glm::vec3(1.0f, 1.5f, 0.6f);
  const glm::quat turn = glm::angleAxis(0.5235988f, glm::vec3(0, 0, 1));
  reparent(s, s.skins[0].joints[0], armature);
  reparent(s, tubeNode(s), armature);
  s.nodes[size_t(s.skins[0].joints[0])].local.rotation = turn;
  s.nodes[size_t(tubeNode(s))].local.rotation = turn;
  rebind(s);
  return s;
}

// normal_torus's mesh node turned about z and x below a node scaled (2, 0.5, 1): the world is not
// a similarity (the paper assumes non-uniform scale only on leaves).
Scene innerNonUniform(bool shearMatrix) {
  Scene s = load("normal_torus");
  int mesh = -1;
  for (size_t n = 0; n < s.nodes.size(); ++n)
    if (s.nodes[n].mesh >= 0) mesh = int(n);
  const int parent = addNode(s, "stretch", -1);
  if (shearMatrix) {
    Node& p = s.nodes[size_t(parent)];
    p.hasMatrix = true;
    p.matrixHasShear = true;
    p.matrix = glm::mat4(1.0f);
    p.matrix[1][0] = 0.6f;  // x += 0.6 y
    p.matrix[2][1] = -0.3f;
  } else {
    s.nodes[size_t(parent)].local.scale = glm::vec3(2.0f, 0.5f, 1.0f);
  }
  reparent(s, mesh, parent);
  s.nodes[size_t(mesh)].local.rotation =
      glm::angleAxis(0.7f, glm::vec3(0, 0, 1)) * glm::angleAxis(0.5f, glm::vec3(1, 0, 0));
  return s;
}

// normal_torus's mesh with a second primitive: the first moved aside, sharing the material.
Scene twoPrimitives() {
  Scene s = load("normal_torus");
  Mesh& m = s.meshes[0];
  Primitive second = m.primitives[0];
  for (glm::vec3& p : second.positions) p = glm::vec3(p.x * 0.5f + 1.2f, p.y * 0.5f, p.z * 0.5f);
  m.primitives.push_back(second);
  return s;
}

// Exporter noise (the paper's cow.glb: node scales 1.2e-5 from uniform, inverse binds as far
// off): every joint's scale 1.8e-5 from uniform, the binds made from those noisy worlds. Below
// kSimilarityTolerance: the fast path, and no visible error.
Scene noisyJointScales() {
  Scene s = load("skinned_tube");
  for (int j : s.skins[0].joints) s.nodes[size_t(j)].local.scale = glm::vec3(1.0f + 1.2e-5f, 1.0f - 0.6e-5f, 1.0f);
  rebind(s);
  return s;
}

// A joint stretched 1 % along x: a real non-uniform scale above the joints below it.
Scene onePercentJoint() {
  Scene s = load("skinned_tube");
  s.nodes[size_t(s.skins[0].joints[1])].local.scale = glm::vec3(1.01f, 1.0f, 1.0f);
  rebind(s);
  return s;
}

struct Case {
  const char* name;
  Scene (*make)();
  bool skinFallback;   // the motor family must take the per-joint fallback
  bool linearFallback; // ... the rigid one
};

Scene innerScale() { return innerNonUniform(false); }
Scene innerShear() { return innerNonUniform(true); }

const Case kCases[] = {
    {"per_joint_scales", perJointScales, true, false},
    {"scaled_armature", scaledArmature, false, false},
    {"two_roots_no_skeleton", twoRoots, false, false},
    {"skin_under_non_uniform", skinUnderNonUniform, true, false},
    {"inner_non_uniform", innerScale, false, true},
    {"inner_shear_matrix", innerShear, false, true},
    {"two_primitives", twoPrimitives, false, false},
    {"noisy_joint_scales", noisyJointScales, false, false},
    {"one_percent_joint", onePercentJoint, true, false},
};

bool motorFamily(const std::string& p) { return p.rfind("motor", 0) == 0 || p == "hybrid"; }

class ExactFallback : public ::testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(ExactFallback, MatchesMatrixAtRest) {
  const Case& c = kCases[std::get<0>(GetParam())];
  const std::string pipeline = std::get<1>(GetParam());
  const Scene scene = c.make();
  FrameSettings settings;
  settings.width = settings.height = 128;
  auto a = renderFrame(scene, "matrix", settings);
  auto b = renderFrame(scene, pipeline, settings);
  ASSERT_TRUE(a) << a.error();
  ASSERT_TRUE(b) << b.error();
  const int64_t da = drawnPixels(a->image), db = drawnPixels(b->image);
  ASSERT_GT(da, 500) << "the matrix pipeline must draw the case";
  EXPECT_LE(std::llabs(da - db), da / 100) << c.name << ": drawn pixels matrix " << da << " vs " << db;
  auto m = compareImages(a->image, b->image);
  ASSERT_TRUE(m) << m.error();
  EXPECT_GE(m->psnr, 50.0) << c.name << " " << pipeline << ": PSNR " << m->psnr;
  if (pipeline.rfind("motor", 0) == 0) {  // the GPU motor path counts what it took
    EXPECT_EQ(b->stats.skinFallbackDraws > 0, c.skinFallback) << c.name;
    EXPECT_EQ(b->stats.linearFallbackDraws > 0, c.linearFallback) << c.name;
    if (c.skinFallback || c.linearFallback) EXPECT_GT(b->stats.fallbackVertices, 0u);
  }
}

std::vector<std::string> pipelinesButMatrix() {
  std::vector<std::string> out = pipelineNames();
  out.erase(out.begin());
  return out;
}

INSTANTIATE_TEST_SUITE_P(Cases, ExactFallback,
                         ::testing::Combine(::testing::Range(0, int(std::size(kCases))),
                                            ::testing::ValuesIn(pipelinesButMatrix())),
                         [](const auto& info) {
                           return std::string(kCases[std::get<0>(info.param)].name) + "_" + std::get<1>(info.param);
                         });

// Real multi-primitive files (../shared/corpus-wide, when present): motor_cf stopped with map::at
// on every mesh of more than one primitive. Every pipeline draws them; the full-precision ones
// within 50 dB of matrix, every one within 1 % of its drawn pixels.
TEST(ExactFallbackRealFiles, MultiPrimitiveFilesInEveryPipeline) {
  const std::string root = std::string(MB_SOURCE_DIR) + "/../shared/corpus-wide/";
  const char* files[] = {"vpenades+SharpGLTF/examples/Example1.glb",
                         "KhronosGroup+glTF-Blender-IO/tests/roundtrip/22_material_slot_merge/22_material_slot_merge.gltf",
                         "trebeljahr+quaternius-showcase/public/glb/platformer_game_pack/Enemy.glb"};
  int tried = 0;
  for (const char* f : files) {
    auto scene = loadScene(root + f);
    if (!scene) continue;
    ++tried;
    int primitives = 0;
    for (const Mesh& m : scene->meshes) primitives = std::max(primitives, int(m.primitives.size()));
    EXPECT_GT(primitives, 1) << f;
    FrameSettings settings;
    settings.width = settings.height = 96;
    auto a = renderFrame(*scene, "matrix", settings);
    ASSERT_TRUE(a) << a.error();
    for (const std::string& p : pipelineNames()) {
      auto b = renderFrame(*scene, p, settings);
      ASSERT_TRUE(b) << f << " " << p << ": " << b.error();
      const int64_t da = drawnPixels(a->image), db = drawnPixels(b->image);
      EXPECT_GT(db, 0) << f << " " << p;
      EXPECT_LE(std::llabs(da - db), da / 100) << f << " " << p << ": " << da << " vs " << db;
      if (p == "matrix_c" || p == "motor_c" || p == "motor_cf") continue;  // int16 positions: corpus-check's bound
      auto m = compareImages(a->image, b->image);
      ASSERT_TRUE(m) << m.error();
      EXPECT_GE(m->psnr, 50.0) << f << " " << p;
    }
  }
  if (tried == 0) GTEST_SKIP() << "../shared/corpus-wide not present";
}

// motor_cf: a triangle whose corner frames turn by more than 180 degrees has no signs
// that put its rotors in one hemisphere; its fragments interpolated a shortened rotor (a frame none
// of its corners has). Such triangles are moved after the others and extract the frame per vertex
// as motor_c does. A normal-mapped quad whose corner tangents turn 0, 120 and 240 degrees about the
// normal: every triangle unresolved, motor_cf then draws motor_c's image.
Scene turningFrames() {
  Scene s = load("normal_torus");
  Primitive q;
  const glm::vec3 corners[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const uint32_t tris[6] = {0, 1, 2, 0, 2, 3};
  for (int k = 0; k < 6; ++k) {
    const glm::vec3 p = corners[tris[k]];
    const float a = 2.0943951f * float(k % 3);  // 120 degrees per corner
    q.positions.push_back(p);
    q.normals.emplace_back(0, 0, 1);
    q.tangents.emplace_back(std::cos(a), std::sin(a), 0.0f, 1.0f);
    q.uv0.emplace_back(0.5f * (p.x + 1.0f), 0.5f * (p.y + 1.0f));
    q.indices.push_back(uint32_t(k));
  }
  q.material = s.meshes[0].primitives[0].material;
  q.hadTangents = true;
  s.meshes[0].primitives = {q};
  return s;
}

TEST(FragmentRotorUnresolved, TrianglesTurningPastHalfATurnExtractPerVertex) {
  const Scene scene = turningFrames();
  std::vector<glm::vec4> rotors;
  for (const glm::vec4& t : scene.meshes[0].primitives[0].tangents) {
    const float a = std::atan2(t.y, t.x);  // rotor of a turn by a about z: (cos a/2, 0, 0, sin a/2)
    rotors.emplace_back(std::cos(0.5f * a), 0.0f, 0.0f, std::sin(0.5f * a));
  }
  Primitive mixed = scene.meshes[0].primitives[0];
  // A third triangle whose corners agree, listed first: it stays first and interpolable.
  for (int k = 0; k < 3; ++k) {
    mixed.positions.push_back(mixed.positions[size_t(k)]);
    mixed.normals.push_back(mixed.normals[size_t(k)]);
    mixed.tangents.emplace_back(1, 0, 0, 1);
    mixed.uv0.push_back(mixed.uv0[size_t(k)]);
    rotors.emplace_back(1, 0, 0, 0);
  }
  mixed.indices.insert(mixed.indices.begin(), {6, 7, 8});
  const motor::SignedRotors signs = motor::signRotorsForInterpolation(mixed, rotors);
  EXPECT_EQ(signs.unresolvedTriangles, 2);
  EXPECT_EQ(signs.interpolableIndices, 3u);
  ASSERT_EQ(signs.primitive.indices.size(), 9u);
  EXPECT_EQ(signs.primitive.indices[0], 6u);

  FrameSettings settings;
  settings.width = settings.height = 128;
  auto c = renderFrame(scene, "motor_c", settings);
  auto cf = renderFrame(scene, "motor_cf", settings);
  ASSERT_TRUE(c) << c.error();
  ASSERT_TRUE(cf) << cf.error();
  EXPECT_EQ(cf->stats.rotorUnresolvedTriangles, 2);
  ASSERT_GT(drawnPixels(c->image), 1000);
  auto m = compareImages(c->image, cf->image);
  ASSERT_TRUE(m) << m.error();
  EXPECT_GE(m->psnr, 50.0) << "motor_cf's unresolved triangles should extract per vertex as motor_c";
}

// linearFromAffine against GLM: motor(linear x) rebuilds every seeded affine map, linear is
// symmetric (the polar stretch), normalLinear its inverse-transpose, and a similarity s R gives
// linear = s I.
TEST(LinearFallback, PolarFactorsRebuildTheMatrix) {
  std::mt19937 rng(34);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  for (int i = 0; i < 2000; ++i) {
    glm::mat4 a(1.0f);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) a[c][r] = u(rng);
    if (std::fabs(glm::determinant(glm::mat3(a))) < 0.05f) continue;
    const motor::LinearTransform t = motor::linearFromAffine(a);
    const glm::mat4 rebuilt = companion::motorToMatrix(t.motor) * glm::mat4(t.linear);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) ASSERT_NEAR(rebuilt[c][r], a[c][r], 2e-4f) << i;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) {
        ASSERT_NEAR(t.linear[c][r], t.linear[r][c], 1e-4f) << i;
        ASSERT_NEAR(t.normalLinear[c][r], glm::transpose(glm::inverse(t.linear))[c][r], 1e-3f) << i;
      }
  }
  const glm::mat4 similarity = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                               glm::rotate(glm::mat4(1.0f), 0.8f, glm::normalize(glm::vec3(1, 1, 0))) *
                               glm::scale(glm::mat4(1.0f), glm::vec3(-0.25f));
  const motor::LinearTransform t = motor::linearFromAffine(similarity);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(t.linear[c][r], c == r ? -0.25f : 0.0f, 1e-6f);
}

}  // namespace
