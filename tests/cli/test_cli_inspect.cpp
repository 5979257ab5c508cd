// `motorbench inspect`: what it lists of a file (animations with their durations and channels,
// cameras, in text and JSON); over a folder, its progress, --summary's aggregate alone, an empty
// file named as empty and a folder of broken files counted without "0/0"; on the conformance
// cases (tests/hostile/README.md), valid files tinygltf 2.7 refuses load (exit 0), a network
// buffer URI and minVersion 2.1 fail naming the file (exit 1, the others still reported), and
// each invalid-but-drawable file lists its repair on its "fallbacks" line and in the JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/hostile_cases.h"
#include "tests/support/cli_parallel.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using namespace mb::cli_test;

const mb::hostile::Case& caseNamed(const std::vector<mb::hostile::Case>& all, const std::string& file) {
  for (const auto& c : all)
    if (c.file == file) return c;
  throw std::runtime_error("no hostile case " + file);
}

// The lines inspect printed for `file` (from its name line to the next file's).
std::string block(const std::string& out, const std::string& file) {
  const size_t at = out.find(file + "\n");
  if (at == std::string::npos) return "";
  const size_t end = out.find("\n/", at + file.size() + 1);
  return out.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// inspect lists animations (name, duration, channels) and cameras (type, name) in text and
// JSON.
TEST(CliInspect, InspectListsAnimationsAndCameras) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_inspect");
  std::ofstream(dir / "camera.gltf") << kCameraGltf;
  const auto r = runMb("inspect skinned_tube " + quoted(dir / "camera.gltf") + " --json " + quoted(dir / "i.json"));
  ASSERT_EQ(r.rc, 0) << r.out;
  auto facts = mb::builtinSceneFacts("skinned_tube");
  ASSERT_TRUE(facts) << facts.error();
  auto scene = mb::loadScene("skinned_tube");
  ASSERT_TRUE(scene);
  const auto j = mb::cli_test::readJson(dir / "i.json");
  ASSERT_FALSE(j.is_discarded());
  const auto& anims = j["files"][0]["animationList"];
  ASSERT_EQ(int(anims.size()), facts->animations);
  int channels = 0;
  for (size_t i = 0; i < anims.size(); ++i) {
    channels += anims[i]["channels"].get<int>();
    EXPECT_EQ(anims[i]["name"], scene->animations[i].name);
    char line[200];
    std::snprintf(line, sizeof line, "  animation %zu '%s': %.3f s, %d channels", i, scene->animations[i].name.c_str(),
                  double(scene->animations[i].duration), anims[i]["channels"].get<int>());
    EXPECT_TRUE(contains(r.out, line)) << line << "\n" << r.out;
  }
  EXPECT_EQ(channels, facts->channels);
  const auto& cams = j["files"][1]["cameraList"];
  ASSERT_EQ(cams.size(), 2u);
  EXPECT_EQ(cams[0]["name"], "Cam");
  EXPECT_EQ(cams[0]["type"], "perspective");
  EXPECT_EQ(cams[1]["type"], "orthographic");
  EXPECT_TRUE(contains(r.out, "  camera 0 'Cam': perspective\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "  camera 1 'Ortho': orthographic\n")) << r.out;
  fs::remove_all(dir);
}

// inspect over a folder: progress on stderr (first and last file, the time left), --summary
// prints the aggregate alone and the failed file on stderr; a 0-byte .glb is "empty file".
TEST(CliInspect, InspectFolderProgressSummaryAndAnEmptyFile) {
  const fs::path dir = mb::cli_test::scratchDir("traps_inspect");
  for (const char* name : {"normal_torus", "textured_box", "crowd"}) {
    auto glb = mb::builtinSceneGlb(name);
    ASSERT_TRUE(glb) << glb.error();
    std::ofstream(dir / (std::string(name) + ".glb"), std::ios::binary)
        .write(reinterpret_cast<const char*>(glb->data()), std::streamsize(glb->size()));
  }
  std::ofstream(dir / "empty.glb").close();
  const std::string mb = mb::cli_test::motorbench();
  const std::vector<Ran> ran = mb::cli_test::runAll(
      dir, {"{ " + mb + "inspect --summary " + quoted(dir) + " 2> err.txt; }", mb + "render nope.glb -o x.png"});
  const std::string& out = ran[0].out;  // stdout only
  const std::string err = mb::cli_test::readText(dir / "err.txt");
  EXPECT_EQ(ran[0].rc, 1) << out << err;  // one input failed
  EXPECT_TRUE(contains(out, "aggregate over 4 files: 3 loaded, 1 failed")) << out;
  EXPECT_FALSE(contains(out, "  geometry ")) << out;  // no file's own lines
  EXPECT_FALSE(contains(out, "FAILED")) << out;
  EXPECT_TRUE(contains(err, "inspect: 1/4 files inspected (")) << err;
  EXPECT_TRUE(contains(err, " left")) << err;  // the estimate
  EXPECT_TRUE(contains(err, "inspect: 4/4 files inspected (")) << err;
  EXPECT_TRUE(contains(err, "inspect: FAILED " + (dir / "empty.glb").string() + ": empty file (0 bytes)")) << err;
  EXPECT_FALSE(contains(err, "magic")) << err;
  // The missing-file error lists every name a scene can be (morph_torus included).
  const std::string& missing = ran[1].out;
  EXPECT_EQ(ran[1].rc, 2) << missing;
  std::vector<std::string> names = mb::builtinSceneNames();
  for (const auto* more : {&mb::goldenOnlySceneNames(), &mb::curvedSceneNames()}) names.insert(names.end(), more->begin(), more->end());
  for (const std::string& n : names) EXPECT_TRUE(contains(missing, n)) << n << "\n" << missing;
  EXPECT_TRUE(contains(missing, "morph_torus")) << missing;
  fs::remove_all(dir);
}

// A folder whose files all fail to load prints its aggregate without a share of zero files.
TEST(CliInputText, InspectOfOnlyBrokenFilesPrintsNoZeroOverZero) {
  const fs::path dir = mb::cli_test::scratchDir("input_broken");
  std::ofstream(dir / "a.gltf") << "{ not json";
  std::ofstream(dir / "b.glb") << "not a glb";
  const auto r = runMb("inspect " + quoted(dir));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "aggregate over 2 files: 0 loaded, 2 failed")) << r.out;
  EXPECT_FALSE(contains(r.out, "0/0 files")) << r.out;
  EXPECT_TRUE(contains(r.out, "- (no file loaded)")) << r.out;
  fs::remove_all(dir);
}

