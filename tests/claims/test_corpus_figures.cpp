// The scale statistics behind the two corpus claims (harness/report/corpus_stats.h, written by
// `motorbench inspect --json`), checked against values derived by hand: the paper's 1e-4
// relative rule, channels that change the scale or only restate it, inner nodes, the source kinds
// of a MANIFEST.tsv, each model counted once, the figures, and the corpus rows judged on them.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>

#include "harness/claims/evaluate.h"
#include "harness/figures/figure.h"
#include "harness/report/corpus_models.h"
#include "harness/report/corpus_stats.h"
#include "pipelines/scene/builtin/gltf_writer.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scale_analysis.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/claims/claims_test_support.h"

using namespace mb;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

Channel scaleChannel(int node, std::vector<glm::vec3> keys) {
  Channel c;
  c.node = node;
  c.path = AnimPath::Scale;
  for (size_t k = 0; k < keys.size(); ++k) {
    c.times.push_back(float(k));
    for (int i = 0; i < 3; ++i) c.values.push_back(keys[k][i]);
  }
  return c;
}

// A root (inner: one child) and a leaf.
Scene twoNodes(glm::vec3 rootScale, glm::vec3 leafScale) {
  Scene s;
  s.nodes.resize(2);
  s.nodes[0].children = {1};
  s.nodes[0].local.scale = rootScale;
  s.nodes[0].name = "root";
  s.nodes[1].parent = 0;
  s.nodes[1].local.scale = leafScale;
  s.roots = {0};
  return s;
}

}  // namespace

// The paper's loader check |s0/s1 - 1| or |s1/s2 - 1| > 1e-4: the reviewer's file's
// (0.997854, 0.9999999, 1) is non-uniform by 0.997854 / 0.9999999 - 1 = -2.1459e-3 (beyond the
// rule, and below 1 %); (1, 1.00005, 1) by 5e-5 (within); a zero divisor is infinite.
TEST(CorpusStatistics, PaperRuleOnHandWorkedScales) {
  EXPECT_NEAR(scaleNonUniformity({0.997854f, 0.9999999f, 1.0f}), 2.1459e-3, 2e-7);
  EXPECT_GT(scaleNonUniformity({0.997854f, 0.9999999f, 1.0f}), kSimilarityTolerance);
  EXPECT_NEAR(scaleNonUniformity({1.0f, 1.00005f, 1.0f}), 5e-5, 1e-7);
  EXPECT_LT(scaleNonUniformity({1.0f, 1.00005f, 1.0f}), kSimilarityTolerance);
  EXPECT_EQ(scaleNonUniformity({-2.0f, 2.0f, 2.0f}), 0.0);  // a mirror is uniform in magnitude
  EXPECT_EQ(scaleNonUniformity({0.0f, 1.0f, 1.0f}), 1.0);  // |0/1 - 1|
  EXPECT_TRUE(std::isinf(scaleNonUniformity({1.0f, 0.0f, 1.0f})));  // 1/0
  EXPECT_NEAR(scaleChange({1, 1, 1}, {1, 1.5f, 1}), 1.0 / 3.0, 1e-7);  // 0.5 / 1.5
  EXPECT_EQ(scaleChange({0, 0, 0}, {0, 0, 0}), 0.0);
}

