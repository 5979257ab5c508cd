// EXT_meshopt_compression / KHR_meshopt_compression through libmeshoptimizer; see
// compressed_geometry.h.
#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cstdint>
#include <tuple>

#include "pipelines/scene/gltf/compressed_geometry.h"

namespace mb {
namespace {

// Decoded bytes allowed per file: the codec packs zeros at well over 30:1, so the claimed
// size, not the payload's, bounds the allocation (the hostile tests refuse 256 MiB).
constexpr uint64_t kMaxDecodedBytes = uint64_t(1) << 27;

struct MeshoptView {
  int buffer = -1;
  uint64_t byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
  std::string mode, filter = "NONE";
};

// The extension's members; "" or the first one missing or malformed.
std::string readExtension(const tinygltf::Value& e, MeshoptView* v) {
  if (!e.IsObject()) return "the extension is not an object";
  auto whole = [&](const char* key, uint64_t* out, bool required) -> bool {
    const tinygltf::Value& x = e.Get(key);
    if (!x.IsNumber()) return !required && !e.Has(key);
    const double d = x.GetNumberAsDouble();
    if (!(d >= 0 && d <= 9007199254740992.0) || d != double(uint64_t(d))) return false;
    *out = uint64_t(d);
    return true;
  };
  uint64_t buffer = 0;
  for (auto [key, out, required] : {std::tuple{"buffer", &buffer, true}, std::tuple{"byteOffset", &v->byteOffset, false},
                                    std::tuple{"byteLength", &v->byteLength, true},
                                    std::tuple{"byteStride", &v->byteStride, true}, std::tuple{"count", &v->count, true}})
    if (!whole(key, out, required)) return std::string("'") + key + "' is missing or not a whole number";
  v->buffer = buffer > uint64_t(INT32_MAX) ? -1 : int(buffer);
  if (!e.Get("mode").IsString()) return "'mode' is missing";
  v->mode = e.Get("mode").Get<std::string>();
  if (e.Has("filter")) v->filter = e.Get("filter").IsString() ? e.Get("filter").Get<std::string>() : "?";
  return "";
}

// Why `v` cannot be decoded as the extension defines it, "" when it can.
std::string checkLayout(const MeshoptView& v) {
  const uint64_t s = v.byteStride;
  if (v.mode == "ATTRIBUTES") {
    if (s == 0 || s > 256 || s % 4) return "ATTRIBUTES byteStride " + std::to_string(s) + " (must be 4..256, a multiple of 4)";
  } else if (v.mode == "TRIANGLES" || v.mode == "INDICES") {
    if (s != 2 && s != 4) return v.mode + " byteStride " + std::to_string(s) + " (must be 2 or 4)";
    if (v.mode == "TRIANGLES" && v.count % 3) return "TRIANGLES count " + std::to_string(v.count) + " is not a multiple of 3";
    if (v.filter != "NONE") return "filter " + v.filter + " on " + v.mode + " data (filters apply to ATTRIBUTES)";
  } else {
    return "mode '" + v.mode + "' (ATTRIBUTES, TRIANGLES or INDICES)";
  }
  if (v.filter == "OCTAHEDRAL" && s != 4 && s != 8) return "OCTAHEDRAL filter with byteStride " + std::to_string(s) + " (4 or 8)";
  if (v.filter == "QUATERNION" && s != 8) return "QUATERNION filter with byteStride " + std::to_string(s) + " (8)";
  if (v.filter != "NONE" && v.filter != "OCTAHEDRAL" && v.filter != "QUATERNION" && v.filter != "EXPONENTIAL")
    return "filter '" + v.filter + "' (NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL)";
  return "";
}

const tinygltf::Value* meshoptExtension(const tinygltf::BufferView& view, std::string* name) {
  for (const char* ext : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
    auto it = view.extensions.find(ext);
    if (it == view.extensions.end()) continue;
    *name = ext;
    return &it->second;
  }
  return nullptr;
}

}  // namespace

Status decodeMeshoptViews(tinygltf::Model& m, CompressionStats& stats) {
  uint64_t decodedTotal = 0;
  const size_t viewCount = m.bufferViews.size();
  for (size_t i = 0; i < viewCount; ++i) {
    std::string ext;
    const tinygltf::Value* e = meshoptExtension(m.bufferViews[i], &ext);
    if (!e) continue;
    auto fail = [&](const std::string& why) { return Status::fail("bufferView " + std::to_string(i) + ": " + ext + ": " + why); };
    MeshoptView v;
    if (std::string why = readExtension(*e, &v); !why.empty()) return fail(why);
    if (std::string why = checkLayout(v); !why.empty()) return fail(why);
    if (v.buffer < 0 || size_t(v.buffer) >= m.buffers.size()) return fail("buffer " + std::to_string(v.buffer) + " does not exist");
    const auto& src = m.buffers[size_t(v.buffer)].data;
    if (v.byteOffset > src.size() || v.byteLength > src.size() - v.byteOffset)
      return fail("byteOffset " + std::to_string(v.byteOffset) + " + byteLength " + std::to_string(v.byteLength) +
                  " lies outside buffer " + std::to_string(v.buffer) + " (" + std::to_string(src.size()) + " bytes)");
    if (v.count > kMaxDecodedBytes / v.byteStride || (decodedTotal += v.count * v.byteStride) > kMaxDecodedBytes)
      return fail("decodes to more than " + std::to_string(kMaxDecodedBytes) + " bytes in this file (limit)");
    const uint64_t size = v.count * v.byteStride;
    if (m.bufferViews[i].byteLength != size)
      return fail("bufferView byteLength " + std::to_string(m.bufferViews[i].byteLength) + " is not count x byteStride = " +
                  std::to_string(size));
    std::vector<unsigned char> out(size_t(size), 0);
    const unsigned char* in = src.data() + v.byteOffset;
    int rc = 0;
    if (v.mode == "ATTRIBUTES") rc = meshopt_decodeVertexBuffer(out.data(), v.count, v.byteStride, in, v.byteLength);
    else if (v.mode == "TRIANGLES") rc = meshopt_decodeIndexBuffer(out.data(), v.count, v.byteStride, in, v.byteLength);
    else rc = meshopt_decodeIndexSequence(out.data(), v.count, v.byteStride, in, v.byteLength);
    if (rc != 0) return fail(v.mode + " data does not decode (meshoptimizer error " + std::to_string(rc) + ")");
    if (v.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), v.count, v.byteStride);
    if (v.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), v.count, v.byteStride);
    if (v.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), v.count, v.byteStride);
    stats.meshoptCompressedBytes += v.byteLength;
    stats.meshoptDecodedBytes += size;
    ++stats.meshoptViews;
    tinygltf::Buffer decoded;
    decoded.data = std::move(out);
    m.buffers.push_back(std::move(decoded));
    tinygltf::BufferView& view = m.bufferViews[i];
    view.buffer = int(m.buffers.size()) - 1;
    view.byteOffset = 0;
    if (v.mode == "ATTRIBUTES" && view.byteStride == 0) view.byteStride = v.byteStride;
    if (v.filter != "NONE")  // lossy: the declared bounds describe the data before the filter
      for (auto& a : m.accessors)
        if (a.bufferView == int(i)) a.minValues.clear(), a.maxValues.clear();
  }
  return {};
}

}  // namespace mb
