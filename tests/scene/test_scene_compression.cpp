// Compressed geometry decoded at load into the Scene the uncompressed file gives.
// The compressed files are made here with the codecs' own encoders (tests/support/
// compressed_gltf.h) from the built-in scenes' .glb bytes, with the bytes they no longer read
// zeroed. Bounds, from the encoders' quantisation:
//  - Draco positions at 14 bits: a coordinate moves by at most half a step, extent / (2^14 - 1) / 2
//    (extent: the primitive's largest axis range, Draco's quantisation box);
//  - Draco texture coordinates at 12 bits: range / (2^12 - 1) / 2 the same way;
//  - Draco normals at 10 bits, octahedral: the grid step on the octahedron's [-1, 1]^2 square is
//    2 / (2^10 - 2); unfolding to the sphere stretches a step by at most 2 (at the fold), so the
//    direction turns by at most 2 x step = 0.0039 rad;
//  - tangents, joints and weights are not quantised (exact); meshopt without filters is lossless
//    (its TRIANGLES codec may rotate a triangle's corners, keeping the winding).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <meshoptimizer.h>
#include <webp/decode.h>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/loader.h"
#include "tests/scene/load_bytes.h"
#include "tests/support/compressed_gltf.h"

using namespace mb;
using compressed::Bytes;
using compressed::Json;

namespace {

using scene_test::load;

Bytes builtin(const std::string& name) {
  auto glb = builtinSceneGlb(name);
  EXPECT_TRUE(glb) << glb.error();
  return glb ? *glb : Bytes{};
}

// Largest axis range of a primitive's positions (Draco's quantisation box edge).
float extent(const std::vector<glm::vec3>& p) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& v : p) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

const std::vector<std::string> kTriangleScenes = {"textured_box", "normal_torus", "skinned_tube", "scaled_hierarchy"};

TEST(SceneCompression, DracoDecodesToTheUncompressedSceneWithinQuantisation) {
  for (const std::string& name : kTriangleScenes) {
    SCOPED_TRACE(name);
    const Bytes glb = builtin(name);
    const Scene a = load(glb, name + ".glb");
    const Bytes draco = compressed::dracoCompressed(glb);
    const Scene b = load(draco, name + "-draco.glb");
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    size_t primitives = 0;
    uint64_t decoded = 0;
    for (size_t m = 0; m < a.meshes.size(); ++m) {
      ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size());
      for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
        const Primitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
        ++primitives;
        ASSERT_EQ(x.positions.size(), y.positions.size());
        EXPECT_EQ(x.indices, y.indices);  // sequential connectivity keeps the order
        const float posBound = extent(x.positions) / float((1 << 14) - 1) / 2 * 1.0001f + 1e-6f;
        float posErr = 0, uvErr = 0, nrmErr = 0;
        for (size_t v = 0; v < x.positions.size(); ++v) {
          const glm::vec3 d = glm::abs(x.positions[v] - y.positions[v]);
          posErr = std::max({posErr, d.x, d.y, d.z});
          nrmErr = std::max(nrmErr, std::acos(std::clamp(glm::dot(x.normals[v], y.normals[v]), -1.0f, 1.0f)));
        }
        EXPECT_LE(posErr, posBound);
        EXPECT_LE(nrmErr, 2 * 2.0f / float((1 << 10) - 2) + 1e-3f);  // + float acos noise near 1
        ASSERT_EQ(x.uv0.size(), y.uv0.size());
        if (!x.uv0.empty()) {
          glm::vec2 lo(1e30f), hi(-1e30f);
          for (const auto& t : x.uv0) lo = glm::min(lo, t), hi = glm::max(hi, t);
          const float uvBound = std::max(hi.x - lo.x, hi.y - lo.y) / float((1 << 12) - 1) / 2 * 1.0001f + 1e-6f;
          for (size_t v = 0; v < x.uv0.size(); ++v)
            uvErr = std::max({uvErr, std::fabs(x.uv0[v].x - y.uv0[v].x), std::fabs(x.uv0[v].y - y.uv0[v].y)});
          EXPECT_LE(uvErr, uvBound);
        }
        EXPECT_EQ(x.joints, y.joints);    // integers, not quantised
        EXPECT_EQ(x.weights, y.weights);  // floats stored losslessly
        EXPECT_EQ(x.hadTangents, y.hadTangents);
      }
    }
    // What the loader decodes: 4 bytes (float or uint32) per component of every attribute and index.
    const Json doc = compressed::splitGlb(glb).json;
    for (const Json& mesh : doc["meshes"])
      for (const Json& prim : mesh["primitives"]) {
        if (!prim.contains("indices")) continue;
        for (const auto& [attr, acc] : prim["attributes"].items())
          decoded += doc["accessors"][acc.get<size_t>()]["count"].get<uint64_t>() * 4 *
                     uint64_t(compressed::typeComponents(doc["accessors"][acc.get<size_t>()]["type"]));
        decoded += doc["accessors"][prim["indices"].get<size_t>()]["count"].get<uint64_t>() * 4;
      }
    EXPECT_EQ(b.compression.dracoPrimitives, int(primitives));
    EXPECT_EQ(b.compression.dracoDecodedBytes, decoded);
    EXPECT_GT(b.compression.dracoCompressedBytes, 0u);
    EXPECT_LT(b.compression.dracoCompressedBytes, decoded);
    EXPECT_EQ(b.stats.accessorBoundsMismatch, 0);  // the declared accessors' data lives in the extension
    EXPECT_EQ(b.stats.skippedPrimitives, 0);
    for (const std::string& u : b.unsupported) EXPECT_EQ(u.find("draco"), std::string::npos) << u;
    EXPECT_EQ(whyNothingDrawn(b), "");
  }
}

