// Conformance: valid glTF 2.0 files that tinygltf 2.7 refuses load and give
// the Scene their plain equivalent gives (pipelines/scene/repair/conformance.h); non-file URIs and
// minVersion > 2.0 stay errors naming the file; invalid but drawable files load with a counted
// repair (LoadStats). Each case is one generated file.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/gltf_builder.h"
#include "tests/support/scene_test_gltf.h"

namespace mb {
namespace {

using mbtest::Bytes;
using mbtest::TestGltf;
using nlohmann::json;

constexpr int kFloat = 5126, kUByte = 5121, kUShort = 5123;

Bytes bytesOf(const std::string& s) { return {s.begin(), s.end()}; }

// A textured, animated quad with a camera: every integer-typed property of glTF 2.0's core
// schema that the loader reads appears at least once (byteStride, sampler filters, texCoord...).
TestGltf richDoc() {
  TestGltf g;
  const std::vector<float> pos = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const int p = g.accessor(g.viewOf(pos, 12), kFloat, 4, "VEC3");
  g.doc["accessors"][p]["min"] = {0, 0, 0};
  g.doc["accessors"][p]["max"] = {1, 1, 0};
  const int n = g.accessor(g.viewOf(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}), kFloat, 4, "VEC3");
  const int uv = g.accessor(g.viewOf(std::vector<float>{0, 0, 1, 0, 0, 1, 1, 1}), kFloat, 4, "VEC2");
  const int idx = g.accessor(g.viewOf(std::vector<uint16_t>{0, 1, 2, 2, 1, 3}), kUShort, 6, "SCALAR");
  const int in = g.accessor(g.viewOf(std::vector<float>{0, 2}), kFloat, 2, "SCALAR");
  g.doc["accessors"][in]["min"] = {0};
  g.doc["accessors"][in]["max"] = {2};
  const int out = g.accessor(g.viewOf(std::vector<float>{0, 0, 0, 1, 2, 3}), kFloat, 2, "VEC3");
  g.meshPrimitive({{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", uv}}, idx);
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 0}}}}}}};
  g.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  g.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33071}, {"wrapT", 33648}}};
  g.doc["images"] = {{{"uri", "data:image/png;base64," + mbtest::base64(hostile::checkerPng())}}};
  g.doc["nodes"][0]["children"] = {1};
  g.doc["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 3}}});
  g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 50}}}}};
  const json channel = {{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}};
  const json sampler = {{"input", in}, {"output", out}};
  g.doc["animations"] = json::array({json{{"channels", json::array({channel})}, {"samplers", json::array({sampler})}}});
  return g;
}

// Every integer in `j` written as a float ("count": 3 -> "count": 3.0).
void floatify(json& j) {
  if (j.is_number_integer()) j = j.get<double>();
  if (j.is_structured())
    for (auto& e : j) floatify(e);
}

Bytes glbOf(const json& doc, const Bytes& bin) {
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  Bytes b = bin;
  while (b.size() % 4) b.push_back(0);
  Bytes out = {'g', 'l', 'T', 'F'};
  auto u32 = [&](size_t v) { for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i))); };
  u32(2);
  u32(12 + 8 + text.size() + (b.empty() ? 0 : 8 + b.size()));
  u32(text.size());
  u32(0x4E4F534Au);
  out.insert(out.end(), text.begin(), text.end());
  if (!b.empty()) {
    u32(b.size());
    u32(0x004E4942u);
    out.insert(out.end(), b.begin(), b.end());
  }
  return out;
}

json docOf(const Bytes& gltf) { return json::parse(gltf.begin(), gltf.end()); }
Bytes textOf(const json& doc) { return bytesOf(doc.dump()); }

