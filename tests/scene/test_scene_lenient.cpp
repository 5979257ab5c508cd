// Lenient where three.js and the Sample Viewer are: invalid files those viewers draw
// load here too, each with its LoadStats counter, and their near relatives that are really broken
// stay errors with a message that says what is wrong. Every file is written byte by byte here.
//  - Draco: a declared accessor count other than the decoded one -> the decoded geometry, which
//    must equal what the same stream gives with the right count (dracoCountMismatch).
//  - GLB JSON chunk length not a multiple of 4, the BIN chunk right after it (three.js reads
//    chunks back to back) or at the next multiple of 4 behind padding -> the same Scene as the
//    padded file (jsonChunkUnpadded); a BIN chunk cut short stays "truncated GLB".
//  - a texture whose image does not exist, used by no material -> kept without image
//    (unusedTexturesWithoutImage); used by a material it stays an error naming both.
#include <gtest/gtest.h>

#include <string>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/hostile_cases.h"
#include "tests/scene/load_bytes.h"
#include "tests/support/compressed_gltf.h"

using namespace mb;
using hostile::Bytes;
using hostile::Doc;
using hostile::Json;

namespace {

using scene_test::load;

std::string refusal(const Bytes& bytes, const std::string& name) {
  auto s = loadGltfMemory(bytes, name);
  EXPECT_FALSE(s) << name << " loaded";
  return s ? "" : s.error();
}

// The only non-zero LoadStats counters of `s`, as inspect lists them.
nlohmann::json fallbacks(const Scene& s) {
  nlohmann::json out = nlohmann::json::object();
  const nlohmann::json all = toJson(s.stats);  // items() must not outlive it
  for (const auto& [k, v] : all.items())
    if (v != 0) out[k] = v;
  return out;
}

// `base` (a well-formed file's counters) with `key` set to 1.
nlohmann::json plus(nlohmann::json base, const std::string& key) {
  base[key] = 1;
  return base;
}

void expectSameGeometry(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t m = 0; m < a.meshes.size(); ++m) {
    ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size());
    for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
      const Primitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
      EXPECT_EQ(x.positions, y.positions);
      EXPECT_EQ(x.normals, y.normals);
      EXPECT_EQ(x.uv0, y.uv0);
      EXPECT_EQ(x.indices, y.indices);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Draco.

Bytes dracoBox() {
  auto glb = builtinSceneGlb("textured_box");
  EXPECT_TRUE(glb) << glb.error();
  return compressed::dracoCompressed(glb ? *glb : Bytes{});
}

// The Draco box with `edit` applied to its JSON.
Bytes editedDraco(const std::function<void(Json&)>& edit) {
  compressed::Glb g = compressed::splitGlb(dracoBox());
  edit(g.json);
  return compressed::joinGlb(g);
}

TEST(SceneLenient, DracoDeclaredCountOtherThanDecodedDrawsTheDecodedGeometry) {
  const Scene good = load(dracoBox(), "draco.glb");
  EXPECT_EQ(good.stats.dracoCountMismatch, 0);
  ASSERT_EQ(good.meshes.size(), 1u);
  const size_t points = good.meshes[0].primitives[0].positions.size();
  ASSERT_EQ(points, 24u) << "the box: 6 faces x 4 corners";

  struct Edit {
    const char* what;
    std::function<void(Json&)> edit;
  };
  const Edit edits[] = {
      {"POSITION declares one more", [](Json& j) {
         Json& a = j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<size_t>()];
         a["count"] = a["count"].get<int>() + 1;
       }},
      {"NORMAL and TEXCOORD_0 declare 4 fewer", [](Json& j) {
         for (const char* name : {"NORMAL", "TEXCOORD_0"}) {
           Json& a = j["accessors"][j["meshes"][0]["primitives"][0]["attributes"][name].get<size_t>()];
           a["count"] = a["count"].get<int>() - 4;
         }
       }},
      {"indices declare 3 more", [](Json& j) {
         Json& a = j["accessors"][j["meshes"][0]["primitives"][0]["indices"].get<size_t>()];
         a["count"] = a["count"].get<int>() + 3;
       }},
  };
  for (const Edit& e : edits) {
    SCOPED_TRACE(e.what);
    const Scene s = load(editedDraco(e.edit), "mismatch.glb");
    EXPECT_EQ(fallbacks(s), (nlohmann::json{{"dracoCountMismatch", 1}})) << "one primitive, nothing else repaired";
    EXPECT_EQ(s.compression.dracoPrimitives, 1);
    expectSameGeometry(good, s);
    EXPECT_EQ(s.meshes[0].primitives[0].positions.size(), points);
  }
}