TEST(SceneCompression, MeshoptIsLossless) {
  for (const std::string& name : kTriangleScenes) {
    SCOPED_TRACE(name);
    const Bytes glb = builtin(name);
    const Scene a = load(glb, name + ".glb");
    const Scene b = load(compressed::meshoptCompressed(glb), name + "-meshopt.glb");
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t m = 0; m < a.meshes.size(); ++m)
      for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
        const Primitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
        EXPECT_EQ(x.positions, y.positions);
        EXPECT_EQ(x.normals, y.normals);
        EXPECT_EQ(x.tangents, y.tangents);
        EXPECT_EQ(x.uv0, y.uv0);
        EXPECT_EQ(x.joints, y.joints);
        EXPECT_EQ(x.weights, y.weights);
        // The TRIANGLES codec may rotate a triangle's corners (same winding): compare each
        // triangle up to rotation.
        ASSERT_EQ(x.indices.size(), y.indices.size());
        for (size_t t = 0; t + 2 < x.indices.size(); t += 3) {
          const uint32_t *i = &x.indices[t], *k = &y.indices[t];
          bool same = false;
          for (int r = 0; r < 3; ++r) same = same || (i[0] == k[r] && i[1] == k[(r + 1) % 3] && i[2] == k[(r + 2) % 3]);
          EXPECT_TRUE(same) << "triangle " << t / 3;
        }
      }
    EXPECT_GT(b.compression.meshoptViews, 0);
    EXPECT_LT(b.compression.meshoptCompressedBytes, b.compression.meshoptDecodedBytes);
    EXPECT_EQ(b.stats.accessorBoundsMismatch, a.stats.accessorBoundsMismatch);
    EXPECT_EQ(b.unsupported, a.unsupported);
  }
}