// "" when the two scenes hold the same drawable content, else the first difference.
std::string difference(const Scene& a, const Scene& b) {
  if (a.meshes.size() != b.meshes.size() || a.nodes.size() != b.nodes.size()) return "mesh or node count";
  for (size_t m = 0; m < a.meshes.size(); ++m) {
    if (a.meshes[m].primitives.size() != b.meshes[m].primitives.size()) return "primitive count";
    for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
      const Primitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
      if (x.positions != y.positions) return "positions";
      if (x.normals != y.normals) return "normals";
      if (x.uv0 != y.uv0) return "uv0";
      if (x.indices != y.indices) return "indices";
      if (x.material != y.material) return "material";
    }
  }
  for (size_t n = 0; n < a.nodes.size(); ++n) {
    const Node &x = a.nodes[n], &y = b.nodes[n];
    if (x.mesh != y.mesh || x.camera != y.camera || x.parent != y.parent || x.children != y.children ||
        x.local.translation != y.local.translation)
      return "node " + std::to_string(n);
  }
  if (a.roots != b.roots) return "roots";
  if (a.materials.size() != b.materials.size() || a.textures.size() != b.textures.size()) return "materials";
  for (size_t t = 0; t < a.textures.size(); ++t)
    if (a.textures[t].image != b.textures[t].image || a.textures[t].sampler != b.textures[t].sampler) return "texture";
  for (size_t s = 0; s < a.samplers.size(); ++s)
    if (a.samplers[s].magFilter != b.samplers[s].magFilter || a.samplers[s].minFilter != b.samplers[s].minFilter ||
        a.samplers[s].wrapS != b.samplers[s].wrapS || a.samplers[s].wrapT != b.samplers[s].wrapT)
      return "sampler";
  if (a.materials.size() && a.materials[0].baseColor.texture != b.materials[0].baseColor.texture) return "baseColor";
  if (a.images.size() != b.images.size()) return "images";
  for (size_t i = 0; i < a.images.size(); ++i)
    if (a.images[i].rgba != b.images[i].rgba) return "image " + std::to_string(i);
  if (a.cameras.size() != b.cameras.size()) return "cameras";
  for (size_t c = 0; c < a.cameras.size(); ++c)
    if (a.cameras[c].yfov != b.cameras[c].yfov || a.cameras[c].znear != b.cameras[c].znear ||
        a.cameras[c].zfar != b.cameras[c].zfar)
      return "camera";
  if (a.animations.size() != b.animations.size()) return "animations";
  for (size_t i = 0; i < a.animations.size(); ++i) {
    if (a.animations[i].channels.size() != b.animations[i].channels.size()) return "channels";
    for (size_t c = 0; c < a.animations[i].channels.size(); ++c) {
      const Channel &x = a.animations[i].channels[c], &y = b.animations[i].channels[c];
      if (x.node != y.node || x.times != y.times || x.values != y.values) return "channel";
    }
  }
  if (a.unsupported != b.unsupported) return "unsupported";
  if (toJson(a.stats) != toJson(b.stats)) return "LoadStats";
  return "";
}

Scene mustLoad(const Bytes& bytes, const std::string& name) {
  auto s = loadGltfMemory(bytes, name);
  EXPECT_TRUE(s.ok()) << s.error();
  return s.ok() ? s.take() : Scene{};
}

// --- valid files tinygltf 2.7 refuses ----------------------------------------------------

TEST(Conformance, WholeNumbersWrittenAsFloatsGiveTheSameScene) {
  const TestGltf g = richDoc();
  const Scene ref = mustLoad(g.gltf(), "ref.gltf");
  ASSERT_EQ(ref.meshes.size(), 1u);
  ASSERT_EQ(ref.images.size(), 1u);
  EXPECT_EQ(ref.images[0].width, 4);
  json text = docOf(g.gltf());
  floatify(text);
  ASSERT_NE(text.dump().find("\"byteLength\":"), std::string::npos);
  ASSERT_NE(text.dump().find("\"count\":4.0"), std::string::npos) << "the file must really hold floats";
  EXPECT_EQ(difference(ref, mustLoad(textOf(text), "floats.gltf")), "");

  json binary = g.doc;
  binary["buffers"] = {{{"byteLength", g.bin.size()}}};
  floatify(binary);
  EXPECT_EQ(difference(ref, mustLoad(glbOf(binary, g.bin), "floats.glb")), "");
}

TEST(Conformance, FloatsThatAreNotWholeStayErrors) {
  json doc = docOf(richDoc().gltf());
  doc["accessors"][0]["count"] = 3.5;
  auto s = loadGltfMemory(textOf(doc), "half.gltf");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().rfind("half.gltf: ", 0), 0u) << s.error();
}

