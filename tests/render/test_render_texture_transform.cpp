// KHR_texture_transform in forward.fs, through every pipeline, against images derived
// by hand. The scene: the quad [-1, 1]^2 at z = 0 seen by a glTF camera at (0, 0, 2) with
// yfov = 2 atan(1/2), so it fills a 64 x 64 frame exactly and pixel (x, y) (top row first) sees
// uv = ((x + 0.5) / 64, (y + 0.5) / 64) (glTF uv: origin top left, v down). The texture is 2 x 2
// texels, NEAREST, REPEAT:  R G  (row v < 0.5)
//                           B W  (row v > 0.5)
// Samples at x, y in {8, 24, 40, 56}, i.e. u, v in {0.133, 0.383, 0.633, 0.883}: each transformed
// coordinate below stays >= 0.1 away from a texel edge (multiples of 0.5).
// The extension's matrix: uv' = T(offset) R(rotation) S(scale) (uv, 1), R turning the uvs
// counter-clockwise in uv space, whose v axis points down: u' = cos u + sin v, v' = -sin u +
// cos v (github.com/KhronosGroup/glTF/issues/1563: three.js, Babylon.js, the Sample Viewer; the
// README's GLSL listing has the other sign, which these tables tell apart).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"
#include "tests/hostile/gltf_builder.h"

using namespace mb;
using hostile::Bytes;
using hostile::Doc;
using hostile::Json;

namespace {

constexpr int kSize = 64;
constexpr int kSamples[4] = {8, 24, 40, 56};
constexpr double kQuarterTurn = 1.5707963267948966;

// The 2 x 2 texture above, as a PNG.
Bytes texturePng() {
  return hostile::png(2, 2, {255, 0, 0, 255, 0, 255, 0, 255,  // R G
                             0, 0, 255, 255, 255, 255, 255, 255});  // B W
}

// The quad with uv0 `uv0` (corners (-1,-1), (1,-1), (1,1), (-1,1)), uv1 = uv0 transposed, an
// explicit tangent frame (nothing is generated from the uvs), `material` and the camera.
Bytes quadScene(const Json& material, const std::vector<glm::vec2>& uv0) {
  Doc d;
  const int sampler = d.push(d.arr("samplers"), Json{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 10497}, {"wrapT", 10497}});
  d.texture(d.image(texturePng()), sampler);
  d.material(material);
  std::vector<glm::vec2> uv1;
  for (const glm::vec2& t : uv0) uv1.push_back({t.y, t.x});
  Json attributes = {{"POSITION", d.positions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}})},
                     {"NORMAL", d.vec3(std::vector<glm::vec3>(4, {0, 0, 1}))},
                     {"TANGENT", d.vec4(std::vector<glm::vec4>(4, {1, 0, 0, 1}))},
                     {"TEXCOORD_0", d.vec2(uv0)},
                     {"TEXCOORD_1", d.vec2(uv1)}};
  d.mesh({{"attributes", attributes}, {"indices", d.indices16({0, 1, 2, 0, 2, 3})}, {"material", 0}});
  d.push(d.arr("cameras"), Json{{"type", "perspective"},
                                {"perspective", {{"yfov", 2 * std::atan(0.5)}, {"znear", 0.1}, {"zfar", 10}, {"aspectRatio", 1}}}});
  d.node({{"mesh", 0}});
  d.node({{"camera", 0}, {"translation", {0, 0, 2}}});
  d.scene({0, 1});
  Json& used = d.arr("extensionsUsed");
  used.push_back("KHR_texture_transform");
  d.finish();
  return hostile::toGlb(d);
}

const std::vector<glm::vec2> kQuadUv = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};

Frame render(const Bytes& glb, const std::string& pipeline) {
  auto scene = loadGltfMemory(glb, "texture_transform.glb");
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {};
  EXPECT_EQ(scene->unsupported, std::vector<std::string>{}) << "the extension is drawn, not listed";
  FrameSettings settings;
  settings.width = settings.height = kSize;
  settings.camera = 0;
  auto f = renderFrame(*scene, pipeline, settings);
  EXPECT_TRUE(f) << f.error();
  return f ? *f : Frame{};
}