// Channels: constant keys equal to the rest scale change nothing; keys differing by 5e-5 change
// nothing; keys (1,1,1) -> (2,2,2) change it uniformly; (1,1,1) -> (1,2,1) non-uniformly (and on
// the root: an inner node); a CUBICSPLINE channel is read at its values, not its tangents.
TEST(CorpusStatistics, ChangingChannelsAndInnerNodes) {
  Scene s = twoNodes({1, 1, 1}, {1, 1, 1});
  Animation a;
  a.channels.push_back(scaleChannel(1, {{1, 1, 1}, {1, 1, 1}}));
  a.channels.push_back(scaleChannel(1, {{1, 1, 1}, {1.00005f, 1.00005f, 1.00005f}}));
  s.animations.push_back(a);
  ScaleReport r = analyzeScale(s);
  EXPECT_EQ(r.scaleChannels, 2);
  EXPECT_EQ(r.changingScaleChannels, 0);
  EXPECT_EQ(r.innerNonUniformNodes, 0);

  s.animations[0].channels.push_back(scaleChannel(1, {{1, 1, 1}, {2, 2, 2}}));
  s.animations[0].channels.push_back(scaleChannel(0, {{1, 1, 1}, {1, 2, 1}}));
  r = analyzeScale(s);
  EXPECT_EQ(r.changingScaleChannels, 2);
  EXPECT_EQ(r.nonUniformChangingChannels, 1);
  EXPECT_EQ(r.innerNonUniformNodes, 1);
  EXPECT_EQ(r.innerNonUniformNode, 0);
  EXPECT_DOUBLE_EQ(r.innerNonUniformityMax, 1.0);  // |1/2 - 1| and |2/1 - 1|: the larger is 1
  EXPECT_EQ(r.innerNonUniformScale, glm::vec3(1, 2, 1));

  // A constant channel that differs from the rest scale sets a scale; it does not animate one:
  // counted apart.
  Scene rest = twoNodes({1, 1, 1}, {3, 3, 3});
  Animation b;
  b.channels.push_back(scaleChannel(1, {{1, 1, 1}, {1, 1, 1}}));
  rest.animations.push_back(b);
  EXPECT_EQ(analyzeScale(rest).changingScaleChannels, 0);
  EXPECT_EQ(analyzeScale(rest).constantScaleChannelsOffRest, 1);

  // CUBICSPLINE [in, value, out] per key: tangents of (9, 1, 9) must not count as a change.
  Scene cubic = twoNodes({1, 1, 1}, {1, 1, 1});
  Channel c = scaleChannel(1, {{9, 1, 9}, {1, 1, 1}, {9, 1, 9}, {9, 1, 9}, {1, 1, 1}, {9, 1, 9}});
  c.interpolation = Interpolation::CubicSpline;
  c.times = {0, 1};
  Animation ca;
  ca.channels.push_back(c);
  cubic.animations.push_back(ca);
  EXPECT_EQ(analyzeScale(cubic).changingScaleChannels, 0);

  // Rest pose: the reviewer's inner node is non-uniform by the 1e-4 rule (0.21 %), and a leaf's
  // non-uniform scale is not counted as inner.
  EXPECT_EQ(analyzeScale(twoNodes({0.997854f, 0.9999999f, 1.0f}, {1, 1, 1})).innerNonUniformNodes, 1);
  EXPECT_EQ(analyzeScale(twoNodes({1, 1, 1}, {1, 5, 1})).innerNonUniformNodes, 0);
}