TEST(Conformance, IndicesWithoutBufferViewAreZeros) {
  TestGltf g;
  const int p = g.accessor(g.viewOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}), kFloat, 3, "VEC3");
  const int n = g.accessor(g.viewOf(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}), kFloat, 3, "VEC3");
  const int uv = g.accessor(-1, kFloat, 3, "VEC2");  // zero-filled attribute
  const int idx = g.accessor(-1, kUShort, 6, "SCALAR");
  g.meshPrimitive({{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", uv}}, idx);
  for (const auto& [name, bytes] : {std::pair{"zero_indices.gltf", g.gltf()}, std::pair{"zero_indices.glb", g.glb()}}) {
    const Scene s = mustLoad(bytes, name);
    ASSERT_EQ(s.meshes.size(), 1u) << name;
    const Primitive& prim = s.meshes[0].primitives[0];
    EXPECT_EQ(prim.indices, std::vector<uint32_t>(6, 0u)) << name;  // two triangles, all vertex 0
    EXPECT_EQ(prim.uv0, std::vector<glm::vec2>(3, glm::vec2(0.0f))) << name;
    EXPECT_EQ(prim.positions[1], glm::vec3(1, 0, 0)) << name;
  }
}

TEST(Conformance, BufferWithoutUriThatNothingReadsIsAPlaceholder) {
  const TestGltf g = richDoc();
  const Scene ref = mustLoad(g.gltf(), "ref.gltf");
  json doc = docOf(g.gltf());
  doc["buffers"].push_back({{"byteLength", 1u << 30}});  // an unread 1 GiB placeholder allocates nothing
  EXPECT_EQ(difference(ref, mustLoad(textOf(doc), "placeholder.gltf")), "");

  doc["bufferViews"][0]["buffer"] = 1;  // now read: an error naming buffer and bufferView
  doc["buffers"][1]["byteLength"] = 1000;
  auto s = loadGltfMemory(textOf(doc), "read.gltf");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "read.gltf: buffer 1 has no uri (a .gltf buffer needs one), but bufferView 0 reads it");
}

TEST(Conformance, GlbPlaceholderBuffers) {
  const TestGltf g = richDoc();
  const Scene ref = mustLoad(g.gltf(), "ref.gltf");
  // Buffer 0 without uri and no BIN chunk, nothing reads it; the data is in buffer 1.
  json doc = docOf(g.gltf());
  doc["buffers"].insert(doc["buffers"].begin(), json{{"byteLength", 16}});
  for (auto& v : doc["bufferViews"]) v["buffer"] = 1;
  EXPECT_EQ(difference(ref, mustLoad(glbOf(doc, {}), "no_bin.glb")), "");
  // A BIN chunk present, but buffer 0 (declared longer than it) unused.
  EXPECT_EQ(difference(ref, mustLoad(glbOf(doc, Bytes(8, 7)), "unused_bin.glb")), "");
  // Read without a BIN chunk, or a second uri-less buffer read: errors.
  for (auto& v : doc["bufferViews"]) v["buffer"] = 0;
  doc["buffers"][0]["byteLength"] = g.bin.size();
  auto s = loadGltfMemory(glbOf(doc, {}), "read_no_bin.glb");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "read_no_bin.glb: buffer 0 has no uri and the GLB has no BIN chunk, but bufferView 0 reads it");
  doc["buffers"][1].erase("uri");
  doc["bufferViews"][2]["buffer"] = 1;
  s = loadGltfMemory(glbOf(doc, g.bin), "second.glb");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(),
            "second.glb: buffer 1 has no uri and is not the GLB's BIN chunk (only buffer 0 is), but bufferView 2 reads it");
}

// RFC 2397: percent-encoded octets when ";base64" is absent; media type parameters; any case.
TEST(Conformance, DataUrisWithoutBase64AndWithParameters) {
  const TestGltf g = richDoc();
  const Scene ref = mustLoad(g.gltf(), "ref.gltf");
  std::string percent;
  for (uint8_t b : g.bin) {
    const bool plain = std::isalnum(b) || b == '-' || b == '_' || b == '.';
    char esc[4];
    std::snprintf(esc, sizeof esc, "%%%02X", b);
    percent += plain ? std::string(1, char(b)) : std::string(esc);
  }
  ASSERT_NE(percent.find('%'), std::string::npos);
  const std::string b64 = mbtest::base64(g.bin);
  for (const std::string& uri : {"data:application/octet-stream," + percent, "data:application/gltf-buffer," + percent,
                                 "data:application/octet-stream;name=quad.bin;base64," + b64,
                                 "DATA:Application/Octet-Stream;BASE64," + b64}) {
    json doc = docOf(g.gltf());
    doc["buffers"][0]["uri"] = uri;
    EXPECT_EQ(difference(ref, mustLoad(textOf(doc), "datauri.gltf")), "") << uri.substr(0, 60);
  }
  // The image too: a percent-encoded PNG decodes (not 1x1 white).
  json doc = docOf(g.gltf());
  std::string png;
  for (uint8_t b : hostile::checkerPng()) {
    char esc[4];
    std::snprintf(esc, sizeof esc, "%%%02X", b);
    png += esc;
  }
  doc["images"][0]["uri"] = "data:image/png," + png;
  EXPECT_EQ(difference(ref, mustLoad(textOf(doc), "image.gltf")), "");
}

