// Accessor decoding: every component type, normalized integers, interleaved strides,
// byteOffsets, matrix column padding, sparse accessors and range errors, on hand-built
// buffers with known values.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/loader.h"
#include "tests/support/scene_test_gltf.h"

using mbtest::TestGltf;

namespace {

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;

tinygltf::Model parse(const TestGltf& g) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model m;
  std::string err, warn;
  auto bytes = g.gltf();
  EXPECT_TRUE(loader.LoadASCIIFromString(&m, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                         unsigned(bytes.size()), "")) << err;
  return m;
}

std::vector<float> decodeFloats(const TestGltf& g, int accessor) {
  auto r = mb::readAccessorFloat(parse(g), accessor, "test");
  EXPECT_TRUE(r.ok()) << r.error();
  return r ? r->values : std::vector<float>{};
}

}  // namespace

TEST(SceneAccessors, EveryComponentTypeByValue) {
  TestGltf g;
  int a0 = g.accessor(g.viewOf(std::vector<int8_t>{-128, -1, 0, 127}), kByte, 4, "SCALAR");
  int a1 = g.accessor(g.viewOf(std::vector<uint8_t>{0, 1, 200, 255}), kUByte, 4, "SCALAR");
  int a2 = g.accessor(g.viewOf(std::vector<int16_t>{-32768, -2, 3, 32767}), kShort, 4, "SCALAR");
  int a3 = g.accessor(g.viewOf(std::vector<uint16_t>{0, 7, 40000, 65535}), kUShort, 4, "SCALAR");
  int a4 = g.accessor(g.viewOf(std::vector<uint32_t>{0, 9, 70000, 16777216}), kUInt, 4, "SCALAR");
  int a5 = g.accessor(g.viewOf(std::vector<float>{-1.5f, 0.25f, 3e8f, 7.0f}), kFloat, 4, "SCALAR");
  EXPECT_EQ(decodeFloats(g, a0), (std::vector<float>{-128, -1, 0, 127}));
  EXPECT_EQ(decodeFloats(g, a1), (std::vector<float>{0, 1, 200, 255}));
  EXPECT_EQ(decodeFloats(g, a2), (std::vector<float>{-32768, -2, 3, 32767}));
  EXPECT_EQ(decodeFloats(g, a3), (std::vector<float>{0, 7, 40000, 65535}));
  EXPECT_EQ(decodeFloats(g, a4), (std::vector<float>{0, 9, 70000, 16777216}));
  EXPECT_EQ(decodeFloats(g, a5), (std::vector<float>{-1.5f, 0.25f, 3e8f, 7.0f}));
  auto u = mb::readAccessorUint(parse(g), a4, "indices");
  ASSERT_TRUE(u.ok());
  EXPECT_EQ(u->values, (std::vector<uint32_t>{0, 9, 70000, 16777216}));
  EXPECT_FALSE(mb::readAccessorUint(parse(g), a5, "indices").ok());  // float indices rejected
  EXPECT_FALSE(mb::readAccessorUint(parse(g), a0, "indices").ok());  // signed rejected
}

