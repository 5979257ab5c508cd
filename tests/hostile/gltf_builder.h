// A tiny glTF 2.0 writer for tests: builds documents as raw JSON + one binary buffer so that
// hostile tests can produce files tinygltf's own writer would refuse to write (lying lengths,
// out-of-range indices, cycles...). Serialises as .glb, as .gltf with a data: URI, or as
// .gltf + external .bin. Also a minimal PNG encoder (stored deflate) for embedded textures.
// Header-only: used by tests/scene/test_scene_hostile.cpp, tests/cli/test_cli_hostile_corpus.cpp and
// the fuzz seed generator.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace mb::hostile {

using Bytes = std::vector<uint8_t>;
using Json = nlohmann::json;

// glTF component types.
constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125,
              kFloat = 5126;

inline void put32(Bytes& b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = uint8_t(v >> (8 * i));
}
inline uint32_t get32(const Bytes& b, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t(b[at + i]) << (8 * i);
  return v;
}
inline void append32(Bytes& b, uint32_t v) {
  b.resize(b.size() + 4);
  put32(b, b.size() - 4, v);
}
inline void appendBytes(Bytes& b, const void* p, size_t n) {
  const auto* c = static_cast<const uint8_t*>(p);
  b.insert(b.end(), c, c + n);
}
inline Bytes toBytes(const std::string& s) { return Bytes(s.begin(), s.end()); }