// The three filters, against the encoder's inputs: octahedral normals (8-bit X/Y: a step of
// 2/254 on the square, at most 2 steps of turn), quaternion rotations (12-bit components: each
// within 1/(2^11 - 1) x sqrt(2)/2 ... bounded here by 1e-3), exponential positions (24-bit
// mantissa with a shared exponent per component: relative error <= 2^-23 of the largest).
TEST(SceneCompression, MeshoptFiltersDecode) {
  hostile::Doc d;
  const std::vector<glm::vec3> pos = {{-1.5f, -1, 0.25f}, {1, -1, 0}, {1, 1.75f, 0}, {-1, 1, -0.5f}};
  std::vector<glm::vec3> nrm = {{0, 0, 1}, {0.6f, 0, 0.8f}, {0, -0.6f, 0.8f}, {-0.48f, 0.6f, 0.64f}};
  std::vector<float> posIn(12), nrmIn(16);
  for (size_t i = 0; i < 4; ++i) {
    for (int c = 0; c < 3; ++c) posIn[i * 3 + size_t(c)] = pos[i][c], nrmIn[i * 4 + size_t(c)] = nrm[i][c];
    nrmIn[i * 4 + 3] = 0;
  }
  Bytes posF(4 * 12), nrmF(4 * 4);
  meshopt_encodeFilterExp(posF.data(), 4, 12, 24, posIn.data());
  meshopt_encodeFilterOct(nrmF.data(), 4, 4, 8, nrmIn.data());
  auto packed = [](const Bytes& raw, size_t stride) {
    Bytes out(meshopt_encodeVertexBufferBound(raw.size() / stride, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), raw.data(), raw.size() / stride, stride));
    return out;
  };
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  Bytes idxPacked(meshopt_encodeIndexBufferBound(6, 4));
  idxPacked.resize(meshopt_encodeIndexBuffer(idxPacked.data(), idxPacked.size(), idx.data(), 6));
  int views[3];
  const Bytes* data[3] = {nullptr, nullptr, &idxPacked};
  Bytes p0 = packed(posF, 12), p1 = packed(nrmF, 4);
  data[0] = &p0, data[1] = &p1;
  const size_t strides[3] = {12, 4, 4}, counts[3] = {4, 4, 6}, lengths[3] = {48, 16, 24};
  const char* modes[3] = {"ATTRIBUTES", "ATTRIBUTES", "TRIANGLES"};
  const char* filters[3] = {"EXPONENTIAL", "OCTAHEDRAL", "NONE"};
  for (int k = 0; k < 3; ++k) {
    const size_t at = d.bin.size();
    d.bin.insert(d.bin.end(), data[k]->begin(), data[k]->end());
    while (d.bin.size() % 4) d.bin.push_back(0);
    Json ext = {{"buffer", 0}, {"byteOffset", at}, {"byteLength", data[k]->size()}, {"byteStride", strides[k]},
                {"count", counts[k]}, {"mode", modes[k]}, {"filter", filters[k]}};
    Json view = {{"buffer", 1}, {"byteLength", lengths[k]}, {"extensions", {{"EXT_meshopt_compression", ext}}}};
    if (k < 2) view["byteStride"] = strides[k];
    views[k] = hostile::Doc::push(d.arr("bufferViews"), view);
  }
  const int posAcc = d.accessor(views[0], hostile::kFloat, 4, "VEC3");
  d.j["accessors"][size_t(posAcc)]["min"] = {-1.5, -1, -0.5};
  d.j["accessors"][size_t(posAcc)]["max"] = {1, 1.75, 0.25};
  const int nrmAcc = d.accessor(views[1], hostile::kByte, 4, "VEC3");
  d.j["accessors"][size_t(nrmAcc)]["normalized"] = true;
  const int idxAcc = d.accessor(views[2], hostile::kUInt, 6, "SCALAR");
  d.mesh({{"attributes", {{"POSITION", posAcc}, {"NORMAL", nrmAcc}}}, {"indices", idxAcc}});
  d.node({{"mesh", 0}});
  d.scene({0});
  d.finish();
  d.j["buffers"].push_back({{"byteLength", 88}});  // the fallback: no data
  d.j["extensionsUsed"] = {"EXT_meshopt_compression"};
  d.j["extensionsRequired"] = {"EXT_meshopt_compression"};
  const Scene s = load(hostile::toGlb(d), "filters.glb");
  ASSERT_EQ(s.meshes.size(), 1u);
  const Primitive& p = s.meshes[0].primitives[0];
  ASSERT_EQ(p.positions.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.positions[i][c], pos[i][c], 2.0f * std::ldexp(1.0f, -23)) << i;
    EXPECT_GE(glm::dot(p.normals[i], nrm[i]), std::cos(2 * 2.0f / 254)) << i;
  }
  EXPECT_EQ(p.indices, idx);
  EXPECT_EQ(s.compression.meshoptViews, 3);
  EXPECT_EQ(s.compression.meshoptDecodedBytes, 48u + 16u + 24u);
}