TEST(SceneLenient, DracoComponentCountOtherThanDecodedStaysAnError) {
  const std::string e = refusal(editedDraco([](Json& j) {
                                  j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"].get<size_t>()]["type"] = "VEC2";
                                }),
                                "vec2.glb");
  EXPECT_NE(e.find("vec2.glb: mesh 0 primitive 0: KHR_draco_mesh_compression: accessor"), std::string::npos) << e;
  EXPECT_NE(e.find("elements of 2 components, the Draco data has 24 of 3"), std::string::npos) << e;
}

// ---------------------------------------------------------------------------------------------
// GLB JSON chunk.

// A textured quad (image in the BIN chunk) and its JSON text, whose length is not a multiple of 4.
struct Parts {
  std::string json;
  Bytes bin;
};
Parts texturedQuad() {
  Doc d;
  const int mat = hostile::normalMappedMaterial(d);
  hostile::quad(d, true, true, mat);
  d.finish();
  Parts p{d.j.dump(), d.bin};
  if (p.json.size() % 4 == 0) p.json += ' ';  // 4k + 1 bytes: unpadded
  EXPECT_NE(p.json.size() % 4, 0u);
  return p;
}

// GLB: header, JSON chunk declaring `json.size()` bytes followed by `gap` bytes, then the BIN
// chunk (declaring `binDeclared`, or its size) unless `bin` is empty. Lengths written as given.
Bytes glb(const std::string& json, const std::string& gap, const Bytes& bin, int64_t binDeclared = -1) {
  Bytes b = {'g', 'l', 'T', 'F'};
  hostile::append32(b, 2);
  hostile::append32(b, 0);
  hostile::append32(b, uint32_t(json.size()));
  hostile::append32(b, 0x4E4F534Au);
  b.insert(b.end(), json.begin(), json.end());
  b.insert(b.end(), gap.begin(), gap.end());
  if (!bin.empty()) {
    hostile::append32(b, uint32_t(binDeclared >= 0 ? uint64_t(binDeclared) : bin.size()));
    hostile::append32(b, 0x004E4942u);
    b.insert(b.end(), bin.begin(), bin.end());
  }
  hostile::put32(b, 8, uint32_t(b.size()));
  return b;
}

TEST(SceneLenient, UnpaddedJsonChunkLoadsAsThePaddedFileAndIsCounted) {
  const Parts p = texturedQuad();
  std::string padded = p.json;
  while (padded.size() % 4) padded += ' ';
  const Scene reference = load(glb(padded, "", p.bin), "padded.glb");
  EXPECT_EQ(reference.stats.jsonChunkUnpadded, 0);
  ASSERT_EQ(reference.images.size(), 1u);

  const std::string spaces(padded.size() - p.json.size(), ' ');
  const struct {
    const char* what;
    Bytes bytes;
  } cases[] = {
      {"BIN chunk right after the JSON (as three.js reads it)", glb(p.json, "", p.bin)},
      {"JSON padded with spaces, its length not", glb(p.json, spaces, p.bin)},
      {"JSON padded with zeros, its length not", glb(p.json, std::string(spaces.size(), '\0'), p.bin)},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const Scene s = load(c.bytes, "unpadded.glb");
    EXPECT_EQ(fallbacks(s), plus(fallbacks(reference), "jsonChunkUnpadded")) << "nothing else repaired";
    expectSameGeometry(reference, s);
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba, reference.images[0].rgba) << "the image is read from the BIN chunk";
  }

  // Without a BIN chunk (buffer 0 a data: URI in the JSON): nothing follows the JSON.
  Doc d;
  hostile::quad(d);
  d.finish();
  std::string embedded = nlohmann::json::parse(hostile::toGltfEmbedded(d)).dump();
  if (embedded.size() % 4 == 0) embedded += ' ';
  const Scene noBin = load(glb(embedded, "", {}), "unpadded-no-bin.glb");
  EXPECT_EQ(fallbacks(noBin), (nlohmann::json{{"jsonChunkUnpadded", 1}}));
  EXPECT_EQ(noBin.meshes.size(), 1u);

  // Both chunks unaligned: both counted.
  Bytes odd = p.bin;
  odd.push_back(0xAB);
  const Scene both = load(glb(p.json, "", odd), "both.glb");
  EXPECT_EQ(fallbacks(both), plus(plus(fallbacks(reference), "binChunkUnaligned"), "jsonChunkUnpadded"));
  expectSameGeometry(reference, both);
}

