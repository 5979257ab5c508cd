// The committed fuzz seed corpus: helpers and the image seeds; the glTF seeds
// are in seed_corpus_scenes.cpp, the only file that includes this one (others: seed_files.h).
//
// The corpus: small, valid glTF/GLB files with real variety, built with the hostile builder (tests/hostile/gltf_builder.h, raw JSON + one buffer)
// and the project's own writer (GlbBuilder), plus PNG/JPEG files for the image fuzzer. The
// loader's seeds cover every accessor component type and normalisation, sparse accessors,
// interleaved and padded strides, data: URIs, every animation path and interpolation, skins with
// and without inverse binds, both camera kinds, every material texture slot, embedded PNGs of
// every colour type and JPEGs (grey, 4:2:0, 4:4:4, progressive), KHR extensions the loader
// ignores, and .gltf files with external .bin (and image) neighbours.
//
// `fuzz_seeds --repo tests/fuzz/seeds` (fuzz build) writes them to seeds/loader and seeds/images;
// the files are committed, and test_scene_fuzz_seeds checks that they load and cover the above.
#pragma once
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pipelines/scene/builtin/gltf_writer.h"
#include "tests/fuzz/seed_files.h"
#include "tests/hostile/hostile_cases.h"

namespace mb::fuzz {

using hostile::Bytes;
using hostile::Doc;
using hostile::Json;
using hostile::kByte, hostile::kUByte, hostile::kShort, hostile::kUShort, hostile::kUInt, hostile::kFloat;


inline int componentSize(int ct) { return ct == kByte || ct == kUByte ? 1 : ct == kShort || ct == kUShort ? 2 : 4; }

// One value stored as component type `ct` (normalized: scaled to the type's range).
inline void encodeValue(Bytes& b, int ct, bool norm, float x) {
  auto put = [&](auto v) { hostile::appendBytes(b, &v, sizeof v); };
  switch (ct) {
    case kByte: put(int8_t(std::lround(norm ? x * 127.0f : x))); break;
    case kUByte: put(uint8_t(std::lround(norm ? x * 255.0f : x))); break;
    case kShort: put(int16_t(std::lround(norm ? x * 32767.0f : x))); break;
    case kUShort: put(uint16_t(std::lround(norm ? x * 65535.0f : x))); break;
    case kUInt: put(uint32_t(std::llround(norm ? double(x) * 4294967295.0 : double(x)))); break;
    default: put(x);
  }
}

// An accessor of `comps`-component elements stored as `ct`; elements are padded to 4 bytes as
// glTF requires for vertex attributes (byteStride written when padded). `minMax`: POSITION bounds.
inline int typed(Doc& d, int ct, bool norm, const std::string& type, int comps, const std::vector<float>& v,
                 bool minMax = false, int target = 0) {
  const int elem = componentSize(ct) * comps, stride = (elem + 3) / 4 * 4;
  const size_t n = v.size() / size_t(comps);
  Bytes data;
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < comps; ++c) encodeValue(data, ct, norm, v[i * size_t(comps) + size_t(c)]);
    data.resize(data.size() + size_t(stride - elem), 0);
  }
  int a = d.accessor(d.view(data.data(), data.size(), stride != elem ? stride : 0, target), ct, n, type);
  if (norm) d.j["accessors"][a]["normalized"] = true;
  if (minMax) {
    Json mn = Json::array(), mx = Json::array();
    for (int c = 0; c < comps; ++c) {
      float lo = v[size_t(c)], hi = lo;
      for (size_t i = 0; i < n; ++i) {
        lo = std::min(lo, v[i * size_t(comps) + size_t(c)]);
        hi = std::max(hi, v[i * size_t(comps) + size_t(c)]);
      }
      mn.push_back(lo);
      mx.push_back(hi);
    }
    d.j["accessors"][a]["min"] = mn;
    d.j["accessors"][a]["max"] = mx;
  }
  return a;
}

inline void useExtension(Doc& d, const std::string& ext, bool required = false) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    if (std::string(key) == "extensionsRequired" && !required) continue;
    auto& a = d.arr(key);
    if (std::find(a.begin(), a.end(), Json(ext)) == a.end()) a.push_back(ext);
  }
}

// A unit quad (node 0, scene 0) whose POSITION, TEXCOORD_0 and COLOR_0 are stored as `ct`.
inline Doc quantizedQuad(int ct, bool norm) {
  Doc d;
  const bool small = norm || ct == kFloat;  // values in [0, 1] (normalized) or integers
  const float s = small ? 1.0f : 2.0f;
  std::vector<float> pos = {0, 0, 0, s, 0, 0, s, s, 0, 0, s, 0};
  std::vector<float> uv = {0, 1, 1, 1, 1, 0, 0, 0};
  std::vector<float> col = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 0};
  if (!small)
    for (float& c : col) c = c * 2.0f;  // unnormalized integers: still a valid (if bright) colour
  Json attrs = {{"POSITION", typed(d, ct, norm, "VEC3", 3, pos, true, 34962)},
                {"NORMAL", ct == kByte || ct == kShort ? typed(d, ct, true, "VEC3", 3, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1})
                                                     : d.vec3(std::vector<glm::vec3>(4, {0, 0, 1}))},
                {"TEXCOORD_0", typed(d, ct, norm, "VEC2", 2, uv)},
                {"COLOR_0", typed(d, ct, norm, "VEC4", 4, col)}};
  std::vector<float> ix = {0, 1, 2, 0, 2, 3};
  const int ict = ct == kByte || ct == kUByte ? kUByte : ct == kShort || ct == kUShort ? kUShort : kUInt;
  Bytes ib;
  for (float i : ix) encodeValue(ib, ict, false, i);
  int ia = d.accessor(d.view(ib.data(), ib.size(), 0, 34963), ict, ix.size(), "SCALAR");
  d.mesh({{"attributes", attrs}, {"indices", ia}});
  d.node({{"mesh", 0}});
  d.scene({0});
  if (ct != kFloat) useExtension(d, "KHR_mesh_quantization", true);
  d.finish();
  return d;
}

