// What was done is shown. render/compare
// print animation, time, camera and loader fallbacks on stderr; compare writes a heat-map
// legend; every counter has a glossary entry; inspect lists animations and cameras; time takes
// folders.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "harness/render/counter_glossary.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/hostile_cases.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::corpusDir;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

// One triangle, a perspective camera 'Cam' on a node looking at it from +Z, and an
// orthographic camera 'Ortho' on no node.
const char* kCameraGltf = R"({
  "asset": {"version": "2.0"},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "cameras": [{"name": "Cam", "type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "zfar": 100}},
              {"name": "Ortho", "type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
  "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 3]}],
  "scenes": [{"nodes": [0, 1]}],
  "scene": 0
})";

const mb::hostile::Case* findCase(const std::vector<mb::hostile::Case>& cases, int mb::LoadStats::*counter) {
  for (const auto& c : cases)
    if (c.counter == counter && c.outcome == mb::hostile::Outcome::Fallback && c.pendingFix.empty() && c.sidecars.empty())
      return &c;
  return nullptr;
}

void writeBytes(const fs::path& p, const std::vector<uint8_t>& b) {
  std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

// "the render/compare summary does not repeat animation, time and camera"
TEST(CliVisibility, RenderAndComparePrintAnimationTimeAndCamera) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_frame");
  const auto r = runMb("render skinned_tube --anim 0 --time 0.25 --size 64x64 -o " + quoted(dir / "x.png"));
  ASSERT_EQ(r.rc, 0) << r.out;
  const std::string animName = [] {
    auto scene = mb::loadScene("skinned_tube");
    return scene && !scene->animations.empty() ? scene->animations[0].name : std::string("?");
  }();
  EXPECT_TRUE(contains(r.out, "motorbench render: animation 0 '" + animName + "' (1 of ")) << r.out;
  EXPECT_TRUE(contains(r.out, "at t = 0.25 s")) << r.out;
  EXPECT_TRUE(contains(r.out, "motorbench render: camera: automatic framing")) << r.out;
  EXPECT_TRUE(contains(r.out, "motorbench render: size: 64x64")) << r.out;
  EXPECT_TRUE(contains(r.out, "motorbench render: pipeline: matrix (the default)")) << r.out;
  const auto rest = runMb("compare skinned_tube --size 64x64 -o " + quoted(dir / "c"));
  ASSERT_EQ(rest.rc, 0) << rest.out;
  EXPECT_TRUE(contains(rest.out, "motorbench compare: rest pose (no --anim/--time; the scene has")) << rest.out;

  // A glTF camera by name: its index, name and type; an orthographic one on no node says what
  // is drawn instead.
  fs::path file = dir / "camera.gltf";
  std::ofstream(file) << kCameraGltf;
  const auto cam = runMb("render " + quoted(file) + " --camera Cam --size 64x64 -o " + quoted(dir / "cam.png"));
  ASSERT_EQ(cam.rc, 0) << cam.out;
  EXPECT_TRUE(contains(cam.out, "camera: glTF camera 0 'Cam' (perspective)")) << cam.out;
  const auto ortho = runMb("render " + quoted(file) + " --camera 1 --size 64x64 -o " + quoted(dir / "o.png"));
  ASSERT_EQ(ortho.rc, 0) << ortho.out;
  EXPECT_TRUE(contains(ortho.out, "camera: glTF camera 1 'Ortho' (orthographic, drawn as perspective) is on no node: "
                                  "automatic framing instead"))
      << ortho.out;
  const auto badCam = runMb("render " + quoted(file) + " --camera Nope -o " + quoted(dir / "n.png"));
  EXPECT_EQ(badCam.rc, 2) << badCam.out;
  EXPECT_TRUE(contains(badCam.out, "(names: 'Cam', 'Ortho')")) << badCam.out;
  fs::remove_all(dir);
}

// "loader fallbacks (an image replaced by white, 64 non-finite positions dropped) are silent
// on render and compare"
TEST(CliVisibility, LoaderFallbacksAreWarnedOnRenderAndCompare) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_fallbacks");
  const auto cases = mb::hostile::allCases();
  for (auto [counter, key] : {std::pair{&mb::LoadStats::nonFinitePositions, std::string("nonFinitePositions")},
                              std::pair{&mb::LoadStats::imagesNotDecoded, std::string("imagesNotDecoded")}}) {
    const mb::hostile::Case* c = findCase(cases, counter);
    ASSERT_NE(c, nullptr) << "no hostile case exercises " << key;
    const fs::path file = dir / c->file;
    writeBytes(file, c->bytes);
    auto scene = mb::loadScene(file.string());
    ASSERT_TRUE(scene) << scene.error();
    const int count = (scene->stats).*counter;
    ASSERT_GE(count, 1);
    const std::string line = "loader fallback: " + key + " " + std::to_string(count);
    const auto r = runMb("render " + quoted(file) + " --size 32x32 -o " + quoted(dir / "r.png"));
    EXPECT_EQ(r.rc, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "motorbench render: " + line)) << c->file << "\n" << r.out;
    const auto cmp = runMb("compare " + quoted(file) + " --size 32x32 -o " + quoted(dir / "c"));
    EXPECT_EQ(cmp.rc, 0) << cmp.out;
    EXPECT_TRUE(contains(cmp.out, "motorbench compare: " + line)) << c->file << "\n" << cmp.out;
    const auto j = mb::cli_test::readJson(dir / "c" / "metrics.json");
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["loaderFallbacks"][key], count) << j["loaderFallbacks"];
  }
  // A clean scene prints no fallback line.
  const auto clean = runMb("render textured_box --size 32x32 -o " + quoted(dir / "clean.png"));
  EXPECT_FALSE(contains(clean.out, "loader fallback")) << clean.out;
  fs::remove_all(dir);
}

