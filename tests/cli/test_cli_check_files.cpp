// `motorbench check FILE|DIR --golden DIR` on a user's own files: goldens recorded with --update
// pass (rc 0); a shader changed through --shader-dir fails with the images named (rc 1); a file
// whose bytes changed is named CHANGED with the hash golden.json recorded (sha256sum's) and not
// judged (rc 1); --quiet prints failures and the summary line only; --junit writes a file that a
// JUnit schema (tests/cli/junit_schema.xsd) accepts and junitparser reads with check.json's counts;
// files without --golden are refused. Two tiny glTF files written here; pipelines matrix,motor.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/cli_test_support.h"
#include "tests/support/junit_check.h"
#include "tests/support/scene_test_gltf.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::readText;
using mb::cli_test::runMb;
using mb::cli_test::junitCounts;
using mb::cli_test::junitCheckSkipped;

void writeBytes(const fs::path& file, const mbtest::Bytes& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A lit quad facing the camera; `animated`: its node slides along x over one second.
mbtest::TestGltf quad(bool animated) {
  mbtest::TestGltf g;
  const std::vector<float> pos = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::vector<float> nrm = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const std::vector<uint16_t> idx = {0, 1, 2, 0, 2, 3};
  const int p = g.accessor(g.viewOf(pos), 5126, 4, "VEC3");
  g.doc["accessors"][p]["min"] = {-1, -1, 0};
  g.doc["accessors"][p]["max"] = {1, 1, 0};
  const int n = g.accessor(g.viewOf(nrm), 5126, 4, "VEC3");
  const int i = g.accessor(g.viewOf(idx), 5123, 6, "SCALAR");
  g.meshPrimitive({{"POSITION", p}, {"NORMAL", n}}, i);
  g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.3, 0.2, 1.0}}}}}};
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  if (animated) {
    const std::vector<float> times = {0, 1}, moves = {-0.5f, 0, 0, 0.5f, 0, 0};
    const int t = g.accessor(g.viewOf(times), 5126, 2, "SCALAR");
    g.doc["accessors"][t]["min"] = {0};
    g.doc["accessors"][t]["max"] = {1};
    const int v = g.accessor(g.viewOf(moves), 5126, 2, "VEC3");
    g.doc["animations"] = nlohmann::json::parse(
        R"([{"name": "slide", "samplers": [{"input": )" + std::to_string(t) + R"(, "output": )" + std::to_string(v) +
        R"(, "interpolation": "LINEAR"}], "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}])");
  }
  return g;
}

// assets/still.gltf and assets/props/slide.glb.
fs::path writeAssets(const fs::path& root) {
  writeBytes(root / "assets" / "still.gltf", quad(false).gltf());
  writeBytes(root / "assets" / "props" / "slide.glb", quad(true).glb());
  return root / "assets";
}

// A copy of shaders/ whose lit fragment output is 80 % as bright.
fs::path dimmedShaders(const fs::path& root) {
  fs::copy(fs::path(MB_SOURCE_DIR) / "shaders", root / "shaders", fs::copy_options::recursive);
  const fs::path fs = root / "shaders" / "forward.fs";
  std::string text = readText(fs);
  const std::string from = "o_color = vec4(linearToSrgb(color)";
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << fs << " no longer contains '" << from << "'; update this test";
  if (at != std::string::npos) text.replace(at, from.size(), "o_color = vec4(0.8 * linearToSrgb(color)");
  std::ofstream(fs) << text;
  return root / "shaders";
}

// coreutils' SHA-256 of the file: the reference for golden.json's hash.
std::string sha256sum(const fs::path& file) {
  std::string out;
  mb::cli_test::runCommand("sha256sum " + quoted(file), &out);
  return out.substr(0, 64);
}