TEST(Conformance, DataUrisThatAreWrongStayErrors) {
  const TestGltf g = richDoc();
  auto load = [&](const std::string& uri) {
    json doc = docOf(g.gltf());
    doc["buffers"][0]["uri"] = uri;
    auto s = loadGltfMemory(textOf(doc), "bad.gltf");
    return s.ok() ? std::string("loaded") : s.error();
  };
  EXPECT_EQ(load("data:application/octet-stream,abc"),
            "bad.gltf: buffer 0: data: URI holds 3 bytes, byteLength is " + std::to_string(g.bin.size()));
  EXPECT_EQ(load("data:text/html," + std::string(g.bin.size(), 'a')),
            "bad.gltf: buffer 0: data: URI media type 'text/html' is not application/octet-stream or application/gltf-buffer");
  EXPECT_EQ(load("data:application/octet-stream;x=1;base64,@@@@"), "bad.gltf: buffer 0: data: URI is not valid base64");
  EXPECT_EQ(load("data:application/octet-stream,%G1"), "bad.gltf: buffer 0: data: URI with a malformed %-escape");
  EXPECT_EQ(load("data:application/octet-stream"), "bad.gltf: buffer 0: malformed data: URI (no ',')");
}

TEST(Conformance, NetworkUrisAndNewerMinVersionAreErrorsNamingTheFile) {
  json doc = docOf(richDoc().gltf());
  doc["buffers"][0]["uri"] = "http://example.com/quad.bin";
  auto s = loadGltfMemory(textOf(doc), "net.gltf", "/tmp");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "net.gltf: buffer 0: uri 'http://example.com/quad.bin' is not a relative path or a data: URI "
                       "(http: is not read; only files beside the glTF and embedded data are)");
  // An image behind a network URI: not read, drawn white, said so.
  doc = docOf(richDoc().gltf());
  doc["images"][0]["uri"] = "https://example.com/checker.png";
  const Scene img = mustLoad(textOf(doc), "net_image.gltf");
  EXPECT_EQ(img.stats.imagesNotDecoded, 1);
  ASSERT_FALSE(img.unsupported.empty());
  EXPECT_EQ(img.unsupported[0], "image 0: uri 'https://example.com/checker.png' is not a relative path or a data: URI (not read)");

  doc = docOf(richDoc().gltf());
  doc["asset"] = {{"version", "2.1"}, {"minVersion", "2.1"}};
  s = loadGltfMemory(textOf(doc), "future.gltf");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "future.gltf: unsupported glTF minVersion 2.1 (this loader reads glTF 2.0)");
  doc["asset"].erase("minVersion");  // a 2.1 file a 2.0 reader may read (glTF 2.0 asset.version)
  EXPECT_TRUE(loadGltfMemory(textOf(doc), "minor.gltf").ok());
}

// --- invalid but drawable: counted ------------------------------------------------------------

TEST(Conformance, AccessorBoundsThatDisagreeAreCounted) {
  TestGltf g = richDoc();
  EXPECT_EQ(mustLoad(g.gltf(), "ok.gltf").stats.accessorBoundsMismatch, 0);
  g.doc["accessors"][0]["max"] = {1, 0.5, 0};  // data reaches y = 1
  const Scene s = mustLoad(g.gltf(), "bounds.gltf");
  EXPECT_EQ(s.stats.accessorBoundsMismatch, 1);
  EXPECT_EQ(s.meshes[0].primitives[0].positions[3], glm::vec3(1, 1, 0));  // the data is drawn
  // Normalized integers: bounds are raw values (glTF 2.0 3.6.2.5), so [0, 255] is right.
  TestGltf q = richDoc();
  const int c = q.accessor(q.viewOf(std::vector<uint8_t>{0, 0, 0, 255, 255, 255, 10, 20, 30, 40, 50, 60}), kUByte, 4,
                           "VEC3", 0, true);
  q.doc["accessors"][c]["min"] = {0, 0, 0};
  q.doc["accessors"][c]["max"] = {255, 255, 255};
  q.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = c;
  EXPECT_EQ(mustLoad(q.gltf(), "normalized.gltf").stats.accessorBoundsMismatch, 0);
  q.doc["accessors"][c]["max"] = {1, 1, 1};  // normalized-space bounds: wrong
  EXPECT_EQ(mustLoad(q.gltf(), "normalized_wrong.gltf").stats.accessorBoundsMismatch, 1);
}

TestGltf animated(const std::vector<float>& times, const std::vector<float>& values, const std::string& path) {
  TestGltf g = richDoc();
  const size_t comps = values.size() / times.size();
  const int in = g.accessor(g.viewOf(times), kFloat, times.size(), "SCALAR");
  const int out = g.accessor(g.viewOf(values), kFloat, times.size(), comps == 4 ? "VEC4" : "VEC3");
  g.doc["animations"][0]["samplers"][0] = {{"input", in}, {"output", out}};
  g.doc["animations"][0]["channels"][0]["target"]["path"] = path;
  return g;
}

