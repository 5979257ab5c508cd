// Real files other viewers draw and the loader refused or drew blank, each rebuilt here as a small
// file with the same feature, loaded, and checked against the valid file it stands for:
//  - a scene root that has a parent (Blender / Kenney "tmpParent"): drawn as a root at its local
//    transform, or once under a listed ancestor (rootsWithParent);
//  - EXT_texture_webp naming no image: the texture's own source (webpTexturesWithoutSource);
//  - an accessor reading past its bufferView, inside its buffer: the buffer's bytes
//    (accessorsPastBufferView); past the buffer's end it stays an error naming the accessor;
//  - lines/points next to triangles of zero area: the triangles are kept and named
//    (zeroAreaPrimitives), and a file drawing nothing else is refused (whyNothingDrawn).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/hostile_cases.h"
#include "tests/scene/load_bytes.h"

using namespace mb;
using hostile::Bytes;
using hostile::Doc;
using hostile::Json;

namespace {

using scene_test::load;

// The non-zero LoadStats counters of `s`, as inspect lists them.
Json fallbacks(const Scene& s) {
  Json out = Json::object();
  const Json all = toJson(s.stats);  // items() must not outlive it
  for (const auto& [k, v] : all.items())
    if (v != 0) out[k] = v;
  return out;
}

Json plus(Json base, const std::string& key, int n = 1) {
  base[key] = n;
  return base;
}

bool listed(const Scene& s, const std::string& text) {
  return std::any_of(s.unsupported.begin(), s.unsupported.end(),
                     [&](const std::string& u) { return u.find(text) != std::string::npos; });
}

std::vector<glm::mat4> restWorld(const Scene& s) { return worldMatrices(s, samplePose(s, AnimState{})); }

// ---------------------------------------------------------------------------------------------
// Scene roots with a parent.

// The quad (hostile::quad: mesh 0 on node 0) at translation (0, 2, 0); node 1 "tmpParent" at
// (100, 0, 0) is its parent. `roots` lists the scene's nodes.
Bytes quadUnderParent(const std::vector<int>& roots, bool parented = true) {
  Doc d;
  hostile::quad(d);
  d.j["nodes"][0]["translation"] = {0, 2, 0};
  d.node({{"name", "tmpParent"}, {"translation", {100, 0, 0}}});
  if (parented) d.j["nodes"][1]["children"] = {0};
  d.scene(roots);
  d.finish();
  return hostile::toGlb(d);
}

TEST(SceneRealGaps, RootWithParentIsDrawnAsARootAtItsLocalTransform) {
  const Scene s = load(quadUnderParent({0}), "tmpparent.glb");
  const Scene valid = load(quadUnderParent({0}, false), "valid.glb");  // the same quad, a true root
  EXPECT_EQ(fallbacks(s), plus(fallbacks(valid), "rootsWithParent")) << "nothing else repaired";
  EXPECT_FALSE(listed(s, "listed as root")) << "drawn, not listed as unsupported";
  EXPECT_EQ(s.roots, std::vector<int>{0});
  EXPECT_EQ(s.nodes[0].parent, -1) << "detached from the unlisted parent";
  EXPECT_TRUE(s.nodes[1].children.empty());
  EXPECT_EQ(nodesInDrawOrder(s), std::vector<int>{0});
  EXPECT_EQ(whyNothingDrawn(s), "");
  // Its local transform only (three.js re-parents it to the scene): (0, 2, 0), not (100, 2, 0).
  const glm::mat4 world = restWorld(s)[0];
  EXPECT_EQ(glm::vec3(world[3]), glm::vec3(0, 2, 0));
  EXPECT_EQ(world, restWorld(valid)[0]);
  EXPECT_EQ(frameScene(s, AnimState{}, 1.0f, -1).eye, frameScene(valid, AnimState{}, 1.0f, -1).eye)
      << "framed like the valid file";
}

TEST(SceneRealGaps, RootUnderAListedAncestorIsDrawnOnceInItsSubtree) {
  // Both listed: the parent is a root, the child is drawn once, under it, at (100, 2, 0).
  const Scene s = load(quadUnderParent({1, 0}), "both.glb");
  EXPECT_EQ(s.stats.rootsWithParent, 1);
  EXPECT_EQ(s.roots, std::vector<int>{1});
  EXPECT_EQ(s.nodes[0].parent, 1);
  EXPECT_EQ(nodesInDrawOrder(s), (std::vector<int>{1, 0}));
  EXPECT_EQ(glm::vec3(restWorld(s)[0][3]), glm::vec3(100, 2, 0));
}

TEST(SceneRealGaps, ListedChainBelowAnUnlistedParentKeepsItsInnerLinks) {
  // tmpParent (1) -> C (2) -> quad (0); the scene lists the quad before C, and C twice. C has no
  // listed ancestor: a root, detached. The quad is under C: stays there, drawn once.
  Doc d;
  hostile::quad(d);
  d.node({{"name", "tmpParent"}, {"translation", {100, 0, 0}}, {"children", {2}}});
  d.node({{"name", "C"}, {"translation", {0, 0, 3}}, {"children", {0}}});
  d.scene({0, 2, 2});
  d.finish();
  const Scene s = load(hostile::toGlb(d), "chain.glb");
  EXPECT_EQ(s.stats.rootsWithParent, 2) << "the quad and C, C counted once";
  EXPECT_EQ(s.roots, (std::vector<int>{2, 2})) << "as listed";
  EXPECT_EQ(s.nodes[2].parent, -1);
  EXPECT_EQ(s.nodes[0].parent, 2);
  EXPECT_EQ(nodesInDrawOrder(s), (std::vector<int>{2, 0}));
  EXPECT_EQ(glm::vec3(restWorld(s)[0][3]), glm::vec3(0, 0, 3));
  EXPECT_EQ(hostile::checkSceneInvariants(s), "");
}

TEST(SceneRealGaps, MeshesOnlyOutsideTheSceneAreRefusedWithTheReason) {
  // The scene lists an empty node; the quad's node is in no scene: nothing would be drawn.
  Doc d;
  hostile::quad(d);
  d.node({{"name", "empty"}});
  d.scene({1});
  d.finish();
  EXPECT_EQ(whyNothingDrawn(load(hostile::toGlb(d), "outside.glb")),
            "no node the scene reaches draws a mesh (1 meshes, on nodes outside the scene only)");
}

// ---------------------------------------------------------------------------------------------
// EXT_texture_webp without an image.

// The normal-mapped quad (texture 0 -> image 0, a PNG) with texture 0's source and
// EXT_texture_webp object set as given (a null `source` leaves it out).
Bytes webpTexture(const Json& source, const Json& extension, bool used = true) {
  Doc d;
  const int mat = hostile::normalMappedMaterial(d);
  hostile::quad(d, true, true, mat);
  if (!used) {
    d.j["materials"][0].erase("pbrMetallicRoughness");
    d.j["materials"][0].erase("normalTexture");
  }
  if (source.is_null()) d.j["textures"][0].erase("source");
  else d.j["textures"][0]["source"] = source;
  if (!extension.is_null()) {
    d.j["textures"][0]["extensions"] = {{"EXT_texture_webp", extension}};
    d.j["extensionsUsed"] = {"EXT_texture_webp"};
  }
  d.finish();
  return hostile::toGlb(d);
}

TEST(SceneRealGaps, WebpWithoutSourceUsesTheTexturesOwnSource) {
  const Scene s = load(webpTexture(0, Json::object()), "nosource.glb");
  const Scene valid = load(webpTexture(0, nullptr), "png.glb");  // the same texture, no extension
  EXPECT_EQ(fallbacks(s), plus(fallbacks(valid), "webpTexturesWithoutSource"));
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].image, 0);
  EXPECT_EQ(s.images[0].rgba, valid.images[0].rgba);
  EXPECT_EQ(s.materials[0].baseColor.texture, 0);
  EXPECT_EQ(s.unsupported, valid.unsupported) << "nothing listed: it draws as the PNG file does";

  // An extension source that does not exist is the same case.
  const Scene missing = load(webpTexture(0, {{"source", 9}}), "missing.glb");
  EXPECT_EQ(missing.stats.webpTexturesWithoutSource, 1);
  EXPECT_EQ(missing.textures[0].image, 0);
  // A valid extension source is still preferred to the fallback, and nothing is counted.
  Doc d;
  const int mat = hostile::normalMappedMaterial(d);
  hostile::quad(d, true, true, mat);
  d.image(hostile::checkerPng(2));
  d.j["textures"][0]["extensions"] = {{"EXT_texture_webp", {{"source", 1}}}};
  d.finish();
  const Scene both = load(hostile::toGlb(d), "both.glb");
  EXPECT_EQ(both.textures[0].image, 1);
  EXPECT_EQ(both.stats.webpTexturesWithoutSource, 0);
}