namespace {

// A sample of 250 files given as inspect JSON in a folder with a manifest: 200 assets, 50 test
// fixtures. Changing scale in 2 assets and 10 fixtures; inner non-uniform scale in 1 asset (the
// reviewer's 0.21 %, not beyond 1 %) and 5 fixtures. The real models are the 200 assets.
json handMadeSample(const fs::path& dir) {
  std::ofstream manifest(dir / "MANIFEST.tsv");
  manifest << "output_file\tsource_repo\tkind\n";
  // The statistics of each distinct scene once (the files differ in name only).
  std::map<std::pair<int, bool>, json> stats;  // (root scale kind, animated) -> file JSON
  json files = json::array();
  for (int i = 0; i < 250; ++i) {
    const bool test = i >= 200;
    const std::string name = "f" + std::to_string(i) + ".glb";
    manifest << name << "\trepo\t" << (test ? "test" : "asset") << "\n";
    const int root = i == 7 ? 1 : test && i < 205 ? 2 : 0;
    const bool animated = i == 3 || i == 4 || (test && i >= 240);
    json& st = stats[{root, animated}];
    if (st.is_null()) {
      const glm::vec3 roots[3] = {glm::vec3(1), glm::vec3(0.997854f, 0.9999999f, 1.0f), glm::vec3(1, 3, 1)};
      Scene s = twoNodes(roots[root], {1, 1, 1});
      if (animated) {
        Animation a;
        a.channels.push_back(scaleChannel(1, {{1, 1, 1}, {2, 2, 2}}));
        s.animations.push_back(a);
      }
      st = toJson(computeFileStats(s));
    }
    files.push_back(st);
    files.back()["file"] = (dir / name).string();
  }
  return files;
}

double value(const json& figures, const std::string& name) {
  const auto f = figures::figureNamed(figures, name);
  EXPECT_TRUE(f.has_value()) << "no figure " << name;
  return f ? f->value : std::nan("");
}

claims::Claim judged(const json& graphs, const std::string& id) {
  claims::FigureSet set;
  set.figures["graphs"] = graphs;
  return mb::claims_test::only(claims::evaluateAll(claims::corpusRows(), set), id);
}

}  // namespace

