// Hand-built glTF documents for the scene tests: JSON + one binary buffer with known bytes,
// serialised as .gltf (data: URI) or .glb, so accessor layouts and malformed variants are
// exactly what a test states.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mbtest {

using Bytes = std::vector<uint8_t>;

inline std::string base64(const Bytes& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = uint32_t(in[i]) << 16;
    if (i + 1 < in.size()) v |= uint32_t(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= in[i + 2];
    out += t[v >> 18];
    out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? t[v & 63] : '=';
  }
  return out;
}

struct TestGltf {
  nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
  Bytes bin;

  template <class T>
  size_t append(const std::vector<T>& values) {  // 4-aligned start
    while (bin.size() % 4) bin.push_back(0);
    size_t at = bin.size();
    bin.resize(at + values.size() * sizeof(T));
    std::memcpy(bin.data() + at, values.data(), values.size() * sizeof(T));
    return at;
  }
  int view(size_t offset, size_t length, int stride = 0) {
    nlohmann::json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
    if (stride) v["byteStride"] = stride;
    doc["bufferViews"].push_back(v);
    return int(doc["bufferViews"].size() - 1);
  }
  template <class T>
  int viewOf(const std::vector<T>& values, int stride = 0) {
    size_t at = append(values);
    return view(at, values.size() * sizeof(T), stride);
  }
  int accessor(int view, int componentType, size_t count, const std::string& type, size_t byteOffset = 0,
               bool normalized = false) {
    nlohmann::json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
    if (view >= 0) a["bufferView"] = view;
    if (byteOffset) a["byteOffset"] = byteOffset;
    if (normalized) a["normalized"] = true;
    doc["accessors"].push_back(a);
    return int(doc["accessors"].size() - 1);
  }
  // One mesh with one primitive drawn by one node in scene 0.
  void meshPrimitive(const nlohmann::json& attributes, int indices = -1, int mode = 4) {
    nlohmann::json p = {{"attributes", attributes}, {"mode", mode}};
    if (indices >= 0) p["indices"] = indices;
    doc["meshes"] = {{{"primitives", {p}}}};
    doc["nodes"] = {{{"mesh", 0}}};
    doc["scenes"] = {{{"nodes", {0}}}};
    doc["scene"] = 0;
  }
  nlohmann::json bufferJson(bool glb) const {
    nlohmann::json b = {{"byteLength", bin.size()}};
    if (!glb) b["uri"] = "data:application/octet-stream;base64," + base64(bin);
    return b;
  }
  Bytes gltf() const {
    nlohmann::json d = doc;
    if (!bin.empty()) d["buffers"] = {bufferJson(false)};
    std::string s = d.dump();
    return Bytes(s.begin(), s.end());
  }
  Bytes glb() const {
    nlohmann::json d = doc;
    if (!bin.empty()) d["buffers"] = {bufferJson(true)};
    std::string json = d.dump();
    while (json.size() % 4) json += ' ';
    Bytes b = bin;
    while (b.size() % 4) b.push_back(0);
    Bytes out;
    auto u32 = [&](uint32_t v) { for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i))); };
    uint32_t total = uint32_t(12 + 8 + json.size() + (b.empty() ? 0 : 8 + b.size()));
    out.reserve(total);
    for (char c : std::string("glTF")) out.push_back(uint8_t(c));
    u32(2);
    u32(total);
    u32(uint32_t(json.size()));
    u32(0x4E4F534Au);
    out.insert(out.end(), json.begin(), json.end());
    if (!b.empty()) {
      u32(uint32_t(b.size()));
      u32(0x004E4942u);
      out.insert(out.end(), b.begin(), b.end());
    }
    return out;
  }
};

}  // namespace mbtest
