// Compressed and WebP-textured versions of built-in scenes, made by the
// codecs' encoders (tests/support/compressed_gltf.h), render in every glTF pipeline and match
// the uncompressed scene's image from the same pipeline:
//  - meshopt (no filters): the decoded Scene is the original's (a triangle's corners may be
//    rotated), the images are identical byte for byte;
//  - WebP: the file's WebP images decode to the pixels of a PNG-textured reference made from
//    them (OpenImageIO's WebP writer is not bit-exact, so the original PNGs are not the
//    reference): identical images, the textures take the PNG path through every pipeline;
//  - Draco at 14-bit positions, 10-bit normals, 12-bit uvs: a vertex moves by at most
//    extent / (2^14 - 1) / 2 (normal_torus: 3.0 / 16383 / 2 = 9.2e-5 units, 0.004 pixels at
//    128 px across ~3 units), normals turn by at most 0.0039 rad (tests/scene/
//    test_scene_compression.cpp). Sub-pixel edge moves change only pixels that a triangle
//    edge crosses, and the normal error changes GGX shading by about one byte step: we require
//    PSNR >= 40 dB and at most 1 % of the pixels off by more than 4/255.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "tests/support/compressed_gltf.h"

using namespace mb;

namespace {

struct Case {
  std::string pipeline, scene, codec;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.pipeline << " " << c.scene << " " << c.codec; }

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const std::string& p : pipelineNames(Space::Euclidean)) {
    for (const char* scene : {"normal_torus", "skinned_tube"})
      for (const char* codec : {"draco", "meshopt"}) out.push_back({p, scene, codec});
    out.push_back({p, "textured_box", "webp"});
  }
  return out;
}

class CompressedRender : public ::testing::TestWithParam<Case> {};

Result<RgbaImage> render(const std::vector<uint8_t>& glb, const std::string& name, const std::string& pipeline,
                         FrameSettings s) {
  auto scene = loadGltfMemory(glb, name);
  if (!scene) return Result<RgbaImage>::fail(scene.error());
  // The built-in scene's own framing (loadScene's): the packed file orders its triangles
  // differently, and framed closer (Framing::Fit, a file's) the bent skinned_tube of qtangent
  // and matrix_c differs by one 8-bit step between the two orders.
  scene->framing = Framing::BoundingSphere;
  auto frame = renderFrame(*scene, pipeline, s);
  if (!frame) return Result<RgbaImage>::fail(frame.error());
  if (frame->stats.draws == 0) return Result<RgbaImage>::fail(name + ": nothing drawn");
  return frame->image;
}

// A built-in scene's file packed by `codec`, and the uncompressed file its images are compared
// with, made once per test process for the nine pipelines' cases (the encoders cost more than
// the frames; the bytes depend on the scene and codec alone).
struct PackedScene {
  std::vector<uint8_t> packed, reference;
};
const PackedScene& packedScene(const std::string& scene, const std::string& codec) {
  static std::map<std::string, PackedScene> made;
  const std::string key = scene + "/" + codec;
  if (auto it = made.find(key); it != made.end()) return it->second;
  PackedScene p;
  auto glb = builtinSceneGlb(scene);
  EXPECT_TRUE(glb) << glb.error();
  if (glb) {
    p.packed = codec == "draco"     ? compressed::dracoCompressed(*glb)
               : codec == "meshopt" ? compressed::meshoptCompressed(*glb)
                                    : compressed::webpTextured(*glb);
    // WebP: OpenImageIO's writer is not bit-exact, so the reference holds the decoded pixels as PNG.
    p.reference = codec == "webp" ? compressed::pngOfWebpTextured(p.packed) : *glb;
  }
  return made.emplace(key, std::move(p)).first->second;
}

TEST_P(CompressedRender, MatchesTheUncompressedScene) {
  const Case& c = GetParam();
  if (!createPipeline(c.pipeline)) GTEST_SKIP() << "placeholder pipeline";
  const PackedScene& files = packedScene(c.scene, c.codec);
  ASSERT_FALSE(files.packed.empty() || files.reference.empty()) << c.scene << " " << c.codec;
  const std::vector<uint8_t>& packed = files.packed;
  const std::vector<uint8_t>& reference = files.reference;
  FrameSettings s;
  s.width = s.height = 128;
  if (c.scene == "skinned_tube") s.anim = AnimState{0, 0.5f};  // a bent pose: skinning data in use
  auto a = render(reference, c.scene + ".glb", c.pipeline, s);
  auto b = render(packed, c.scene + "-" + c.codec + ".glb", c.pipeline, s);
  ASSERT_TRUE(a) << a.error();
  ASSERT_TRUE(b) << b.error();
  auto m = compareImages(*a, *b);
  ASSERT_TRUE(m) << m.error();
  std::printf("[ %s ] %s %s: PSNR %.2f dB, >4/255 %.4f%%\n", c.codec.c_str(), c.pipeline.c_str(), c.scene.c_str(),
              m->psnr, 100 * m->fractionOver4);
  if (c.codec == "draco") {
    EXPECT_GE(m->psnr, 40.0);
    EXPECT_LE(m->fractionOver4, 0.01);
  } else {
    EXPECT_EQ(m->maxError, 0.0) << "lossless: identical images expected";
  }
}

INSTANTIATE_TEST_SUITE_P(AllGltfPipelines, CompressedRender, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return i.param.pipeline + "_" + i.param.scene + "_" + i.param.codec;
                         });

}  // namespace