TEST(Conformance, KeyframeTimesThatDoNotIncreaseAreSortedAndCounted) {
  EXPECT_EQ(mustLoad(richDoc().gltf(), "ok.gltf").stats.keyframeTimesNotIncreasing, 0);
  // Authored 0, 2, 1: drawn as 0, 1, 2 with each value moving with its time.
  const Scene s = mustLoad(animated({0, 2, 1}, {0, 0, 0, 20, 0, 0, 10, 0, 0}, "translation").gltf(), "unordered.gltf");
  EXPECT_EQ(s.stats.keyframeTimesNotIncreasing, 1);
  ASSERT_EQ(s.animations.size(), 1u);
  EXPECT_EQ(s.animations[0].channels[0].times, (std::vector<float>{0, 1, 2}));
  EXPECT_FLOAT_EQ(sampleAnimation(s, 0, 1.0f)[0].translation.x, 10.0f);
  EXPECT_FLOAT_EQ(sampleAnimation(s, 0, 1.5f)[0].translation.x, 15.0f);
  // Equal times: a jump, kept; counted (glTF requires strictly increasing).
  const Scene j = mustLoad(animated({0, 1, 1, 2}, {0, 0, 0, 1, 0, 0, 5, 0, 0, 6, 0, 0}, "translation").gltf(), "jump.gltf");
  EXPECT_EQ(j.stats.keyframeTimesNotIncreasing, 1);
  EXPECT_FLOAT_EQ(sampleAnimation(j, 0, 0.5f)[0].translation.x, 0.5f);
  EXPECT_FLOAT_EQ(sampleAnimation(j, 0, 1.5f)[0].translation.x, 5.5f);
}

TEST(Conformance, NonUnitRotationKeysAreNormalisedAndCounted) {
  // (x, y, z, w): the identity at length 2, a 90-degree turn about z at length 1 (not counted),
  // and a zero key (identity, counted).
  const float h = std::sqrt(0.5f);
  const Scene s = mustLoad(animated({0, 1, 2}, {0, 0, 0, 2, 0, 0, h, h, 0, 0, 0, 0}, "rotation").gltf(), "rot.gltf");
  EXPECT_EQ(s.stats.rotationKeysNormalised, 2);
  const glm::quat q = sampleAnimation(s, 0, 0.0f)[0].rotation;
  EXPECT_FLOAT_EQ(q.w, 1.0f);
  EXPECT_NEAR(glm::length(sampleAnimation(s, 0, 0.5f)[0].rotation), 1.0f, 1e-6f);
  // Within the validator's tolerance (int8 quantization error): not counted.
  const Scene ok = mustLoad(animated({0, 1}, {0, 0, 0, 1.005f, 0, 0, h, h}, "rotation").gltf(), "rot_ok.gltf");
  EXPECT_EQ(ok.stats.rotationKeysNormalised, 0);
}

TEST(Conformance, CamerasWithAnInvalidDepthRangeAreRepairedAndCounted) {
  EXPECT_EQ(mustLoad(richDoc().gltf(), "ok.gltf").stats.camerasRepaired, 0);
  TestGltf g = richDoc();
  g.doc["cameras"][0]["perspective"]["zfar"] = 0.05;  // below znear 0.1
  g.doc["cameras"].push_back({{"type", "perspective"}, {"perspective", {{"yfov", 0.0}, {"znear", 0.5}}}});
  g.doc["cameras"].push_back({{"type", "orthographic"},
                              {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 2}, {"zfar", 2}}}});
  g.doc["cameras"].push_back({{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.5}}}});  // valid
  const Scene s = mustLoad(g.gltf(), "cameras.gltf");
  EXPECT_EQ(s.stats.camerasRepaired, 3);
  ASSERT_EQ(s.cameras.size(), 4u);
  EXPECT_EQ(s.cameras[0].zfar, 0.0f);  // infinite
  EXPECT_FLOAT_EQ(s.cameras[0].znear, 0.1f);
  EXPECT_FLOAT_EQ(s.cameras[1].yfov, 0.8f);
  EXPECT_EQ(s.cameras[2].zfar, 0.0f);
  EXPECT_FLOAT_EQ(s.cameras[3].yfov, 1.0f);
  EXPECT_EQ(s.cameras[3].zfar, 0.0f);  // absent: infinite, as authored
}

}  // namespace
}  // namespace mb