inline std::string base64(const Bytes& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    uint32_t v = (uint32_t(in[i]) << 16) | (uint32_t(in[i + 1]) << 8) | in[i + 2];
    out += t[v >> 18];
    out += t[(v >> 12) & 63];
    out += t[(v >> 6) & 63];
    out += t[v & 63];
  }
  if (i + 1 == in.size()) {
    uint32_t v = uint32_t(in[i]) << 16;
    out += t[v >> 18];
    out += t[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == in.size()) {
    uint32_t v = (uint32_t(in[i]) << 16) | (uint32_t(in[i + 1]) << 8);
    out += t[v >> 18];
    out += t[(v >> 12) & 63];
    out += t[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// PNG (8-bit RGBA, no filter, stored deflate blocks).
inline uint32_t crc32(const uint8_t* p, size_t n, uint32_t crc = 0) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

inline void pngChunk(Bytes& out, const char* type, const Bytes& data) {
  uint8_t len[4] = {uint8_t(data.size() >> 24), uint8_t(data.size() >> 16),
                    uint8_t(data.size() >> 8), uint8_t(data.size())};
  appendBytes(out, len, 4);
  Bytes td(type, type + 4);
  td.insert(td.end(), data.begin(), data.end());
  appendBytes(out, td.data(), td.size());
  uint32_t c = crc32(td.data(), td.size());
  uint8_t cb[4] = {uint8_t(c >> 24), uint8_t(c >> 16), uint8_t(c >> 8), uint8_t(c)};
  appendBytes(out, cb, 4);
}

inline Bytes zlibStored(const Bytes& raw) {
  Bytes z = {0x78, 0x01};
  size_t pos = 0;
  do {
    size_t n = std::min<size_t>(65535, raw.size() - pos);
    bool last = pos + n == raw.size();
    z.push_back(last ? 1 : 0);
    z.push_back(uint8_t(n));
    z.push_back(uint8_t(n >> 8));
    z.push_back(uint8_t(~n));
    z.push_back(uint8_t(~n >> 8));
    z.insert(z.end(), raw.begin() + long(pos), raw.begin() + long(pos + n));
    pos += n;
  } while (pos < raw.size());
  uint32_t a = 1, b = 0;
  for (uint8_t c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  uint32_t ad = (b << 16) | a;
  z.push_back(uint8_t(ad >> 24));
  z.push_back(uint8_t(ad >> 16));
  z.push_back(uint8_t(ad >> 8));
  z.push_back(uint8_t(ad));
  return z;
}

// A PNG whose IHDR declares width x height but whose pixel data holds `rgba` (w*h*4 bytes
// normally; pass fewer to make a lying header).
inline Bytes png(uint32_t width, uint32_t height, const Bytes& rgba, uint32_t dataWidth = 0,
                 uint32_t dataHeight = 0) {
  if (!dataWidth) dataWidth = width;
  if (!dataHeight) dataHeight = height;
  Bytes out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  Bytes ihdr;
  for (uint32_t v : {width, height}) {
    ihdr.push_back(uint8_t(v >> 24));
    ihdr.push_back(uint8_t(v >> 16));
    ihdr.push_back(uint8_t(v >> 8));
    ihdr.push_back(uint8_t(v));
  }
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA, deflate, no filter, no interlace
  pngChunk(out, "IHDR", ihdr);
  Bytes raw;
  for (uint32_t y = 0; y < dataHeight; ++y) {
    raw.push_back(0);  // filter: none
    for (uint32_t x = 0; x < dataWidth * 4; ++x) {
      size_t i = size_t(y) * dataWidth * 4 + x;
      raw.push_back(i < rgba.size() ? rgba[i] : 0);
    }
  }
  pngChunk(out, "IDAT", zlibStored(raw));
  pngChunk(out, "IEND", {});
  return out;
}

// A PNG with any IHDR fields and already-packed scanlines (filter byte 0 is prepended to each
// row; for Adam7, pass the reduced rows of the seven passes in order). Optional PLTE and tRNS.
inline Bytes pngRaw(uint32_t w, uint32_t h, uint8_t depth, uint8_t colourType, const std::vector<Bytes>& rows,
                    const Bytes& plte = {}, const Bytes& trns = {}, bool adam7 = false) {
  Bytes out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  Bytes ihdr;
  for (uint32_t v : {w, h})
    for (int s = 24; s >= 0; s -= 8) ihdr.push_back(uint8_t(v >> s));
  ihdr.insert(ihdr.end(), {depth, colourType, 0, 0, uint8_t(adam7 ? 1 : 0)});
  pngChunk(out, "IHDR", ihdr);
  if (!plte.empty()) pngChunk(out, "PLTE", plte);
  if (!trns.empty()) pngChunk(out, "tRNS", trns);
  Bytes raw;
  for (const Bytes& r : rows) {
    raw.push_back(0);
    raw.insert(raw.end(), r.begin(), r.end());
  }
  pngChunk(out, "IDAT", zlibStored(raw));
  pngChunk(out, "IEND", {});
  return out;
}

inline Bytes checkerPng(uint32_t size = 4) {
  Bytes px;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      bool on = ((x ^ y) & 1) != 0;
      px.insert(px.end(), {uint8_t(on ? 255 : 40), uint8_t(on ? 200 : 40), 80, 255});
    }
  return png(size, size, px);
}

// ---------------------------------------------------------------------------------------------
// A glTF document: JSON + the bytes of buffer 0 (the GLB BIN chunk / data: URI / .bin file).
struct Doc {
  Json j;
  Bytes bin;

  Doc() {
    j = Json::object();
    j["asset"] = {{"version", "2.0"}, {"generator", "motorbench hostile-input generator"}};
  }

  Json& arr(const char* key) {
    if (!j.contains(key)) j[key] = Json::array();
    return j[key];
  }
  static int push(Json& a, Json v) {
    a.push_back(std::move(v));
    return int(a.size()) - 1;
  }

  // Appends raw bytes to the buffer (4-byte aligned) and returns a bufferView index.
  int view(const void* data, size_t n, int stride = 0, int target = 0) {
    while (bin.size() % 4) bin.push_back(0);
    size_t off = bin.size();
    appendBytes(bin, data, n);
    Json v = {{"buffer", 0}, {"byteOffset", off}, {"byteLength", n}};
    if (stride) v["byteStride"] = stride;
    if (target) v["target"] = target;
    return push(arr("bufferViews"), v);
  }

  int accessor(int bufferView, int componentType, uint64_t count, const std::string& type,
               uint64_t byteOffset = 0) {
    Json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
    if (bufferView >= 0) a["bufferView"] = bufferView;
    if (byteOffset) a["byteOffset"] = byteOffset;
    return push(arr("accessors"), a);
  }

  template <class V>
  int floats(const std::vector<V>& v, const std::string& type, bool minMax = false) {
    int bv = view(v.data(), v.size() * sizeof(V));
    int a = accessor(bv, kFloat, v.size(), type);
    if (minMax && !v.empty()) {
      constexpr int n = int(sizeof(V) / sizeof(float));
      Json mn = Json::array(), mx = Json::array();
      for (int c = 0; c < n; ++c) {
        float lo = INFINITY, hi = -INFINITY;
        for (const V& e : v) {
          float x = reinterpret_cast<const float*>(&e)[c];
          if (std::isfinite(x)) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
          }
        }
        if (!std::isfinite(lo)) lo = hi = 0;
        mn.push_back(lo);
        mx.push_back(hi);
      }
      j["accessors"][a]["min"] = mn;
      j["accessors"][a]["max"] = mx;
    }
    return a;
  }
  int positions(const std::vector<glm::vec3>& p) { return floats(p, "VEC3", true); }
  int vec3(const std::vector<glm::vec3>& v) { return floats(v, "VEC3"); }
  int vec2(const std::vector<glm::vec2>& v) { return floats(v, "VEC2"); }
  int vec4(const std::vector<glm::vec4>& v) { return floats(v, "VEC4"); }
  int mat4(const std::vector<glm::mat4>& v) { return floats(v, "MAT4"); }
  int scalars(const std::vector<float>& v) { return floats(v, "SCALAR", true); }

  int indices16(const std::vector<uint16_t>& ix) {
    int bv = view(ix.data(), ix.size() * 2, 0, 34963);
    return accessor(bv, kUShort, ix.size(), "SCALAR");
  }
  int indices32(const std::vector<uint32_t>& ix) {
    int bv = view(ix.data(), ix.size() * 4, 0, 34963);
    return accessor(bv, kUInt, ix.size(), "SCALAR");
  }
  int joints(const std::vector<glm::u16vec4>& jv) {
    int bv = view(jv.data(), jv.size() * 8);
    return accessor(bv, kUShort, jv.size(), "VEC4");
  }

  int mesh(Json primitive) { return push(arr("meshes"), Json{{"primitives", {primitive}}}); }
  int node(Json n = Json::object()) { return push(arr("nodes"), std::move(n)); }
  int material(Json m) { return push(arr("materials"), std::move(m)); }
  int image(const Bytes& pngBytes) {
    int bv = view(pngBytes.data(), pngBytes.size());
    return push(arr("images"), Json{{"bufferView", bv}, {"mimeType", "image/png"}});
  }
  int texture(int image, int sampler = -1) {
    Json t = {{"source", image}};
    if (sampler >= 0) t["sampler"] = sampler;
    return push(arr("textures"), t);
  }
  void scene(const std::vector<int>& roots) {
    j["scenes"] = Json::array({Json{{"nodes", roots}}});
    j["scene"] = 0;
  }
  // Declares buffer 0 from `bin` (call last; tests may then lie about it).
  Doc& finish() {
    while (bin.size() % 4) bin.push_back(0);
    if (!bin.empty() && !j.contains("buffers")) j["buffers"] = Json::array({Json{{"byteLength", bin.size()}}});
    return *this;
  }
};

// ---------------------------------------------------------------------------------------------
// Serialisation.

// GLB container: 12-byte header, JSON chunk (space-padded), optional BIN chunk (zero-padded).
inline Bytes glbContainer(const std::string& json, const Bytes& bin, uint32_t version = 2) {
  std::string js = json;
  while (js.size() % 4) js += ' ';
  Bytes b = {'g', 'l', 'T', 'F'};
  append32(b, version);
  append32(b, 0);  // total length, patched below
  append32(b, uint32_t(js.size()));
  append32(b, 0x4E4F534Au);  // JSON
  appendBytes(b, js.data(), js.size());
  if (!bin.empty()) {
    Bytes pb = bin;
    while (pb.size() % 4) pb.push_back(0);
    append32(b, uint32_t(pb.size()));
    append32(b, 0x004E4942u);  // BIN
    appendBytes(b, pb.data(), pb.size());
  }
  put32(b, 8, uint32_t(b.size()));
  return b;
}

inline Bytes toGlb(const Doc& d) { return glbContainer(d.j.dump(), d.bin); }

// .gltf with buffer 0 embedded as a base64 data: URI.
inline Bytes toGltfEmbedded(const Doc& d) {
  Json j = d.j;
  if (j.contains("buffers") && !j["buffers"].empty() && !j["buffers"][0].contains("uri"))
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(d.bin);
  return toBytes(j.dump(1));
}

// .gltf whose buffer 0 is the external file `binName` (returned separately).
inline Bytes toGltfExternal(const Doc& d, const std::string& binName) {
  Json j = d.j;
  if (j.contains("buffers") && !j["buffers"].empty()) j["buffers"][0]["uri"] = binName;
  return toBytes(j.dump(1));
}

// Byte offsets of the GLB structure: ends of the header fields and chunk headers.
struct GlbLayout {
  size_t jsonStart = 20, jsonEnd = 20, binHeader = 0, binStart = 0, binEnd = 0;
  bool hasBin = false;
};
inline GlbLayout glbLayout(const Bytes& glb) {
  GlbLayout l;
  if (glb.size() < 20) return l;
  l.jsonEnd = 20 + size_t(get32(glb, 12));
  if (l.jsonEnd + 8 <= glb.size()) {
    l.hasBin = true;
    l.binHeader = l.jsonEnd;
    l.binStart = l.jsonEnd + 8;
    l.binEnd = l.binStart + size_t(get32(glb, l.jsonEnd));
  }
  return l;
}

}  // namespace mb::hostile