TEST(CorpusStatistics, FiguresCountTheRealModelsByKind) {
  const fs::path dir = fs::temp_directory_path() / ("mb_corpus_figures_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  json files = handMadeSample(dir);
  const json kinds = report::aggregateByKind(files);
  ASSERT_TRUE(kinds.is_object());
  EXPECT_EQ(kinds["asset"]["loaded"], 200);
  EXPECT_EQ(kinds["test"]["loaded"], 50);
  EXPECT_EQ(kinds["asset"]["filesWithChangingScale"], 2);
  EXPECT_EQ(kinds["test"]["filesWithChangingScale"], 10);
  EXPECT_EQ(kinds["test"]["filesWithInnerNonUniformScale"], 5);
  const json f = report::scaleFigures(files);
  // No content hash in these hand-made stats: each file is its own model.
  EXPECT_EQ(value(f, "scale.all.files"), 250);
  EXPECT_EQ(value(f, "scale.all.models"), 250);
  EXPECT_EQ(value(f, "scale.all.animated.models"), 12);
  EXPECT_EQ(value(f, "scale.all.nonuniform_inner.models"), 6);
  EXPECT_EQ(value(f, "scale.files"), 200);
  EXPECT_EQ(value(f, "scale.models"), 200);
  EXPECT_EQ(value(f, "scale.animated.models"), 2);
  EXPECT_EQ(value(f, "scale.channel.models"), 2);
  EXPECT_EQ(value(f, "scale.nonuniform.models"), 1);
  EXPECT_EQ(value(f, "scale.nonuniform_inner.models"), 1);
  EXPECT_EQ(value(f, "scale.nonuniform_inner_beyond_1pct.models"), 0);
  EXPECT_EQ(value(f, "scale.nonuniform_leaves_only.models"), 0);
  EXPECT_EQ(value(f, "scale.kind.test.animated.models"), 10);
  EXPECT_EQ(value(f, "scale.kind.asset.models"), 200);
  EXPECT_EQ(value(f, "scale.failed.files"), 0);
  EXPECT_EQ(f["scale.animated.models"]["n"], 200);
  EXPECT_EQ(f["scale.animated.models"]["tolerance"], "0.0001 relative");
  EXPECT_NE(f["scale.models"]["scope"].get<std::string>().find("250 files of " + dir.string()), std::string::npos)
      << f["scale.models"]["scope"];

  // The kinds travel with the files (inspect writes each one's "kind"): with the manifest gone,
  // as in a clone reading results/corpus-graph.json, the fixtures are still left out.
  json annotated = files, aggregate = json::object();
  report::addCorpusAggregates(annotated, aggregate);
  EXPECT_EQ(annotated[0]["kind"], "asset");
  EXPECT_EQ(annotated[249]["kind"], "test");
  fs::remove(dir / "MANIFEST.tsv");
  EXPECT_TRUE(report::aggregateByKind(files).is_null());
  EXPECT_EQ(report::aggregateByKind(annotated)["test"]["loaded"], 50);
  EXPECT_EQ(report::scaleFigures(annotated)["scale.models"]["value"], 200);
  fs::remove_all(dir);
}

// The rows on those figures: 2 of 200 = 1.0 % changing, above 0.5 %: differs; 0 of the 1 model
// with non-uniform scale has it on leaves only: differs. Without the two changing assets and the
// 0.21 % node: 0 of 200, reproduced, and nothing non-uniform left to judge; two files cannot
// resolve 0.5 %.
TEST(CorpusStatistics, RowsJudgeTheFigures) {
  const fs::path dir = fs::temp_directory_path() / ("mb_corpus_rows_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  json files = handMadeSample(dir);
  const claims::Claim a = judged(report::scaleFigures(files), "animated_scale_corpus");
  EXPECT_EQ(a.verdict, claims::Verdict::Differs) << a.verdictText;
  EXPECT_NE(a.measured.find("1 % (2 models / 200 models)"), std::string::npos) << a.measured;  // a share, in %
  const claims::Claim l = judged(report::scaleFigures(files), "nonuniform_scale_leaves");
  EXPECT_EQ(l.verdict, claims::Verdict::Differs) << l.verdictText;
  for (int i : {3, 4, 7}) {
    FileStats st = computeFileStats(twoNodes({1, 1, 1}, {1, 1, 1}));
    st.file = files[size_t(i)]["file"];
    files[size_t(i)] = toJson(st);
  }
  EXPECT_EQ(judged(report::scaleFigures(files), "animated_scale_corpus").verdict, claims::Verdict::Reproduced);
  const claims::Claim none = judged(report::scaleFigures(files), "nonuniform_scale_leaves");
  EXPECT_EQ(none.verdict, claims::Verdict::NotMeasurable) << none.verdictText;
  EXPECT_NE(none.verdictText.find("graphs:scale.nonuniform.models is 0"), std::string::npos) << none.verdictText;
  const claims::Claim small = judged(report::scaleFigures(json::array({files[0], files[1]})), "animated_scale_corpus");
  EXPECT_EQ(small.verdict, claims::Verdict::NotMeasurable) << small.verdictText;
  EXPECT_NE(small.verdictText.find("n = 2 < 200"), std::string::npos) << small.verdictText;
  fs::remove_all(dir);
}

// A built-in scene given to inspect is not real content: counted in scale.all.*, not in scale.*.
TEST(CorpusStatistics, BuiltinScenesAreLeftOutOfTheRealModels) {
  json files = json::array();
  json builtin = toJson(computeFileStats(twoNodes({1, 2, 1}, {1, 1, 1})));
  builtin["input"] = "scaled_hierarchy";
  files.push_back(builtin);
  FileStats real = computeFileStats(twoNodes({1, 1, 1}, {1, 1, 1}));
  real.file = "corpus/a.glb";
  files.push_back(toJson(real));
  const json f = report::scaleFigures(files);
  EXPECT_EQ(value(f, "scale.all.models"), 2);
  EXPECT_EQ(value(f, "scale.all.nonuniform_inner.models"), 1);
  EXPECT_EQ(value(f, "scale.models"), 1);
  EXPECT_EQ(value(f, "scale.nonuniform_inner.models"), 0);
  EXPECT_NE(f["scale.models"]["scope"].get<std::string>().find("2 files of corpus and 1 built-in scenes"), std::string::npos)
      << f["scale.models"]["scope"];
}

// The scale statistics against scales worked by hand: a scale channel animates scale only when its
// keys change over time (constant channels, equal to the rest scale or not, are counted apart),
// and one relative tolerance (1e-4) decides non-uniformity for every statistic, so "only on
// leaves" and the inner-node count can never disagree.
TEST(ScaleDefinitions, ConstantChannelsAreCountedApartFromAnimatedOnes) {
  Scene s = twoNodes({1, 1, 1}, {1, 1, 1});
  Animation a;
  a.channels.push_back(scaleChannel(1, {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}));  // RiggedSimple's kind: all 1
  a.channels.push_back(scaleChannel(0, {{2, 2, 2}, {2, 2, 2}}));              // constant, not the rest scale 1
  a.channels.push_back(scaleChannel(1, {{1, 1, 1}, {1.5f, 1.5f, 1.5f}}));     // changes by 50 %
  a.channels.push_back(scaleChannel(1, {{1, 1, 1}, {1.00005f, 1, 1}}));       // 5e-5: within 1e-4, constant
  s.animations.push_back(a);
  const ScaleReport r = analyzeScale(s);
  EXPECT_EQ(r.scaleChannels, 4);
  EXPECT_EQ(r.changingScaleChannels, 1);
  EXPECT_EQ(r.constantScaleChannels, 3);
  EXPECT_EQ(r.constantScaleChannelsOffRest, 1);
  const nlohmann::json j = toJson(computeFileStats(s));
  EXPECT_EQ(j["scale"]["constantScaleChannels"], 3);
  const nlohmann::json agg = aggregateFileJson(nlohmann::json::array({j}));
  EXPECT_EQ(agg["filesWithChangingScale"], 1);
  EXPECT_EQ(agg["filesWithOnlyConstantScaleChannels"], 0);
}

TEST(ScaleDefinitions, OneNonUniformToleranceForLeavesAndInnerNodes) {
  // (1, 1.00005, 1): |1/1.00005 - 1| = 5.0e-5 < 1e-4 -> uniform for every statistic and for the
  // motor fallback's per-node flag alike (one similarity tolerance).
  ScaleReport r = analyzeScale(twoNodes({1, 1.00005f, 1}, {1, 1, 1}));
  EXPECT_EQ(r.innerNonUniformNodes, 0);
  EXPECT_TRUE(r.nonUniformOnlyOnLeaves);
  EXPECT_FALSE(r.nonUniformScale);
  EXPECT_FALSE(r.nodes[0].restNonUniform);
  // (1, 1.001, 1): 1e-3 > 1e-4 on the inner node -> non-uniform, not only on leaves.
  r = analyzeScale(twoNodes({1, 1.001f, 1}, {1, 1, 1}));
  EXPECT_EQ(r.innerNonUniformNodes, 1);
  EXPECT_FALSE(r.nonUniformOnlyOnLeaves);
  EXPECT_TRUE(r.nonUniformScale);
  // On the leaf only: non-uniform, only on leaves.
  r = analyzeScale(twoNodes({1, 1, 1}, {1, 1.001f, 1}));
  EXPECT_EQ(r.innerNonUniformNodes, 0);
  EXPECT_TRUE(r.nonUniformOnlyOnLeaves);
  EXPECT_TRUE(r.nonUniformScale);
}

namespace {

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

// One triangle on a node whose scale grows from 1 to 2 (when `grows`), written by GlbBuilder:
// one tightly packed buffer view per accessor, uint32 indices.
void writeBuilderGlb(const fs::path& path, const std::vector<glm::vec3>& positions, bool grows) {
  GlbBuilder b;
  MeshData m;
  m.positions = positions;
  m.normals.assign(3, glm::vec3(0, 0, 1));
  m.indices = {0, 1, 2};
  const int node = b.addNode("triangle");
  b.setMesh(node, b.addMesh("triangle", m, -1));
  b.addRoot(node);
  if (grows) b.addChannel(b.addAnimation("grow"), node, "scale", {0, 1}, {1, 1, 1, 2, 2, 2});
  auto bytes = b.writeGlb();
  ASSERT_TRUE(bytes) << bytes.error();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes->data()), std::streamsize(bytes->size()));
}

// The same triangle and animation as writeBuilderGlb(kTriangle, true) in another layout, by
// hand: a .gltf with an external .bin, the animation's data first, position and normal
// interleaved in one strided view, uint16 indices, another node name and generator.
void writeInterleavedGltf(const fs::path& path) {
  std::vector<float> bin = {0, 1, /*scale keys*/ 1, 1, 1, 2, 2, 2};
  for (const glm::vec3& p : kTriangle) bin.insert(bin.end(), {p.x, p.y, p.z, 0, 0, 1});
  const uint16_t indices[4] = {0, 1, 2, 0};  // the last one is padding
  std::ofstream b(path.parent_path() / "data.bin", std::ios::binary);
  b.write(reinterpret_cast<const char*>(bin.data()), std::streamsize(bin.size() * 4));
  b.write(reinterpret_cast<const char*>(indices), sizeof indices);
  b.close();
  const json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "written by hand"}}},
      {"buffers", {{{"uri", "data.bin"}, {"byteLength", 8 * 4 + 18 * 4 + 8}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 32}},
                       {{"buffer", 0}, {"byteOffset", 32}, {"byteLength", 72}, {"byteStride", 24}},
                       {{"buffer", 0}, {"byteOffset", 104}, {"byteLength", 6}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}, {"min", {0}}, {"max", {1}}},
                     {{"bufferView", 0}, {"byteOffset", 8}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}},
                     {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                      {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                     {{"bufferView", 1}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                     {{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"NORMAL", 3}, {"POSITION", 2}}}, {"indices", 4}}}}}}},
      {"nodes", {{{"name", "Body"}, {"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"scene", 0},
      {"animations", {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "scale"}}}}}},
                       {"samplers", {{{"input", 0}, {"output", 1}}}}}}}};
  std::ofstream(path) << gltf.dump(1);
}

}  // namespace