// The texel colour seen at the 16 samples, rows top to bottom: "RRGG/RRGG/BBWW/BBWW". A channel
// counts as lit above half: the emissive texel is 0 or 1, the lighting of a black metal adds < 2%.
std::string samples(const RgbaImage& image) {
  std::string out;
  for (int y : kSamples) {
    if (!out.empty()) out += '/';
    for (int x : kSamples) {
      const uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
      const int bits = (p[0] > 128) | (p[1] > 128) << 1 | (p[2] > 128) << 2;
      out += bits == 1 ? 'R' : bits == 2 ? 'G' : bits == 4 ? 'B' : bits == 7 ? 'W' : '?';
    }
  }
  return out;
}

// The emissive-only material: black metal (no diffuse, Fresnel f0 = 0), emissive = the texture.
Json emissiveMaterial(const Json& textureInfo) {
  return {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 1}}},
          {"emissiveFactor", {1, 1, 1}},
          {"emissiveTexture", textureInfo}};
}

Json transformed(const Json& ext) {
  return {{"index", 0}, {"texCoord", 0}, {"extensions", {{"KHR_texture_transform", ext}}}};
}

TEST(RenderTextureTransform, EmissiveTexelsMatchHandDerivedTablesInEveryPipeline) {
  struct Case {
    const char* what;
    Json textureInfo;
    const char* expected;
  };
  const Case cases[] = {
      // u -> column floor(2u): 0 0 1 1; v -> row: 0 0 1 1.
      {"no transform", {{"index", 0}}, "RRGG/RRGG/BBWW/BBWW"},
      // u + 0.5 = 0.633 0.883 1.133 1.383: columns 1 1 0 0.
      {"offset (0.5, 0)", transformed({{"offset", {0.5, 0}}}), "GGRR/GGRR/WWBB/WWBB"},
      // 2u = 0.27 0.77 1.27 1.77: columns 0 1 0 1; v / 2 < 0.45: row 0 everywhere.
      {"scale (2, 0.5)", transformed({{"scale", {2, 0.5}}}), "RGRG/RGRG/RGRG/RGRG"},
      // u' = v: column from the row's v (0 0 1 1 down the rows); v' = -u = 0.867 0.617 0.367
      // 0.117 (mod 1): rows 1 1 0 0 across. The image turned a quarter clockwise: B R / W G.
      {"rotation pi/2", transformed({{"rotation", kQuarterTurn}}), "BBRR/BBRR/WWGG/WWGG"},
      // The extension's texCoord 1 overrides the textureInfo's 0: TEXCOORD_1 = (v, u), column from
      // v (0 0 1 1 down the rows), row from u (0 0 1 1 across).
      {"texCoord 1 (overriding 0)", transformed({{"texCoord", 1}}), "RRBB/RRBB/GGWW/GGWW"},
      // S: (2u, v); R: (v, -2u); T: u' = v + 0.25 = 0.383 0.633 0.883 1.133 -> columns 0 1 1 0
      // down the rows; v' = 0.5 - 2u = 0.234 -0.266 -0.766 -1.266 = 0.234 0.734 0.234 0.734
      // (mod 1) -> rows 0 1 0 1 across.
      {"offset (0.25, 0.5), rotation pi/2, scale (2, 1)",
       transformed({{"offset", {0.25, 0.5}}, {"rotation", kQuarterTurn}, {"scale", {2, 1}}}), "RBRB/GWGW/GWGW/RBRB"},
  };
  for (const std::string& p : pipelineNames()) {
    for (const Case& c : cases) {
      SCOPED_TRACE(p + ": " + c.what);
      const Frame f = render(quadScene(emissiveMaterial(c.textureInfo), kQuadUv), p);
      ASSERT_EQ(f.image.width, kSize);
      EXPECT_EQ(samples(f.image), c.expected);
    }
  }
}

