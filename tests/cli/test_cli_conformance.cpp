// `motorbench inspect` on the conformance cases (tests/hostile/README.md):
// valid files tinygltf 2.7 refuses load (exit 0), a network buffer URI and minVersion 2.1 fail
// naming the file (exit 1, the others still reported), and each invalid-but-drawable file lists
// its repair on its "fallbacks" line and in the JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/hostile_cases.h"
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