TEST(SceneRealGaps, WebpWithoutAnyImageIsKeptUnusedAndDrawnUntexturedUsed) {
  const Scene unused = load(webpTexture(nullptr, Json::object(), false), "unused.glb");
  EXPECT_EQ(unused.stats.webpTexturesWithoutSource, 1);
  EXPECT_EQ(unused.textures[0].image, -1);
  EXPECT_FALSE(listed(unused, "EXT_texture_webp")) << "no material draws it";

  const Scene used = load(webpTexture(nullptr, {{"source", 9}}), "used.glb");
  EXPECT_EQ(used.stats.webpTexturesWithoutSource, 1);
  EXPECT_EQ(used.textures[0].image, -1) << "sampled by no draw: untextured";
  EXPECT_TRUE(listed(used, "texture 0: EXT_texture_webp names no image (source 9 does not exist) and the texture "
                           "has no source: drawn untextured"));
}

// ---------------------------------------------------------------------------------------------
// Accessors past their bufferView.

// The quad with its TEXCOORD_0 bufferView `shortBy` bytes shorter than the accessor reads
// (hostile::quad: positions, normals, uvs, indices in that order, so the indices follow).
Bytes uvViewShortBy(size_t shortBy) {
  Doc d;
  const hostile::QuadIds q = hostile::quad(d);
  const int view = d.j["accessors"][q.uv]["bufferView"];
  d.j["bufferViews"][view]["byteLength"] = 32 - shortBy;
  d.finish();
  return hostile::toGlb(d);
}