// Duplicate models: files of the same mesh content are one model. A corpus of three files written
// here: a.glb and b.gltf hold the same triangle (and the same growing scale) in different
// layouts, names and generators; c.glb a different triangle that does not animate. Expected by
// construction: 3 files, 2 distinct models, and the growing scale counted once, 1 of 2 models
// (per file it would be 2 of 3).
TEST(CorpusStatistics, DuplicateModelsAreCountedOnce) {
  const fs::path dir = fs::temp_directory_path() / ("mb_corpus_models_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  writeBuilderGlb(dir / "a.glb", kTriangle, true);
  writeInterleavedGltf(dir / "b.gltf");
  writeBuilderGlb(dir / "c.glb", {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, false);
  json files = json::array();
  for (const char* name : {"a.glb", "b.gltf", "c.glb"}) {  // as inspect writes each file
    auto scene = loadScene((dir / name).string());
    ASSERT_TRUE(scene) << scene.error();
    FileStats st = computeFileStats(*scene);
    st.file = (dir / name).string();
    files.push_back(toJson(st));
    files.back()["contentHash"] = report::contentHash(*scene);
  }
  EXPECT_EQ(files[0]["contentHash"], files[1]["contentHash"]);
  EXPECT_NE(files[0]["contentHash"], files[2]["contentHash"]);
  const json f = report::scaleFigures(files);
  EXPECT_EQ(value(f, "scale.all.files"), 3);
  EXPECT_EQ(value(f, "scale.all.models"), 2);
  EXPECT_EQ(value(f, "scale.all.animated.models"), 1);
  EXPECT_EQ(value(f, "scale.all.channel.models"), 1);
  EXPECT_NE(f["scale.all.models"]["definition"].get<std::string>().find(report::kSameModelDefinition), std::string::npos);
  const json models = report::toJson(report::distinctModels(files));
  ASSERT_EQ(models["largestDuplicateGroups"].size(), 1u) << models;
  EXPECT_EQ(models["largestDuplicateGroups"][0], json({(dir / "a.glb").string(), (dir / "b.gltf").string()}));
  EXPECT_EQ(report::filesAndModels(report::distinctModels(files)), "3 files, 2 distinct models");
  fs::remove_all(dir);
}

// Without meshes (../shared/corpus-graph) an animated or skinned graph is the content: the same
// nodes and keys are one model whatever the node names, other keys or another rest scale another;
// a static graph identifies nothing (no hash: a model of its own); with meshes the graph does not
// count.
TEST(CorpusStatistics, GraphOnlyFilesHashTheirGraph) {
  const Scene s = twoNodes({1, 1, 1}, {1, 1, 1});
  EXPECT_EQ(report::contentHash(s), "");
  const auto animated = [](glm::vec3 rootScale, glm::vec3 key) {
    Scene a = twoNodes(rootScale, {1, 1, 1});
    a.animations.push_back(Animation{});
    a.animations[0].channels.push_back(scaleChannel(1, {{1, 1, 1}, key}));
    return a;
  };
  const std::string hash = report::contentHash(animated({1, 1, 1}, {2, 2, 2}));
  EXPECT_EQ(hash.size(), 16u);
  Scene renamed = animated({1, 1, 1}, {2, 2, 2});
  renamed.nodes[1].name = "leaf";
  EXPECT_EQ(report::contentHash(renamed), hash);
  EXPECT_NE(report::contentHash(animated({1, 1, 1}, {2, 2, 3})), hash);
  EXPECT_NE(report::contentHash(animated({1, 2, 1}, {2, 2, 2})), hash);

  const auto meshed = [](Scene scene, glm::vec3 corner) {
    scene.meshes.push_back(Mesh{});
    scene.meshes[0].primitives.push_back(Primitive{});
    scene.meshes[0].primitives[0].positions = {kTriangle[0], kTriangle[1], corner};
    return scene;
  };
  const std::string meshHash = report::contentHash(meshed(s, kTriangle[2]));
  EXPECT_EQ(meshHash.size(), 16u);
  EXPECT_EQ(report::contentHash(meshed(animated({1, 2, 1}, {2, 2, 3}), kTriangle[2])), meshHash);
  EXPECT_NE(report::contentHash(meshed(s, {0, 2, 0})), meshHash);
}

// Every figure a corpus row reads is one inspect writes (graphs:) or one the corpus report holds
// (corpus:, results/corpus/report.json as committed: a report's figures, harness/document).
TEST(CorpusStatistics, EveryReferenceIsAFigureOfItsSource) {
  FileStats st = computeFileStats(twoNodes({1, 1, 1}, {1, 1, 1}));
  st.file = "corpus/a.glb";
  const json graphs = report::scaleFigures(json::array({toJson(st)}));
  // The committed report, searched as text for each figure's key (parsing it costs 0.3 s).
  std::ifstream in(fs::path(MB_SOURCE_DIR) / "results" / "corpus" / "report.json");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string corpus = text.str();
  for (const claims::ClaimRow& row : claims::corpusRows())
    for (const claims::Evidence& e : row.evidence)
      for (const std::string& ref : {e.value, e.over}) {
        if (ref.empty()) continue;
        const std::string source = ref.substr(0, ref.find(':')), name = ref.substr(ref.find(':') + 1);
        if (source == "graphs") {
          EXPECT_TRUE(graphs.contains(name)) << row.id << ": " << ref;
        } else if (source == "corpus") {
          if (corpus.empty()) continue;  // a checkout without results/
          EXPECT_NE(corpus.find("\"" + name + "\": {"), std::string::npos) << row.id << ": " << ref;
        } else {
          ADD_FAILURE() << row.id << " reads " << ref << ": not a corpus source";
        }
      }
}