inline const char* componentName(int ct) {
  return ct == kByte ? "byte" : ct == kUByte ? "ubyte" : ct == kShort ? "short" : ct == kUShort ? "ushort" : ct == kUInt ? "uint" : "float";
}

// Images ------------------------------------------------------------------------------------

// PNG or JPEG bytes written by OpenImageIO from `px` (w x h x channels, 8 or 16 bit). `hints`
// are ImageSpec attributes (JPEG quality, subsampling, progressive).
inline Bytes oiioImage(const char* format, int w, int h, int channels, bool wide, const std::vector<uint16_t>& px,
                       const std::vector<std::pair<std::string, std::string>>& hints = {}) {
  std::vector<unsigned char> file;
  OIIO::Filesystem::IOVecOutput vec(file);
  auto out = OIIO::ImageOutput::create(format, &vec);
  if (!out) return {};
  OIIO::ImageSpec spec(w, h, channels, wide ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  for (const auto& [k, v] : hints) spec.attribute(k, v);
  if (!out->open(std::string("memory.") + format, spec)) return {};
  std::vector<uint8_t> narrow(px.begin(), px.end());
  bool ok = wide ? out->write_image(OIIO::TypeDesc::UINT16, px.data()) : out->write_image(OIIO::TypeDesc::UINT8, narrow.data());
  out->close();
  return ok ? Bytes(file.begin(), file.end()) : Bytes{};
}

// A w x h pattern: smooth ramps plus a few hard edges, `channels` samples per pixel.
inline std::vector<uint16_t> pattern(int w, int h, int channels, bool wide) {
  std::vector<uint16_t> px;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) {
        int v = (x * 255 / std::max(w - 1, 1) + c * 80 + ((x / 4 + y / 4) % 2) * 60) % 256;
        if (c == 3 || (channels == 2 && c == 1)) v = 255 - y * 255 / std::max(h - 1, 1);  // alpha ramp
        px.push_back(uint16_t(wide ? v * 257 + (x & 1) : v));
      }
  return px;
}

// Every PNG colour type and bit depth, interlaced, with tRNS, and JPEGs. Names say what.
std::vector<SeedFile> imageSeeds() {
  using hostile::pngRaw;
  std::vector<SeedFile> s;
  auto png = [&](const std::string& n, int ch, bool wide) { s.push_back({n, oiioImage("png", 12, 8, ch, wide, pattern(12, 8, ch, wide))}); };
  png("png_grey8.png", 1, false);
  png("png_grey16.png", 1, true);
  png("png_grey_alpha8.png", 2, false);
  png("png_rgb8.png", 3, false);
  png("png_rgb16.png", 3, true);
  png("png_rgba8.png", 4, false);
  png("png_rgba16.png", 4, true);
  s.push_back({"png_palette8_trns.png", pngRaw(3, 2, 8, 3, {{2, 0, 1}, {1, 2, 0}}, {10, 20, 30, 40, 50, 60, 70, 80, 90}, {0, 128})});
  s.push_back({"png_palette2.png", pngRaw(4, 2, 2, 3, {{0x1B}, {0xE4}}, {0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255})});
  s.push_back({"png_grey1.png", pngRaw(8, 2, 1, 0, {{0xB5}, {0x4A}})});
  s.push_back({"png_grey4_trns.png", pngRaw(4, 1, 4, 0, {{0x3F, 0x70}}, {}, {0, 7})});
  s.push_back({"png_rgb8_adam7.png", pngRaw(2, 2, 8, 2, {{1, 2, 3}, {4, 5, 6}, {7, 8, 9, 10, 11, 12}}, {}, {}, true)});
  auto jpg = [&](const std::string& n, int ch, std::vector<std::pair<std::string, std::string>> hints) {
    s.push_back({n, oiioImage("jpeg", 16, 16, ch, false, pattern(16, 16, ch, false), hints)});
  };
  jpg("jpeg_rgb_420_q90.jpg", 3, {{"Compression", "jpeg:90"}});
  jpg("jpeg_rgb_444_q100.jpg", 3, {{"Compression", "jpeg:100"}, {"jpeg:subsampling", "4:4:4"}});
  jpg("jpeg_rgb_422_q75.jpg", 3, {{"Compression", "jpeg:75"}, {"jpeg:subsampling", "4:2:2"}});
  jpg("jpeg_grey_q90.jpg", 1, {{"Compression", "jpeg:90"}});
  jpg("jpeg_rgb_progressive.jpg", 3, {{"Compression", "jpeg:85"}, {"jpeg:progressive", "1"}});
  return s;
}

// A quad textured with `image` (PNG or JPEG bytes) as base colour.
inline Doc texturedQuad(const Bytes& image, const std::string& mime) {
  Doc d;
  int bv = d.view(image.data(), image.size());
  int img = Doc::push(d.arr("images"), Json{{"bufferView", bv}, {"mimeType", mime}});
  int tex = d.texture(img);
  int mat = d.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", tex}}}}}});
  hostile::quad(d, true, true, mat);
  d.finish();
  return d;
}

}  // namespace mb::fuzz
