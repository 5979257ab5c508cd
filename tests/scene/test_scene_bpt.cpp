// The BPT reader (pipelines/scene/builtin/bpt_reader.h), .bpt dispatch in loadScene, the
// MB_bezier_patches glTF primitive and the built-in scene `teapot`: the project's teapot copy
// parses to Newell's 32 patches; a generated set of malformed files fails with a message
// naming the line, without allocating for claimed-but-absent patches.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/builtin/bpt_reader.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "pipelines/scene/transform.h"

namespace fs = std::filesystem;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string teapotText() { return readFile(std::string(MB_SOURCE_DIR) + "/pipelines/scene/data/teapot.bpt"); }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string join(const std::vector<std::string>& ls) {
  std::string s;
  for (const auto& l : ls) s += l + "\n";
  return s;
}

TEST(SceneBpt, TeapotCopyParsesToNewellsPatches) {
  auto pts = mb::parseBpt(teapotText(), "teapot.bpt");
  ASSERT_TRUE(pts) << pts.error();
  ASSERT_EQ(pts->size(), 32u * 16u);
  // First and last control points of the file, read by hand.
  EXPECT_EQ((*pts)[0], glm::vec3(1.4f, 0.0f, 2.4f));
  EXPECT_EQ((*pts)[1], glm::vec3(1.4f, -0.784f, 2.4f));
  // The shared data folder's copy is the same file.
  std::string shared = readFile(std::string(MB_SOURCE_DIR) + "/../shared/data/teapot.bpt");
  if (!shared.empty()) EXPECT_EQ(shared, teapotText());
  // z is up: the lid knob's apex is the highest point, 3.15.
  float top = -1e9f;
  for (const auto& p : *pts) top = std::max(top, p.z);
  EXPECT_EQ(top, 3.15f);
}

TEST(SceneBpt, ToleratesBlankLinesAndCrLf) {
  std::string t = teapotText(), crlf;
  for (char c : t) crlf += c == '\n' ? std::string("\r\n\r\n") : std::string(1, c);
  auto pts = mb::parseBpt(crlf, "crlf.bpt");
  ASSERT_TRUE(pts) << pts.error();
  EXPECT_EQ(pts->size(), 512u);
}

struct Malformed {
  std::string name, text, expect;  // `expect`: a part of the message (the line and the reason)
};

// Generated from the teapot: each case breaks one thing at a known line.
std::vector<Malformed> malformedSet() {
  const std::vector<std::string> good = lines(teapotText());
  auto with = [&](size_t line, const std::string& replacement) {
    auto ls = good;
    ls[line - 1] = replacement;
    return join(ls);
  };
  auto truncated = [&](size_t keep) { return join({good.begin(), good.begin() + long(keep)}); };
  return {
      {"empty", "", "empty file"},
      {"truncated mid-patch", truncated(100), "line 1: 32 patches claimed, but the file has 99 more lines"},
      {"count too high", with(1, "33"), "line 1: 33 patches claimed, but the file has 544 more lines"},
      {"billion patches claimed", with(1, "1000000000"), "line 1: 1000000000 patches claimed; the limit is 1048576"},
      {"count overflows", with(1, "99999999999999999999999"), "line 1: expected the patch count"},
      {"count zero", with(1, "0"), "line 1: patch count 0"},
      {"count negative", with(1, "-3"), "line 1: patch count -3"},
      {"count not a number", with(1, "thirty-two"), "line 1: expected the patch count (one integer), found 'thirty-two'"},
      {"wrong degree", with(19, "2 2"), "line 19: patch 2 of 32: degrees 2 2 not supported"},
      {"degree line missing", with(19, "1.0 2.0 3.0"), "line 19: patch 2 of 32: expected the degrees"},
      {"text in a number", with(7, "1.3375 abc 2.53125"), "line 7: patch 1 of 32, control point 5 of 16: 'abc' is not a number"},
      {"number with junk", with(7, "1.3375 0.0x 2.53125"), "line 7: patch 1 of 32, control point 5 of 16: '0.0x' is not a number"},
      {"NaN", with(8, "nan 0 0"), "line 8: patch 1 of 32, control point 6 of 16: non-finite coordinate 'nan'"},
      {"Inf", with(8, "0 -inf 0"), "line 8: patch 1 of 32, control point 6 of 16: non-finite coordinate '-inf'"},
      {"beyond double", with(8, "0 0 1e999"), "line 8: patch 1 of 32, control point 6 of 16: '1e999' is out of range"},
      {"beyond float", with(8, "0 0 1e300"), "line 8: patch 1 of 32, control point 6 of 16: '1e300' is beyond float range"},
      {"two coordinates", with(9, "1.0 2.0"), "line 9: patch 1 of 32, control point 7 of 16: expected 3 numbers (x y z), found 2"},
      {"four coordinates", with(9, "1 2 3 4"), "found 4 fields"},
      {"trailing content", teapotText() + "3 3\n",
       "line " + std::to_string(good.size() + 1) + ": unexpected content after the last patch ('3')"},
      {"binary garbage", std::string("\x01\xff\xfe\n", 4), "line 1: expected the patch count"},
  };
}

TEST(SceneBpt, MalformedFilesFailNamingTheLine) {
  for (const Malformed& m : malformedSet()) {
    SCOPED_TRACE(m.name);
    auto r = mb::parseBpt(m.text, "bad.bpt");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().rfind("bad.bpt: ", 0), 0u) << r.error();
    EXPECT_NE(r.error().find(m.expect), std::string::npos) << r.error();
  }
}