TEST(SceneRealGaps, AccessorPastItsBufferViewReadsTheBuffersBytes) {
  const Scene s = load(uvViewShortBy(8), "short.glb");
  const Scene valid = load(uvViewShortBy(0), "valid.glb");
  EXPECT_EQ(fallbacks(s), plus(fallbacks(valid), "accessorsPastBufferView"));
  // The authored uvs (hostile::quad), the last one read past the view.
  ASSERT_EQ(s.meshes[0].primitives[0].uv0.size(), 4u);
  EXPECT_EQ(s.meshes[0].primitives[0].uv0[3], glm::vec2(0, 0));
  EXPECT_EQ(s.meshes[0].primitives[0].uv0[1], glm::vec2(1, 1));
  EXPECT_EQ(s.meshes[0].primitives[0].uv0, valid.meshes[0].primitives[0].uv0);
}

TEST(SceneRealGaps, AccessorPastItsBufferStaysAnErrorNamingIt) {
  // TEXCOORD_0 last in the buffer, read from byte 8 of its 32-byte view: 8 bytes past the end.
  Doc d;
  const int pos = d.positions(hostile::quadPositions());
  const int idx = d.indices16({0, 1, 2, 0, 2, 3});
  const int uv = d.vec2(std::vector<glm::vec2>{{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  d.j["accessors"][uv]["byteOffset"] = 8;
  d.mesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"indices", idx}});
  d.node({{"mesh", 0}});
  d.scene({0});
  d.finish();
  auto s = loadGltfMemory(hostile::toGlb(d), "past.glb");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error(), "past.glb: accessor 2 (TEXCOORD_0) reads past bufferView 2 and past the end of buffer 0 (0 "
                       "bytes follow the view)");
}

