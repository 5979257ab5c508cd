// Vertex formats as the baseline does them: the matrix pipeline uploads a tangent
// only where the glTF-Sample-Viewer has one (authored TANGENT, or generated for a normal map),
// so a primitive without both is position + normal + uv = 32 bytes; dropping the tangent
// changes no pixel (nothing reads it without a normal map); the stats split the shading bytes
// normal-mapped / not, for every pipeline.
#include <gtest/gtest.h>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/frame_vertices.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

Scene load(const std::string& name) {
  auto scene = loadScene(name);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

Frame render(const Scene& scene, const std::string& pipeline, const AnimState& anim = {}) {
  FrameSettings s;
  s.anim = anim;
  s.width = 128;
  s.height = 96;
  auto f = renderFrame(scene, pipeline, s);
  EXPECT_TRUE(f) << f.error();
  return f ? f.take() : Frame{};
}

// `scene` with no normal maps; `keepTangents`: the primitives keep their tangents as if the
// file authored TANGENT (the Sample Viewer then still uploads them).
Scene withoutNormalMaps(Scene scene, bool keepTangents) {
  for (Material& m : scene.materials) m.normal = TextureRef{};
  for (Mesh& mesh : scene.meshes)
    for (Primitive& p : mesh.primitives) {
      if (!keepTangents) p.tangents.clear();
      p.hadTangents = keepTangents;
    }
  return scene;
}

uint64_t vertexCount(const Scene& scene) {
  uint64_t n = 0;
  for (const Mesh& m : scene.meshes)
    for (const Primitive& p : m.primitives) n += p.positions.size();
  return n;
}

}  // namespace

TEST(MatrixVertexFormat, TangentOnlyWhereTheSampleViewerHasOne) {
  Primitive p;
  p.positions = {{1, 2, 3}, {4, 5, 6}};
  p.normals = {{0, 0, 1}, {0, 1, 0}};
  p.uv0 = {{0.25f, 0.5f}, {0.75f, 1.0f}};
  EXPECT_EQ(gl::floatFrameFormat(p).variant, 1);  // MB_NO_TANGENT: no tangent attribute
  // Hand-written layout: position, normal, uv.
  EXPECT_EQ(gl::floatFrameFormat(p).data,
            (std::vector<float>{1, 2, 3, 0, 0, 1, 0.25f, 0.5f, 4, 5, 6, 0, 1, 0, 0.75f, 1.0f}));
  p.tangents = {{1, 0, 0, 1}, {0, 0, 1, -1}};
  EXPECT_EQ(gl::floatFrameFormat(p).variant, 0);
  EXPECT_EQ(gl::floatFrameFormat(p).data,
            (std::vector<float>{1, 2, 3, 0, 0, 1, 1, 0, 0, 1, 0.25f, 0.5f,  //
                                4, 5, 6, 0, 1, 0, 0, 0, 1, -1, 0.75f, 1.0f}));
}

TEST(MatrixVertexFormat, NormalMappedBuiltinIs48BytesAndAllNormalMapped) {
  const Scene scene = load("textured_box");
  const PipelineStats m = render(scene, "matrix").stats;
  const PipelineStats q = render(scene, "motor").stats;
  ASSERT_EQ(m.vertices, vertexCount(scene));
  EXPECT_EQ(m.vertexBytes, m.vertices * 48);
  EXPECT_EQ(m.normalMappedVertices, m.vertices);
  EXPECT_EQ(m.normalMappedVertexBytes, m.vertexBytes);
  EXPECT_EQ(q.vertexBytes, q.vertices * 36);
  EXPECT_EQ(q.normalMappedVertices, q.vertices);
  EXPECT_EQ(q.normalMappedVertexBytes, q.vertexBytes);
}

