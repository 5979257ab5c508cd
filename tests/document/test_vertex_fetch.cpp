// The GPU-relevant evidence (harness/report/vertex_fetch.h) against values derived by hand from
// meshoptimizer's documented models: 64-byte fetch lines, a FIFO post-transform cache.
#include <gtest/gtest.h>

#include "harness/report/vertex_fetch.h"

namespace mb::report {
namespace {

// A unit quad in z = 0: vertices 0..3, triangles (0 1 2) and (2 1 3).
Primitive quad() {
  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  p.normals.assign(4, {0, 0, 1});
  p.indices = {0, 1, 2, 2, 1, 3};
  return p;
}

TEST(VertexFetch, QuadAt48BytesFetchesThreeLines) {
  // 4 x 48 = 192 bytes = lines 0..2 exactly, each missed once: 192 bytes, no overfetch.
  const FetchFigures f = analyzePrimitive(quad(), 48);
  EXPECT_EQ(f.bytesFetched, 192u);
  EXPECT_EQ(f.uniqueVertexBytes, 192u);
  EXPECT_EQ(f.verticesReferenced, 4u);
  // 4 distinct vertices through a 16-entry FIFO: each transformed once; ACMR 4/2.
  EXPECT_EQ(f.verticesTransformed, 4u);
  EXPECT_EQ(f.triangles, 2u);
  EXPECT_EQ(f.skippedPrimitives, 0u);
}

TEST(VertexFetch, SmallerStridesRoundUpToWholeLines) {
  // 4 x 36 = 144 bytes span lines 0..2 (144 / 64 = 2.25): 192 fetched, overfetch 4/3.
  EXPECT_EQ(analyzePrimitive(quad(), 36).bytesFetched, 192u);
  EXPECT_EQ(analyzePrimitive(quad(), 36).uniqueVertexBytes, 144u);
  // 4 x 28 = 112 bytes span lines 0..1: 128 fetched.
  EXPECT_EQ(analyzePrimitive(quad(), 28).bytesFetched, 128u);
  // 4 x 16 = 64 bytes: one line.
  EXPECT_EQ(analyzePrimitive(quad(), 16).bytesFetched, 64u);
}

TEST(VertexFetch, FifoEvictsAfterSixteenNewVertices) {
  // Six triangles of fresh vertices 0..17, then (0 1 2) again: the 16-entry FIFO has pushed
  // 0, 1, 2 out, so 18 + 3 = 21 transforms over 7 triangles (ACMR 3); a 32-entry FIFO
  // still holds them (18).
  Primitive p;
  for (uint32_t i = 0; i < 18; ++i) p.positions.push_back({float(i), float(i % 2), 0});
  for (uint32_t i = 0; i < 18; ++i) p.indices.push_back(i);
  p.indices.insert(p.indices.end(), {0, 1, 2});
  EXPECT_EQ(analyzePrimitive(p, 32).verticesTransformed, 21u);
  EXPECT_EQ(analyzePrimitive(p, 32, CacheModel{32, 64, 128}).verticesTransformed, 18u);
  // Warps of 3 vertices: every fresh triangle fills a warp, which flushes the cache, so the
  // 32-entry FIFO no longer keeps 0 1 2: 21 again.
  EXPECT_EQ(analyzePrimitive(p, 32, CacheModel{32, 3, 128}).verticesTransformed, 21u);
}

TEST(VertexFetch, BadIndicesAreCountedNotAnalysed) {
  Primitive p = quad();
  p.indices[5] = 7;  // past the 4 vertices
  const FetchFigures f = analyzePrimitive(p, 48);
  EXPECT_EQ(f.skippedPrimitives, 1u);
  EXPECT_EQ(f.bytesFetched, 0u);
  EXPECT_EQ(analyzePrimitive(quad(), 0).skippedPrimitives, 1u);    // no stride
  EXPECT_EQ(analyzePrimitive(quad(), 300).skippedPrimitives, 1u);  // over meshoptimizer's 256
}

TEST(VertexFetch, PerFrameUsesThePipelinesStrideAndInstances) {
  Scene s;
  s.meshes.push_back({"quad", {quad()}, {}});
  Node n;
  n.mesh = 0;
  n.instances.resize(3);  // drawn three times
  s.nodes.push_back(n);
  s.roots = {0};
  PipelineStats st;
  st.vertexBytes = 4 * 36;  // a 36-byte layout, no normal-mapped primitive
  st.vertices = 4;
  const nlohmann::json j = vertexFetchJson(s, st);
  EXPECT_EQ(j["strideBytes"]["other"], 36);
  EXPECT_TRUE(j["strideBytes"]["normalMapped"].is_null());
  EXPECT_EQ(j["bytesFetchedPerFrame"], 3 * 192);
  EXPECT_EQ(j["uniqueVertexBytesPerFrame"], 3 * 144);
  EXPECT_DOUBLE_EQ(j["overfetch"].get<double>(), 192.0 / 144.0);
  EXPECT_DOUBLE_EQ(j["bytesFetchedPerVertex"].get<double>(), 192.0 / 4.0);
  EXPECT_EQ(j["verticesTransformedPerFrame"], 3 * 4);
  EXPECT_DOUBLE_EQ(j["acmr"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["atvr"].get<double>(), 1.0);
  EXPECT_NE(j["model"].get<std::string>().find("16-entry FIFO"), std::string::npos);
}

TEST(VertexFetch, OneFlatQuadHasNoOverdraw) {
  Scene s;
  s.meshes.push_back({"quad", {quad()}, {}});
  Node n;
  n.mesh = 0;
  s.nodes.push_back(n);
  s.roots = {0};
  const nlohmann::json j = overdrawJson(s);
  ASSERT_GT(j["pixelsCovered"].get<double>(), 0);
  EXPECT_DOUBLE_EQ(j["overdraw"].get<double>(), 1.0);  // every covered pixel shaded once
}

}  // namespace
}  // namespace mb::report