TEST(SceneAccessors, NormalizedIntegers) {
  TestGltf g;
  int b = g.accessor(g.viewOf(std::vector<int8_t>{-128, -127, 0, 64, 127}), kByte, 5, "SCALAR", 0, true);
  int ub = g.accessor(g.viewOf(std::vector<uint8_t>{0, 51, 255}), kUByte, 3, "SCALAR", 0, true);
  int s = g.accessor(g.viewOf(std::vector<int16_t>{-32768, -32767, 16384, 32767}), kShort, 4, "SCALAR", 0, true);
  int us = g.accessor(g.viewOf(std::vector<uint16_t>{0, 13107, 65535}), kUShort, 3, "SCALAR", 0, true);
  auto vb = decodeFloats(g, b);
  ASSERT_EQ(vb.size(), 5u);
  EXPECT_FLOAT_EQ(vb[0], -1.0f);  // max(c / 127, -1)
  EXPECT_FLOAT_EQ(vb[1], -1.0f);
  EXPECT_FLOAT_EQ(vb[2], 0.0f);
  EXPECT_FLOAT_EQ(vb[3], 64.0f / 127.0f);
  EXPECT_FLOAT_EQ(vb[4], 1.0f);
  auto vub = decodeFloats(g, ub);
  EXPECT_FLOAT_EQ(vub[1], 0.2f);
  EXPECT_FLOAT_EQ(vub[2], 1.0f);
  auto vs = decodeFloats(g, s);
  EXPECT_FLOAT_EQ(vs[0], -1.0f);
  EXPECT_FLOAT_EQ(vs[1], -1.0f);
  EXPECT_FLOAT_EQ(vs[2], 16384.0f / 32767.0f);
  EXPECT_FLOAT_EQ(vs[3], 1.0f);
  auto vus = decodeFloats(g, us);
  EXPECT_FLOAT_EQ(vus[1], 0.2f);
  EXPECT_FLOAT_EQ(vus[2], 1.0f);
}

TEST(SceneAccessors, InterleavedStrideAndOffsets) {
  // Per vertex (16 bytes): vec3 float position, then vec2 unorm16 uv. 3 vertices after a
  // 8-byte gap inside the bufferView, which itself starts 4 bytes into the buffer.
  TestGltf g;
  g.append(std::vector<uint32_t>{0xDEADBEEF});
  std::vector<uint8_t> bytes(8 + 3 * 16, 0xAB);
  for (int v = 0; v < 3; ++v) {
    float p[3] = {float(v), float(v) + 0.5f, -float(v)};
    uint16_t uv[2] = {uint16_t(v * 1000), uint16_t(65535 - v)};
    std::memcpy(&bytes[8 + 16 * size_t(v)], p, 12);
    std::memcpy(&bytes[8 + 16 * size_t(v) + 12], uv, 4);
  }
  size_t at = g.append(bytes);
  int view = g.view(at, bytes.size(), 16);
  int pos = g.accessor(view, kFloat, 3, "VEC3", 8);
  int uv = g.accessor(view, kUShort, 3, "VEC2", 20, true);
  auto p = decodeFloats(g, pos);
  EXPECT_EQ(p, (std::vector<float>{0, 0.5f, 0, 1, 1.5f, -1, 2, 2.5f, -2}));
  auto t = decodeFloats(g, uv);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_FLOAT_EQ(t[2], 1000.0f / 65535.0f);
  EXPECT_FLOAT_EQ(t[5], 65533.0f / 65535.0f);
}

TEST(SceneAccessors, MatrixColumnsArePadded) {
  // MAT2 of bytes: each 2-byte column starts on a 4-byte boundary (8 bytes per element).
  TestGltf g;
  int m2 = g.accessor(g.viewOf(std::vector<int8_t>{1, 2, 0, 0, 3, 4, 0, 0}), kByte, 1, "MAT2");
  EXPECT_EQ(decodeFloats(g, m2), (std::vector<float>{1, 2, 3, 4}));
}

TEST(SceneAccessors, SparseAccessors) {
  TestGltf g;
  int base = g.viewOf(std::vector<float>{0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3});
  int idx = g.viewOf(std::vector<uint16_t>{1, 3});
  int val = g.viewOf(std::vector<float>{10, 11, 12, 30, 31, 32});
  int a = g.accessor(base, kFloat, 4, "VEC3");
  g.doc["accessors"][size_t(a)]["sparse"] = {{"count", 2},
                                              {"indices", {{"bufferView", idx}, {"componentType", kUShort}}},
                                              {"values", {{"bufferView", val}}}};
  // No bufferView: zeros, then the sparse values.
  int z = g.accessor(-1, kFloat, 3, "VEC3");
  g.doc["accessors"][size_t(z)]["sparse"] = {{"count", 1},
                                              {"indices", {{"bufferView", idx}, {"componentType", kUShort}}},
                                              {"values", {{"bufferView", val}}}};
  EXPECT_EQ(decodeFloats(g, a), (std::vector<float>{0, 0, 0, 10, 11, 12, 2, 2, 2, 30, 31, 32}));
  EXPECT_EQ(decodeFloats(g, z), (std::vector<float>{0, 0, 0, 10, 11, 12, 0, 0, 0}));
  // Sparse index beyond count is an error.
  int bad = g.accessor(-1, kFloat, 2, "VEC3");
  g.doc["accessors"][size_t(bad)]["sparse"] = g.doc["accessors"][size_t(a)]["sparse"];
  auto r = mb::readAccessorFloat(parse(g), bad, "POSITION");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("sparse index 3 out of range"), std::string::npos) << r.error();
}