// "the diff heat map has no legend"
TEST(CliVisibility, CompareWritesTheHeatMapLegend) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_legend");
  const auto r = runMb("compare normal_torus -o " + quoted(dir));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  const auto& stops = j["diffLegend"]["stops"];
  ASSERT_EQ(stops.size(), 7u);
  auto legend = mb::readImage((dir / "diff_legend.png").string());
  ASSERT_TRUE(legend) << legend.error();
  ASSERT_EQ(legend->width, 32 * 7);
  ASSERT_EQ(legend->height, 32 + 16);  // the blocks, then their numbers
  auto pixel = [&](const mb::RgbaImage& img, int x, int y) {
    const uint8_t* p = &img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    return std::vector<int>{p[0], p[1], p[2]};
  };
  // The scale the heat map's documentation states: 1 step blue, 4 red, 16 yellow, 64 white.
  const std::map<int, std::vector<int>> stated = {{1, {0, 0, 255}}, {4, {255, 0, 0}}, {16, {255, 255, 0}}, {64, {255, 255, 255}}};
  for (size_t i = 0; i < stops.size(); ++i) {
    const std::vector<int> block = pixel(*legend, int(i) * 32 + 16, 16);
    EXPECT_EQ(block, stops[i]["rgb"].get<std::vector<int>>()) << "block " << i;
    const int steps = stops[i]["steps"];
    if (stated.count(steps)) EXPECT_EQ(block, stated.at(steps)) << steps << " steps";
  }
  // Each block's number of steps written under it: light text on the dark strip.
  for (size_t i = 0; i < stops.size(); ++i) {
    int light = 0;
    for (int y = 32; y < 48; ++y)
      for (int x = int(i) * 32; x < int(i) * 32 + 32; ++x) light += pixel(*legend, x, y)[0] > 160;
    EXPECT_GT(light, 5) << "no number under block " << i;
  }
  // The diff's worst pixel has the legend colour of its difference when that is a stop.
  const int steps = int(std::lround(j["metrics"]["maxError"].get<double>() * 255));
  auto diff = mb::readImage((dir / "diff.png").string());
  ASSERT_TRUE(diff);
  for (const auto& s : stops)
    if (s["steps"] == steps)
      EXPECT_EQ(pixel(*diff, j["metrics"]["maxErrorPixel"]["x"], j["metrics"]["maxErrorPixel"]["y"]),
                s["rgb"].get<std::vector<int>>());
  fs::remove_all(dir);
}

// "`zeroScalarFrames` and other counters are not explained anywhere": every counter the JSON
// files carry has a glossary entry (report and README show the glossary).
TEST(CliVisibility, EveryCounterHasAGlossaryEntry) {
  auto keysOf = [](const nlohmann::json& j) {
    std::vector<std::string> keys;
    for (const auto& [k, v] : j.items()) keys.push_back(k);
    return keys;
  };
  for (const auto& [group, json] : {std::pair{std::string("PipelineStats"), mb::toJson(mb::PipelineStats{})},
                                    std::pair{std::string("LoadStats"), mb::toJson(mb::LoadStats{})},
                                    std::pair{std::string("ImageMetrics"), mb::toJson(mb::ImageMetrics{})}})
    for (const std::string& key : keysOf(json)) {
      const mb::CounterEntry* e = mb::findCounter(group, key);
      ASSERT_NE(e, nullptr) << group << "." << key << " has no glossary entry (harness/render/counter_glossary.cpp)";
      EXPECT_GT(e->meaning.size(), 10u) << key;
    }
}

// "inspect lists animations (name, duration, channels) and cameras (type, name) in text and
// JSON".
TEST(CliVisibility, InspectListsAnimationsAndCameras) {
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

// "`time` accepts folders".
TEST(CliVisibility, TimeAcceptsAFolder) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_time");
  auto glb = mb::builtinSceneGlb("textured_box");
  ASSERT_TRUE(glb);
  fs::create_directories(dir / "scenes" / "sub");
  writeBytes(dir / "scenes" / "sub" / "box.glb", *glb);
  const auto r = runMb("time " + quoted(dir / "scenes") + " --frames 2 --warmup 0 --best-of 1 --size 32x32 --json " +
                       quoted(dir / "t.json"));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "t.json");
  ASSERT_FALSE(j.is_discarded());
  ASSERT_EQ(j["results"].size(), 1u) << j.dump(1);
  EXPECT_EQ(j["results"][0]["scene"], (dir / "scenes" / "sub" / "box.glb").string());
  fs::remove_all(dir);
}

}  // namespace