TEST(CliCheckFiles, GoldensOfAFolderPassThenAShaderChangeFailsAndAFileChangeIsNamed) {
  const fs::path root = mb::cli_test::scratchDir("check_files");
  const fs::path assets = writeAssets(root), golden = root / "goldens";
  const std::string check = "check " + quoted(assets) + " --golden " + quoted(golden) + " --pipelines matrix,motor ";
  auto r = runMb(check + "--update");
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "update: 8 images changed, 0 unchanged")) << r.out;  // (1 + 3 poses) x 2
  for (const char* f : {"still_gltf.rest.matrix.png", "props_slide_glb.rest.motor.png",
                        "props_slide_glb.slide-t0.350.matrix.png", "props_slide_glb.slide-t0.700.motor.png"})
    EXPECT_TRUE(fs::exists(golden / f)) << f << "\n" << r.out;
  const auto manifest = readJson(golden / "golden.json");
  ASSERT_FALSE(manifest.is_discarded());
  EXPECT_EQ(manifest["sources"]["props_slide_glb"]["path"], "props/slide.glb");
  EXPECT_EQ(manifest["sources"]["props_slide_glb"]["sha256"], sha256sum(assets / "props" / "slide.glb"));
  EXPECT_EQ(manifest["sources"]["still_gltf"]["sha256"], sha256sum(assets / "still.gltf"));
  for (const auto& e : manifest["images"])
    if (e["pose"] == "slide-t0.700") EXPECT_FLOAT_EQ(e["settings"]["time"].get<float>(), 0.7f) << e;

  // Unchanged: every image passes; the JUnit file has one case per image.
  r = runMb(check + "--out " + quoted(root / "pass") + " --junit " + quoted(root / "pass" / "junit.xml"));
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "check: 8 images: 8 passed, 0 warned, 0 failed, 0 errors\n")) << r.out;

  // A dimmer fragment output: every image fails, named; --quiet prints those and the summary only.
  r = runMb(check + "--quiet --shader-dir " + quoted(dimmedShaders(root)) + " --out " + quoted(root / "dim") +
            " --junit " + quoted(root / "dim" / "junit.xml"));
  EXPECT_EQ(r.rc, 1) << r.out;
  std::istringstream lines(r.out);
  int fails = 0, others = 0;
  for (std::string line; std::getline(lines, line);) (line.rfind("FAIL  ", 0) == 0 ? fails : others)++;
  EXPECT_EQ(fails, 8) << r.out;
  EXPECT_EQ(others, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "FAIL  props_slide_glb.slide-t0.350.motor.png  [exact]")) << r.out;
  EXPECT_TRUE(contains(r.out, "\ncheck: 8 images: 0 passed, 0 warned, 8 failed, 0 errors\n")) << r.out;
  const auto dim = readJson(root / "dim" / "check.json");
  ASSERT_FALSE(dim.is_discarded());
  EXPECT_EQ(dim["counts"]["fail"], 8);
  const std::string xml = readText(root / "dim" / "junit.xml");
  EXPECT_TRUE(contains(xml, "<testcase classname=\"props/slide.glb\" name=\"slide-t0.350.motor\"")) << xml;
  EXPECT_TRUE(contains(xml, "<failure message=\"")) << xml;

  // One byte more in the .glb: named as changed, its images not judged; the other file passes.
  std::ofstream(assets / "props" / "slide.glb", std::ios::app | std::ios::binary) << ' ';
  r = runMb(check + "--out " + quoted(root / "changed") + " --junit " + quoted(root / "changed" / "junit.xml"));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "CHANGED  props/slide.glb: changed since its goldens were recorded (sha256 " +
                                  manifest["sources"]["props_slide_glb"]["sha256"].get<std::string>().substr(0, 12)))
      << r.out;
  EXPECT_TRUE(contains(r.out, "run check --update")) << r.out;
  EXPECT_FALSE(contains(r.out, "props_slide_glb.rest.matrix.png  [")) << r.out;  // not judged
  EXPECT_TRUE(contains(r.out, "check: 8 images: 2 passed, 0 warned, 0 failed, 0 errors; 1 file changed since its "
                              "goldens were recorded (6 images not judged)"))
      << r.out;
  const auto changed = readJson(root / "changed" / "check.json");
  ASSERT_FALSE(changed.is_discarded());
  EXPECT_EQ(changed["counts"]["changed"], 6);
  EXPECT_EQ(changed["changedFiles"][0]["path"], "props/slide.glb");
  // Shards of the same check merge to the same verdict, the changed file kept.
  for (const char* shard : {"1/2", "2/2"})
    EXPECT_EQ(runMb(check + "--quiet --shard " + shard + " --out " + quoted(root / ("s" + std::string(1, shard[0])))).rc,
              shard[0] == '1' ? 1 : 0);  // by scene name: 1/2 props_slide_glb (changed), 2/2 still_gltf
  r = runMb("merge " + quoted(root / "s1") + " " + quoted(root / "s2") + " -o " + quoted(root / "merged"));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "merge: 2 shard(s): 8 images: 2 passed, 0 warned, 0 failed, 0 errors; 1 file changed"))
      << r.out;

  // The three JUnit files against the schema, read by junitparser: check.json's counts.
  const auto counts = junitCounts({root / "pass" / "junit.xml", root / "dim" / "junit.xml", root / "changed" / "junit.xml"});
  if (junitCheckSkipped(counts)) {
    std::printf("JUnit schema check skipped: %s\n", counts[0].c_str());
  } else {
    ASSERT_EQ(counts.size(), 3u) << ::testing::PrintToString(counts);
    EXPECT_EQ(counts[0], "8 0 0 8 0 0");
    EXPECT_EQ(counts[1], "8 8 0 8 8 0");  // dim: check.json counts.fail 8
    EXPECT_EQ(counts[2], "8 6 0 8 6 0");  // changed: check.json counts.changed 6
  }
  fs::remove_all(root);
}

// The schema is not a formality: a case without its name, and a count that is not a number, fail it.
TEST(CliCheckFiles, JunitSchemaRefusesMalformedFiles) {
  const fs::path root = mb::cli_test::scratchDir("junit_schema");
  std::ofstream(root / "nameless.xml") << "<testsuites><testsuite name=\"s\" tests=\"1\"><testcase classname=\"c\"/>"
                                          "</testsuite></testsuites>\n";
  std::ofstream(root / "count.xml") << "<testsuites><testsuite name=\"s\" tests=\"one\"></testsuite></testsuites>\n";
  const auto counts = junitCounts({root / "nameless.xml", root / "count.xml"});
  if (junitCheckSkipped(counts)) GTEST_SKIP() << counts[0];
  ASSERT_EQ(counts.size(), 2u) << ::testing::PrintToString(counts);
  for (const std::string& c : counts) EXPECT_EQ(c.rfind("ERROR", 0), 0u) << c;
  fs::remove_all(root);
}

TEST(CliCheckFiles, FilesNeedTheirOwnGoldenFolder) {
  const fs::path root = mb::cli_test::scratchDir("check_files_golden");
  const fs::path assets = writeAssets(root);
  auto r = runMb("check " + quoted(assets));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "files and folders need --golden DIR")) << r.out;
  r = runMb("check " + quoted(assets) + " --golden " + quoted(root / "none"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "record the goldens of these files first")) << r.out;
  r = runMb("check " + quoted(root / "nope.glb") + " --golden " + quoted(root / "g"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "nope.glb: no such file or folder")) << r.out;
  fs::remove_all(root);
}

}  // namespace