TEST(CliConformance, InspectLoadsValidFilesAndListsRepairsOfInvalidOnes) {
  const auto all = mb::hostile::allCases();
  const fs::path dir = scratchDir("conformance");
  const std::vector<std::string> valid = {"whole_number_floats.glb", "indices_without_bufferview.glb",
                                          "unread_buffer_without_uri.gltf", "glb_placeholder_buffer.glb",
                                          "datauri_percent_encoded.gltf"};
  const std::map<std::string, std::string> repaired = {{"accessor_bounds_wrong.glb", "accessorBoundsMismatch"},
                                                       {"anim_times_decreasing.glb", "keyframeTimesNotIncreasing"},
                                                       {"anim_zero_quaternions.glb", "rotationKeysNormalised"},
                                                       {"camera_zfar_below_znear.glb", "camerasRepaired"}};
  auto write = [&](const std::string& sub, const std::string& file) {
    fs::create_directories(dir / sub);
    const auto& c = caseNamed(all, file);
    std::ofstream(dir / sub / file, std::ios::binary).write(reinterpret_cast<const char*>(c.bytes.data()),
                                                             std::streamsize(c.bytes.size()));
    return (dir / sub / file).string();
  };
  for (const auto& f : valid) write("valid", f);
  std::map<std::string, std::string> paths;
  for (const auto& [f, counter] : repaired) paths[f] = write("valid", f);

  std::string out;
  int rc = runCommand(motorbench() + "inspect " + quoted(dir / "valid") + " --json " + quoted(dir / "inspect.json") + " 2>&1",
                      &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_EQ(out.find("FAILED"), std::string::npos) << out;
  const nlohmann::json j = readJson(dir / "inspect.json");
  ASSERT_EQ(j["files"].size(), valid.size() + repaired.size()) << out;
  for (const auto& [f, counter] : repaired) {
    auto scene = mb::loadScene(paths[f]);
    ASSERT_TRUE(scene.ok()) << scene.error();
    const int n = mb::toJson(scene->stats)[counter].get<int>();
    ASSERT_GE(n, 1) << f;
    const std::string text = block(out, paths[f]);
    ASSERT_FALSE(text.empty()) << f << " not reported:\n" << out;
    const size_t line = text.find("  fallbacks   ");
    ASSERT_NE(line, std::string::npos) << text;
    EXPECT_NE(text.substr(line, text.find('\n', line) - line).find(counter + " " + std::to_string(n)), std::string::npos)
        << f << ": fallbacks line lacks " << counter << " " << n << ":\n" << text;
    bool inJson = false;
    for (const auto& file : j["files"])
      if (file["file"] == paths[f]) inJson = file["fallbacks"][counter] == n;
    EXPECT_TRUE(inJson) << f << ": JSON fallbacks lack " << counter;
  }

  // Errors that stay: each names its file; the other inputs are still reported; exit 1.
  const std::string http = write("errors", "buffer_uri_http.gltf"), future = write("errors", "min_version_2_1.gltf");
  rc = runCommand(motorbench() + "inspect " + quoted(dir / "errors") + " " + quoted(dir / "valid" / valid[0]) + " 2>&1", &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("FAILED      " + http + ": buffer 0: uri 'http://example.com/quad.bin' is not a relative path"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("FAILED      " + future + ": unsupported glTF minVersion 2.1"), std::string::npos) << out;
  EXPECT_NE(out.find("2 of 3 input(s) failed"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
