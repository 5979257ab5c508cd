// Render and compare say what they do not draw and what they drew another way: one line per
// feature `inspect` lists as unsupported (checked against inspect --json's own list of the same
// file), one line per non-zero fallback counter of each pipeline (checked against the counter in
// compare's metrics.json) and of the loader (checked against the loaded scene's count); every
// counter the JSON files carry has a glossary entry.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "harness/render/counter_glossary.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/hostile_cases.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/scene_test_gltf.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::runMb;
using mb::cli_test::writeBytes;

// One triangle facing the camera with a morph target (POSITION offsets) and a node extension
// no pipeline knows (the morph target is drawn; the extension is what motorbench leaves out).
fs::path unsupportedFile(const fs::path& dir) {
  mbtest::TestGltf g;
  const std::vector<float> pos = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const int acc = g.accessor(g.viewOf(pos), 5126, 3, "VEC3");
  g.doc["accessors"][acc]["min"] = {0, 0, 0};
  g.doc["accessors"][acc]["max"] = {1, 1, 0};
  const std::vector<float> offsets = {0, 0, 0, 0.5f, 0, 0, 0, 0.5f, 0};
  const int target = g.accessor(g.viewOf(offsets), 5126, 3, "VEC3");
  g.doc["accessors"][target]["min"] = {0, 0, 0};
  g.doc["accessors"][target]["max"] = {0.5, 0.5, 0};
  g.meshPrimitive({{"POSITION", acc}});
  g.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", target}}};
  g.doc["meshes"][0]["weights"] = {0.5};
  g.doc["nodes"][0]["extensions"] = {{"EXT_motorbench_test_unknown", nlohmann::json::object()}};
  const fs::path file = dir / "unsupported.gltf";
  const mbtest::Bytes bytes = g.gltf();
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return file;
}

// A hostile case whose only outcome is a counted fallback of `counter` (no pending fix, no
// side files); null when the catalogue has none.
const mb::hostile::Case* findCase(const std::vector<mb::hostile::Case>& cases, int mb::LoadStats::*counter) {
  for (const auto& c : cases)
    if (c.counter == counter && c.outcome == mb::hostile::Outcome::Fallback && c.pendingFix.empty() && c.sidecars.empty())
      return &c;
  return nullptr;
}

TEST(CliFrameNotes, RenderAndCompareListWhatInspectListsAsUnsupported) {
  const fs::path dir = mb::cli_test::scratchDir("frame_notes_unsupported");
  const fs::path file = unsupportedFile(dir);
  const auto inspect = runMb("inspect " + quoted(file) + " --json " + quoted(dir / "inspect.json"));
  ASSERT_EQ(inspect.rc, 0) << inspect.out;
  const auto j = readJson(dir / "inspect.json");
  ASSERT_FALSE(j.is_discarded()) << inspect.out;
  const nlohmann::json& list = j["files"][0]["unsupported"];
  ASSERT_TRUE(list.is_array()) << j.dump(1);
  // The node extension (the morph target is drawn, so it is not listed).
  bool extension = false;
  for (const auto& u : list) extension = extension || contains(u.get<std::string>(), "EXT_motorbench_test_unknown");
  ASSERT_TRUE(extension) << list.dump();

  const auto render = runMb("render " + quoted(file) + " --size 64x64 -o " + quoted(dir / "r.png"));
  ASSERT_EQ(render.rc, 0) << render.out;
  const auto compare = runMb("compare " + quoted(file) + " --size 64x64 -o " + quoted(dir / "c"));
  ASSERT_EQ(compare.rc, 0) << compare.out;
  for (const auto& u : list) {
    EXPECT_TRUE(contains(render.out, "motorbench render: unsupported (not drawn): " + u.get<std::string>() + "\n"))
        << u << "\n" << render.out;
    EXPECT_TRUE(contains(compare.out, "motorbench compare: unsupported (not drawn): " + u.get<std::string>() + "\n"))
        << u << "\n" << compare.out;
  }
  // One line each, no more: as many lines as inspect's entries.
  size_t lines = 0;
  for (size_t at = 0; (at = render.out.find("unsupported (not drawn): ", at)) != std::string::npos; ++at) ++lines;
  EXPECT_EQ(lines, list.size()) << render.out;
  // A file without such features prints none.
  const auto plain = runMb("render textured_box --size 32x32 -o " + quoted(dir / "box.png"));
  ASSERT_EQ(plain.rc, 0) << plain.out;
  EXPECT_FALSE(contains(plain.out, "unsupported (not drawn)")) << plain.out;
  fs::remove_all(dir);
}

// instanced_grid has instances whose scale is non-uniform or mirrored: the motor pipeline draws
// them with its scale fallback (scaleFallbackInstances). render and compare print the counter
// with its count, the same count compare writes into metrics.json's stats.
TEST(CliFrameNotes, NonZeroFallbackCountersArePrintedPerPipeline) {
  const fs::path dir = mb::cli_test::scratchDir("frame_notes_fallbacks");
  const auto compare = runMb("compare instanced_grid --pipelines matrix,motor --size 64x64 -o " + quoted(dir / "c"));
  ASSERT_NE(compare.rc, 2) << compare.out;
  const auto j = readJson(dir / "c" / "metrics.json");
  ASSERT_FALSE(j.is_discarded()) << compare.out;
  const nlohmann::json& stats = j["stats"][1];
  for (const char* k : {"linearFallbackDraws", "skinFallbackDraws", "skinFallbackJoints", "fallbackVertices"})
    EXPECT_TRUE(stats.contains(k)) << k << " missing from metrics.json stats";
  const int64_t scaled = stats["scaleFallbackInstances"];
  ASSERT_GT(scaled, 0) << "instanced_grid no longer takes the motor scale fallback";
  const std::string line = "motor fallback: scaleFallbackInstances " + std::to_string(scaled) + " instances: ";
  EXPECT_TRUE(contains(compare.out, "motorbench compare: " + line)) << compare.out;
  const auto render = runMb("render instanced_grid --pipeline motor --size 64x64 -o " + quoted(dir / "g.png"));
  ASSERT_EQ(render.rc, 0) << render.out;
  EXPECT_TRUE(contains(render.out, "motorbench render: " + line)) << render.out;
  // Every non-zero fallback counter of either pipeline has its line, and only those.
  for (int side = 0; side < 2; ++side) {
    const std::string name = j["pipelines"][side];
    for (const char* k : {"nonUniformScaleNodes", "negativeScaleNodes", "shearMatrixNodes", "zeroScalarFrames",
                          "biasedFrames", "scaleFallbackInstances", "rotorSplitVertices", "rotorUnresolvedTriangles",
                          "linearFallbackDraws", "skinFallbackDraws", "skinFallbackJoints", "fallbackVertices"}) {
      const nlohmann::json& v = j["stats"][side][k];
      const std::string counter = name + " fallback: " + k + " ";
      EXPECT_EQ(contains(compare.out, counter), v.is_number() && v.get<double>() != 0) << counter << v;
      if (v.is_number() && v.get<double>() != 0) EXPECT_TRUE(contains(compare.out, counter + v.dump() + " ")) << counter;
    }
  }
  fs::remove_all(dir);
}

// The loader's fallbacks (an image replaced by white, non-finite positions dropped) are printed
// by render and compare with their counts, and recorded in compare's metrics.json.
TEST(CliFrameNotes, LoaderFallbacksAreWarnedOnRenderAndCompare) {
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

// Every counter the JSON files carry has a glossary entry (report and README show the
// glossary).
TEST(CliGlossary, EveryCounterHasAGlossaryEntry) {
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

}  // namespace