// ---------------------------------------------------------------------------------------------
// Lines and points next to triangles.

// Six points on the x axis drawn as a line strip, as points and as 5 indexed triangles between
// them (all collinear), plus `extra` indices appended to the triangle list.
Bytes linesAndFlatTriangles(const std::vector<uint16_t>& extra = {}) {
  Doc d;
  std::vector<glm::vec3> p;
  for (int i = 0; i < 6; ++i) p.push_back({float(i), 0, 0});
  p.push_back({0, 1, 0});  // off the axis, used by `extra` only
  std::vector<uint16_t> tri = {0, 1, 2, 1, 2, 3, 2, 3, 4, 3, 4, 5, 0, 5, 0};
  tri.insert(tri.end(), extra.begin(), extra.end());
  const int pos = d.positions(p), idx = d.indices16(tri);
  Json prims = Json::array();
  for (int mode : {3, 0, 4}) {
    Json prim = {{"attributes", {{"POSITION", pos}}}, {"mode", mode}};
    if (mode == 4) prim["indices"] = idx;
    prims.push_back(prim);
  }
  d.arr("meshes").push_back({{"primitives", prims}});
  d.node({{"mesh", 0}});
  d.scene({0});
  d.finish();
  return hostile::toGlb(d);
}

TEST(SceneRealGaps, ZeroAreaTrianglesNextToLinesAreNamedAndRefused) {
  const Scene s = load(linesAndFlatTriangles(), "flat.glb");
  EXPECT_EQ(s.stats.skippedPrimitives, 2);
  EXPECT_EQ(s.stats.zeroAreaPrimitives, 1);
  ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
  EXPECT_EQ(s.meshes[0].primitives[0].indices.size(), 15u) << "kept";
  EXPECT_TRUE(listed(s, "mesh 0 primitive 2: all 5 triangles have zero area (nothing drawn at rest)"));
  EXPECT_EQ(whyNothingDrawn(s),
            "only points/lines (2 skipped: 1 x mode 0 (points) not supported, 1 x mode 3 (line strip) not supported); "
            "every triangle has zero area (1 primitives)");

  // One triangle with area among them: drawn, nothing named.
  const Scene drawn = load(linesAndFlatTriangles({0, 1, 6}), "drawn.glb");
  EXPECT_EQ(drawn.stats.zeroAreaPrimitives, 0);
  EXPECT_EQ(whyNothingDrawn(drawn), "");
}

TEST(SceneRealGaps, TrianglesSharingALinePrimitivesIndicesAreDrawn) {
  // The lines and the triangles read one indices accessor (the quad's 6): the triangles keep them.
  Doc d;
  hostile::quad(d);
  Json& prims = d.j["meshes"][0]["primitives"];
  Json lines = prims[0];
  lines["mode"] = 1;
  prims.insert(prims.begin(), lines);
  d.finish();
  const Scene s = load(hostile::toGlb(d), "shared.glb");
  EXPECT_EQ(s.stats.skippedPrimitives, 1);
  ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
  EXPECT_EQ(s.meshes[0].primitives[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(s.stats.zeroAreaPrimitives, 0);
  EXPECT_EQ(whyNothingDrawn(s), "");
}

TEST(SceneRealGaps, HasAreaAtRest) {
  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1e-3f, 0}};
  p.indices = {0, 1, 2};
  EXPECT_FALSE(hasAreaAtRest(p)) << "collinear";
  p.indices = {0, 0, 3, 1, 1, 1};
  EXPECT_FALSE(hasAreaAtRest(p)) << "repeated corners";
  p.indices = {0, 1, 3};
  EXPECT_TRUE(hasAreaAtRest(p)) << "height 1e-3 of a unit edge";
}

}  // namespace