// Every textureInfo takes the transform: for each slot, the quad with the combined transform on
// that slot draws, at the 16 samples, what the quad without it draws when its uvs are the
// transformed ones, computed by hand at the corners (affine maps commute with interpolation):
// u' = v + 0.25, v' = 0.5 - 2u: (0, 1) -> (1.25, 0.5), (1, 1) -> (1.25, -1.5), (1, 0) -> (0.25,
// -1.5), (0, 0) -> (0.25, 0.5). And it differs from the untransformed quad there.
TEST(RenderTextureTransform, EverySlotSamplesThroughItsTransformInEveryPipeline) {
  const Json ext = {{"offset", {0.25, 0.5}}, {"rotation", kQuarterTurn}, {"scale", {2, 1}}};
  const std::vector<glm::vec2> bakedUv = {{1.25f, 0.5f}, {1.25f, -1.5f}, {0.25f, -1.5f}, {0.25f, 0.5f}};
  auto material = [](const char* slot, const Json& info) {
    Json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.6}}},
              {"emissiveFactor", {0.2, 0.2, 0.2}}};
    if (std::string(slot) == "baseColorTexture" || std::string(slot) == "metallicRoughnessTexture")
      m["pbrMetallicRoughness"][slot] = info;
    else
      m[slot] = info;
    return m;
  };
  auto at = [](const RgbaImage& image, int x, int y) {
    const size_t i = (size_t(y) * size_t(image.width) + size_t(x)) * 4;
    return std::vector<uint8_t>(image.rgba.begin() + long(i), image.rgba.begin() + long(i + 4));
  };
  for (const std::string& p : pipelineNames())
    for (const char* slot : {"baseColorTexture", "metallicRoughnessTexture", "normalTexture", "occlusionTexture", "emissiveTexture"}) {
      SCOPED_TRACE(p + ": " + slot);
      const Frame withTransform = render(quadScene(material(slot, transformed(ext)), kQuadUv), p);
      const Frame baked = render(quadScene(material(slot, {{"index", 0}}), bakedUv), p);
      const Frame plain = render(quadScene(material(slot, {{"index", 0}}), kQuadUv), p);
      ASSERT_EQ(withTransform.image.width, kSize);
      int differs = 0;
      for (int y : kSamples)
        for (int x : kSamples) {
          EXPECT_EQ(at(withTransform.image, x, y), at(baked.image, x, y)) << "pixel " << x << ", " << y;
          differs += at(withTransform.image, x, y) != at(plain.image, x, y);
        }
      EXPECT_GT(differs, 0) << "the transform changes what the slot samples";
      // The transform's mat3 is the only uniform added, and only for the slot that has one.
      EXPECT_EQ(withTransform.stats.uniformBytesPerFrame, plain.stats.uniformBytesPerFrame + 9 * sizeof(float));
    }
}

// An identity transform ({} : offset 0, rotation 0, scale 1) goes through the matrix and draws
// the same bytes as no transform (1 u + 0 v + 0 is exact in floating point).
TEST(RenderTextureTransform, IdentityTransformDrawsTheUntransformedImage) {
  for (const std::string& p : pipelineNames()) {
    SCOPED_TRACE(p);
    const Frame identity = render(quadScene(emissiveMaterial(transformed(Json::object())), kQuadUv), p);
    const Frame plain = render(quadScene(emissiveMaterial({{"index", 0}}), kQuadUv), p);
    EXPECT_EQ(identity.image.rgba, plain.image.rgba);
  }
}

// KHR_materials_emissive_strength multiplies the emissive factor (loaded, not listed).
TEST(RenderTextureTransform, EmissiveStrengthMultipliesTheEmissiveFactor) {
  Json m = emissiveMaterial({{"index", 0}});
  m["emissiveFactor"] = {0.25, 0.125, 0.5};
  m["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}};
  auto scene = loadGltfMemory(quadScene(m, kQuadUv), "strength.glb");
  ASSERT_TRUE(scene) << scene.error();
  EXPECT_EQ(scene->materials[0].emissiveFactor, glm::vec3(1.0f, 0.5f, 2.0f));
  EXPECT_EQ(scene->unsupported, std::vector<std::string>{});
}

}  // namespace