TEST(SceneAccessors, RangeErrors) {
  TestGltf g;
  int view = g.viewOf(std::vector<float>(9, 1.0f));  // 36 bytes
  int ok = g.accessor(view, kFloat, 3, "VEC3");
  int past = g.accessor(view, kFloat, 4, "VEC3");
  int offset = g.accessor(view, kFloat, 3, "VEC3", 4);
  int interleavedPast = g.accessor(g.view(0, 36, 16), kFloat, 3, "VEC3");  // 2*16+12 = 44 > 36
  int tooSmallStride = g.accessor(g.view(0, 36, 8), kFloat, 2, "VEC3");
  auto m = parse(g);
  EXPECT_TRUE(mb::readAccessorFloat(m, ok, "POSITION").ok());
  for (int bad : {past, offset, interleavedPast}) {
    auto r = mb::readAccessorFloat(m, bad, "POSITION");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().find("accessor " + std::to_string(bad) + " (POSITION) reads past bufferView"), 0u) << r.error();
  }
  auto r = mb::readAccessorFloat(m, tooSmallStride, "POSITION");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("byteStride 8"), std::string::npos) << r.error();
  EXPECT_FALSE(mb::readAccessorFloat(m, 99, "POSITION").ok());
}

TEST(SceneAccessors, LoaderDecodesIndicesAndModes) {
  // Quad as u8-indexed list, as a strip and as a fan: all give 2 triangles.
  for (int mode : {4, 5, 6}) {
    TestGltf g;
    int pos = g.accessor(g.viewOf(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}), kFloat, 4, "VEC3");
    std::vector<uint8_t> idx = mode == 4 ? std::vector<uint8_t>{0, 1, 2, 0, 2, 3}
                             : mode == 5 ? std::vector<uint8_t>{0, 1, 3, 2} : std::vector<uint8_t>{0, 1, 2, 3};
    int ind = g.accessor(g.viewOf(idx), kUByte, idx.size(), "SCALAR");
    g.doc["accessors"][size_t(pos)]["min"] = {0, 0, 0};
    g.doc["accessors"][size_t(pos)]["max"] = {1, 1, 0};
    g.meshPrimitive({{"POSITION", pos}}, ind, mode);
    auto s = mb::loadGltfMemory(g.glb(), "quad.glb");
    ASSERT_TRUE(s.ok()) << s.error();
    const auto& p = s->meshes[0].primitives[0];
    EXPECT_EQ(p.indices.size(), 6u) << "mode " << mode;
    EXPECT_EQ(s->stats.flatNormalsGenerated, 1);
    for (const auto& n : p.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f) << "mode " << mode;  // all CCW
  }
}

TEST(SceneAccessors, LoaderErrorNamesFileAccessorAndView) {
  TestGltf g;
  int pos = g.accessor(g.viewOf(std::vector<float>(9, 0.0f)), kFloat, 4, "VEC3");
  g.meshPrimitive({{"POSITION", pos}});
  auto s = mb::loadGltfMemory(g.glb(), "box.glb");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "box.glb: accessor 0 (POSITION) reads past bufferView 0 and past the end of buffer 0 (0 bytes follow the view)");
}