TEST(SceneLenient, TruncatedGlbAfterAnUnpaddedJsonChunkIsStillRefusedAsTruncated) {
  const Parts p = texturedQuad();
  // Cut: the header still declares the whole file.
  Bytes cut = glb(p.json, "", p.bin);
  const size_t whole = cut.size();
  cut.resize(whole - 16);
  std::string e = refusal(cut, "cut.glb");
  EXPECT_NE(e.find("cut.glb: truncated GLB: header declares " + std::to_string(whole) + " bytes, file has " +
                   std::to_string(whole - 16)),
            std::string::npos)
      << e;

  // Lengths consistent but the BIN chunk declares 16 bytes more than follow it.
  e = refusal(glb(p.json, "", p.bin, int64_t(p.bin.size()) + 16), "short-bin.glb");
  EXPECT_NE(e.find("short-bin.glb: truncated GLB: BIN chunk (after a JSON chunk of " + std::to_string(p.json.size()) +
                   " bytes, not a multiple of 4) declares " + std::to_string(p.bin.size() + 16) + " bytes, " +
                   std::to_string(p.bin.size()) + " remain"),
            std::string::npos)
      << e;

  // Neither a BIN chunk after the JSON nor padding before one: says so.
  e = refusal(glb(p.json, "xyz", p.bin), "garbage.glb");
  EXPECT_NE(e.find("GLB JSON chunk length " + std::to_string(p.json.size()) + " is not a multiple of 4 and no chunk starts at byte"),
            std::string::npos)
      << e;
}

// ---------------------------------------------------------------------------------------------
// Textures without image.

// The normal-mapped quad (texture 0, image 0) plus texture 1 with source `source`; `useIt`: the
// material's occlusionTexture is texture 1.
Bytes withSecondTexture(int source, bool useIt) {
  Doc d;
  const int mat = hostile::normalMappedMaterial(d);
  hostile::quad(d, true, true, mat);
  d.j["textures"].push_back({{"source", source}});
  if (useIt) d.j["materials"][0]["occlusionTexture"] = {{"index", 1}};
  d.finish();
  return hostile::toGlb(d);
}

TEST(SceneLenient, UnusedTextureWithoutImageIsKeptWithoutImageAndCounted) {
  const Scene s = load(withSecondTexture(7, false), "unused.glb");
  const Scene valid = load(withSecondTexture(0, false), "valid.glb");
  EXPECT_EQ(fallbacks(s), plus(fallbacks(valid), "unusedTexturesWithoutImage")) << "nothing else repaired";
  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.textures[0].image, 0);
  EXPECT_EQ(s.textures[1].image, -1);
  EXPECT_EQ(s.materials[0].baseColor.texture, 0) << "the used texture is untouched";

  EXPECT_EQ(valid.stats.unusedTexturesWithoutImage, 0);
  EXPECT_EQ(valid.textures[1].image, 0);
}

TEST(SceneLenient, UsedTextureWithoutImageStaysAnErrorNamingBoth) {
  const std::string e = refusal(withSecondTexture(7, true), "used.glb");
  EXPECT_NE(e.find("used.glb: texture 1 refers to image 7, which does not exist (1 images)"), std::string::npos) << e;
  // A missing sampler is outside this leniency (the issue names images): an error naming it.
  Doc d;
  const int mat = hostile::normalMappedMaterial(d);
  hostile::quad(d, true, true, mat);
  d.j["textures"].push_back({{"source", 0}, {"sampler", 4}});
  d.finish();
  const std::string f = refusal(hostile::toGlb(d), "sampler.glb");
  EXPECT_NE(f.find("sampler.glb: texture 1 refers to sampler 4, which does not exist (0 samplers)"), std::string::npos) << f;
}

}  // namespace