// A declared count other than the decoded one loads (the decoded geometry, as
// three.js draws it; tests/scene/test_scene_lenient.cpp); a component count that differs is
// still an error naming the primitive.
TEST(SceneCompression, DracoComponentMismatchNamesThePrimitive) {
  const Bytes glb = compressed::dracoCompressed(builtin("textured_box"));
  compressed::Glb g = compressed::splitGlb(glb);
  const size_t pos = g.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  g.json["accessors"][pos]["type"] = "VEC4";
  auto s = loadGltfMemory(compressed::joinGlb(g), "mismatch.glb");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("mismatch.glb: mesh 0 primitive 0: KHR_draco_mesh_compression: accessor"), std::string::npos)
      << s.error();
  EXPECT_NE(s.error().find("the Draco data has"), std::string::npos) << s.error();
}

TEST(SceneCompression, CorruptPayloadsAreErrors) {
  const Bytes draco = compressed::dracoCompressed(builtin("textured_box"));
  compressed::Glb g = compressed::splitGlb(draco);
  const Json& view = g.json["bufferViews"][g.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<size_t>()];
  for (size_t i = 0; i < view["byteLength"].get<size_t>(); ++i) g.bin[view["byteOffset"].get<size_t>() + i] = uint8_t(i * 37);
  auto s = loadGltfMemory(compressed::joinGlb(g), "garbage-draco.glb");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("KHR_draco_mesh_compression: Draco data does not decode"), std::string::npos) << s.error();

  compressed::Glb m = compressed::splitGlb(compressed::meshoptCompressed(builtin("textured_box")));
  for (Json& v : m.json["bufferViews"])
    if (v.contains("extensions")) {
      const Json& e = v["extensions"]["EXT_meshopt_compression"];
      for (size_t i = 0; i < e["byteLength"].get<size_t>(); ++i) m.bin[e["byteOffset"].get<size_t>() + i] = 0xFF;
      break;
    }
  auto t = loadGltfMemory(compressed::joinGlb(m), "garbage-meshopt.glb");
  ASSERT_FALSE(t);
  EXPECT_NE(t.error().find("EXT_meshopt_compression: ATTRIBUTES data does not decode"), std::string::npos) << t.error();
}

TEST(SceneCompression, UnalignedBinChunkIsPaddedAndCounted) {
  // The box's BIN chunk with one byte more than its buffer needs: chunk length 4k + 1.
  const Bytes glb = builtin("textured_box");
  compressed::Glb g = compressed::splitGlb(glb);
  Bytes bin = g.bin;
  bin.push_back(0xAB);
  Bytes odd = hostile::glbContainer(g.json.dump(), {});
  const size_t binHeader = odd.size();
  hostile::append32(odd, uint32_t(bin.size()));
  hostile::append32(odd, 0x004E4942u);
  odd.insert(odd.end(), bin.begin(), bin.end());
  hostile::put32(odd, 8, uint32_t(odd.size()));
  const Scene a = load(glb, "box.glb"), b = load(odd, "unaligned.glb");
  EXPECT_EQ(b.stats.binChunkUnaligned, 1);
  EXPECT_EQ(a.stats.binChunkUnaligned, 0);
  ASSERT_EQ(b.meshes.size(), 1u);
  EXPECT_EQ(a.meshes[0].primitives[0].positions, b.meshes[0].primitives[0].positions);
  EXPECT_EQ(a.images[0].rgba, b.images[0].rgba);
  // Cut short instead (the chunk claims 3 bytes more than the file has): still an error.
  Bytes truncated = odd;
  hostile::put32(truncated, binHeader, uint32_t(bin.size() + 3));
  auto t = loadGltfMemory(truncated, "truncated.glb");
  ASSERT_FALSE(t);
  EXPECT_NE(t.error().find("BIN chunk runs past the end"), std::string::npos) << t.error();
}