TEST(MatrixVertexFormat, WithoutNormalMapOrTangentIs32BytesAndTheSameImage) {
  // Rigid (textured_box) and skinned (skinned_tube, the skinned no-tangent shader variant).
  for (const char* name : {"textured_box", "skinned_tube"}) {
    SCOPED_TRACE(name);
    const Scene base = load(name);
    const AnimState anim = base.animations.empty() ? AnimState{}
                                                   : AnimState{0, 0.4f * base.animations[0].duration};
    const Scene bare = withoutNormalMaps(base, false);
    const Scene authored = withoutNormalMaps(base, true);
    const Frame fBare = render(bare, "matrix", anim);
    const Frame fAuthored = render(authored, "matrix", anim);
    const uint64_t n = vertexCount(base);
    ASSERT_EQ(fBare.stats.vertices, n);
    EXPECT_EQ(fBare.stats.vertexBytes, n * 32);       // position + normal + uv
    EXPECT_EQ(fAuthored.stats.vertexBytes, n * 48);   // + authored tangent
    EXPECT_EQ(fBare.stats.normalMappedVertices, 0u);
    EXPECT_EQ(fBare.stats.normalMappedVertexBytes, 0u);
    EXPECT_DOUBLE_EQ(fBare.stats.floatsPerVertex, 8.0);
    // Nothing reads the tangent without a normal map: bit-identical images.
    EXPECT_EQ(fBare.image.rgba, fAuthored.image.rgba);
    // The motor vertex keeps its 9 floats (the rotor carries the normal too).
    const Frame motor = render(bare, "motor", anim);
    EXPECT_EQ(motor.stats.vertexBytes, n * 36);
    // Affine uploads the same 8-float vertex (affine.vs MB_NO_TANGENT), 12 floats with
    // an authored tangent, and the two draw bit-identical images.
    const Frame affineBare = render(bare, "affine", anim);
    const Frame affineAuthored = render(authored, "affine", anim);
    EXPECT_EQ(affineBare.stats.vertexBytes, n * 32);
    EXPECT_EQ(affineAuthored.stats.vertexBytes, n * 48);
    EXPECT_DOUBLE_EQ(affineBare.stats.floatsPerVertex, 8.0);
    EXPECT_EQ(affineBare.image.rgba, affineAuthored.image.rgba);
  }
}

TEST(MatrixVertexFormat, MixedScenesSplitBytesPerPrimitive) {
  // textured_box's mesh twice: once normal-mapped, once with a plain material and no tangents.
  Scene scene = load("textured_box");
  ASSERT_EQ(scene.meshes.size(), 1u);
  Material plain = scene.materials.at(size_t(scene.meshes[0].primitives[0].material));
  plain.normal = TextureRef{};
  scene.materials.push_back(plain);
  Mesh copy = scene.meshes[0];
  for (Primitive& p : copy.primitives) {
    p.material = int(scene.materials.size() - 1);
    p.tangents.clear();
    p.hadTangents = false;
    for (glm::vec3& x : p.positions) x += glm::vec3(3.0f, 0.0f, 0.0f);
  }
  scene.meshes.push_back(copy);
  Node n;
  n.mesh = 1;
  scene.nodes.push_back(n);
  scene.roots.push_back(int(scene.nodes.size() - 1));
  const uint64_t mapped = vertexCount(scene) / 2;
  for (const Primitive& p : scene.meshes[0].primitives) EXPECT_TRUE(gl::normalMapped(scene, p));
  for (const Primitive& p : scene.meshes[1].primitives) EXPECT_FALSE(gl::normalMapped(scene, p));
  const PipelineStats m = render(scene, "matrix").stats;
  EXPECT_EQ(m.normalMappedVertices, mapped);
  EXPECT_EQ(m.normalMappedVertexBytes, mapped * 48);
  EXPECT_EQ(m.vertexBytes - m.normalMappedVertexBytes, mapped * 32);
  const PipelineStats q = render(scene, "motor").stats;
  EXPECT_EQ(q.normalMappedVertices, mapped);
  EXPECT_EQ(q.normalMappedVertexBytes, mapped * 36);
  EXPECT_EQ(q.vertexBytes - q.normalMappedVertexBytes, mapped * 36);
}