TEST(SceneBpt, LoadSceneDispatchesOnTheExtension) {
  fs::path dir = fs::temp_directory_path() / ("mb_scene_bpt_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "pot.BPT") << teapotText();
  std::ofstream(dir / "bad.bpt") << "2\n3 3\n";
  auto s = mb::loadScene((dir / "pot.BPT").string());
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->meshes.size(), 1u);
  EXPECT_EQ(s->meshes[0].primitives[0].patchPoints.size(), 512u);
  EXPECT_TRUE(s->meshes[0].primitives[0].positions.empty());
  EXPECT_TRUE(s->materials[0].doubleSided);
  // The root turns the file's +Z up to +Y.
  glm::vec3 up = glm::mat3_cast(s->nodes[0].local.rotation) * glm::vec3(0, 0, 1);
  EXPECT_NEAR(up.y, 1.0f, 1e-6f);
  auto bad = mb::loadScene((dir / "bad.bpt").string());
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("bad.bpt: line 1: 2 patches claimed"), std::string::npos) << bad.error();
  auto missing = mb::loadScene((dir / "none.bpt").string());
  EXPECT_NE(missing.error().find("no such file"), std::string::npos);
  fs::remove_all(dir);
}

TEST(SceneBpt, BuiltinTeapotSplitsBodyAndLidOnTwoNodes) {
  auto s = mb::loadScene("teapot");
  ASSERT_TRUE(s) << s.error();
  EXPECT_TRUE(s->unsupported.empty());
  ASSERT_EQ(s->meshes.size(), 2u);
  auto pts = mb::parseBpt(teapotText(), "teapot.bpt");
  ASSERT_TRUE(pts);
  const auto& body = s->meshes[0].primitives[0].patchPoints;
  const auto& lid = s->meshes[1].primitives[0].patchPoints;
  ASSERT_EQ(body.size(), 24u * 16u);
  ASSERT_EQ(lid.size(), 8u * 16u);
  // Lid = patches 21-28 of the file, body = the rest, in file order.
  EXPECT_TRUE(std::equal(lid.begin(), lid.end(), pts->begin() + 20 * 16));
  EXPECT_TRUE(std::equal(body.begin(), body.begin() + 20 * 16, pts->begin()));
  EXPECT_TRUE(std::equal(body.begin() + 20 * 16, body.end(), pts->begin() + 28 * 16));
  int bodyNode = -1, lidNode = -1;
  for (size_t n = 0; n < s->nodes.size(); ++n) {
    if (s->nodes[n].mesh == 0) bodyNode = int(n);
    if (s->nodes[n].mesh == 1) lidNode = int(n);
  }
  ASSERT_GE(bodyNode, 0);
  ASSERT_GE(lidNode, 0);
  EXPECT_EQ(s->nodes[size_t(lidNode)].parent, bodyNode) << "the lid is a child of the body";
  // Animation: at t = 2 s the body has made half a turn, the lid is 0.7 up (along the
  // teapot's up axis) and turned back by half a turn relative to the body.
  ASSERT_EQ(s->animations.size(), 1u);
  EXPECT_EQ(s->animations[0].duration, 4.0f);
  auto pose = mb::sampleAnimation(*s, 0, 2.0f);
  EXPECT_NEAR(pose[size_t(lidNode)].translation.z, 0.7f, 1e-6f);
  glm::vec3 x = glm::mat3_cast(pose[size_t(bodyNode)].rotation) * glm::vec3(1, 0, 0);
  EXPECT_NEAR(x.x, -1.0f, 1e-5f);
  glm::quat world = pose[size_t(bodyNode)].rotation * pose[size_t(lidNode)].rotation;
  EXPECT_NEAR(std::fabs(world.w), 1.0f, 1e-5f) << "lid turns against the body";
}

TEST(SceneBpt, StatisticsCountPatchesAndTheirTessellatedVertices) {
  auto s = mb::loadScene("teapot");
  ASSERT_TRUE(s) << s.error();
  mb::FileStats f = mb::computeFileStats(*s);
  EXPECT_EQ(f.patches, 32);
  EXPECT_EQ(f.vertices, 0) << "no stored vertices";
  EXPECT_EQ(f.drawnVertices, 32 * 17 * 17) << "level 16: (16+1)^2 per patch";
  s->patchLevel = 64;
  EXPECT_EQ(mb::computeFileStats(*s).drawnVertices, 32 * 65 * 65);
}

TEST(SceneBpt, PatchPrimitiveExtensionIsValidated) {
  // Take the built-in's glTF and break the patch primitive's control-point count.
  auto glb = mb::builtinSceneGlb("teapot");
  ASSERT_TRUE(glb) << glb.error();
  auto ok = mb::loadGltfMemory(*glb, "teapot.glb");
  ASSERT_TRUE(ok) << ok.error();
  // "degree":[3,3] -> [2,3]: refused with the mesh and primitive named.
  std::string bytes(glb->begin(), glb->end());
  size_t at = bytes.find("\"degree\":[3,3]");
  ASSERT_NE(at, std::string::npos);
  bytes[at + 10] = '2';
  auto bad = mb::loadGltfMemory(std::vector<uint8_t>(bytes.begin(), bytes.end()), "bad.glb");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("bad.glb: mesh 0 primitive 0: MB_bezier_patches: only degree [3, 3]"), std::string::npos)
      << bad.error();
}

}  // namespace