TEST(SceneCompression, NothingDrawnSaysWhy) {
  hostile::Doc d;
  const int pos = d.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  d.j["meshes"] = Json::array({{{"primitives", Json::array({{{"attributes", {{"POSITION", pos}}}, {"mode", 1}},
                                                             {{"attributes", {{"POSITION", pos}}}, {"mode", 0}}})}}});
  d.node({{"mesh", 0}});
  d.scene({0});
  d.finish();
  const Scene lines = load(hostile::toGlb(d), "lines.glb");
  EXPECT_EQ(lines.stats.skippedPrimitives, 2);
  ASSERT_EQ(lines.skipped.size(), 2u);
  EXPECT_EQ(lines.skipped[0].reason, "mode 1 (lines) not supported");
  EXPECT_EQ(whyNothingDrawn(lines), "only points/lines (2 skipped: 1 x mode 0 (points) not supported, 1 x mode 1 (lines) not supported)");

  hostile::Doc e;
  e.node({{"name", "empty"}});
  e.scene({0});
  e.finish();
  EXPECT_EQ(whyNothingDrawn(load(hostile::toGlb(e), "empty.glb")), "the file has no meshes (1 nodes)");
  for (const std::string& name : builtinSceneNames()) EXPECT_EQ(whyNothingDrawn(*loadScene(name)), "") << name;
}

}  // namespace

namespace {

// EXT_texture_webp: textures naming their image only in the extension load, and the WebP
// images (written by OpenImageIO) decode to the pixels libwebp's own decoder gives for the same
// bytes (WebPDecodeRGBA, the reference). Not to the PNG originals: OpenImageIO 2.4's writer is
// not bit-exact even in its lossless mode.
TEST(SceneCompression, WebpTexturesDecodeAsLibwebpDoes) {
  const Bytes glb = builtin("textured_box");
  const Bytes webpGlb = compressed::webpTextured(glb);
  const Scene a = load(glb, "box.glb"), b = load(webpGlb, "box-webp.glb");
  ASSERT_EQ(a.images.size(), b.images.size());
  ASSERT_EQ(a.textures.size(), b.textures.size());
  for (size_t t = 0; t < a.textures.size(); ++t) EXPECT_EQ(a.textures[t].image, b.textures[t].image);
  const Json doc = compressed::splitGlb(webpGlb).json;
  for (size_t i = 0; i < b.images.size(); ++i) {
    const std::string uri = doc["images"][i]["uri"];
    ASSERT_EQ(uri.rfind("data:image/webp;base64,", 0), 0u);
    const Bytes webp = compressed::base64Decode(uri.substr(uri.find(',') + 1));
    int w = 0, h = 0;
    uint8_t* ref = WebPDecodeRGBA(webp.data(), webp.size(), &w, &h);
    ASSERT_NE(ref, nullptr);
    EXPECT_EQ(b.images[i].width, w);
    EXPECT_EQ(b.images[i].height, h);
    EXPECT_TRUE(b.images[i].rgba.size() == size_t(w) * size_t(h) * 4 &&
                std::equal(b.images[i].rgba.begin(), b.images[i].rgba.end(), ref))
        << "image " << i;
    WebPFree(ref);
  }
  EXPECT_EQ(b.compression.webpImages, int(a.images.size()));
  EXPECT_EQ(b.stats.imagesNotDecoded, 0);
  for (const std::string& u : b.unsupported) EXPECT_EQ(u.find("webp"), std::string::npos) << u;
}

}  // namespace
