// KHR_draco_mesh_compression through Draco's own decoder (libdraco); see compressed_geometry.h.
#include <draco/compression/decode.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/compressed_geometry.h"

namespace mb {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";
constexpr int kTriangles = 4, kStrip = 5, kFan = 6;

// The glTF componentType of a Draco integer type, 0 for floats (normalizedValue needs it).
int gltfComponentType(draco::DataType t) {
  switch (t) {
    case draco::DT_INT8: return TINYGLTF_COMPONENT_TYPE_BYTE;
    case draco::DT_UINT8: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    case draco::DT_INT16: return TINYGLTF_COMPONENT_TYPE_SHORT;
    case draco::DT_UINT16: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    case draco::DT_UINT32: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    default: return 0;
  }
}

// One stored component as a double; false for types glTF cannot hold (64-bit, bool).
bool component(const uint8_t* p, draco::DataType t, double* out) {
  switch (t) {
    case draco::DT_INT8: { int8_t v; std::memcpy(&v, p, 1); *out = v; return true; }
    case draco::DT_UINT8: *out = *p; return true;
    case draco::DT_INT16: { int16_t v; std::memcpy(&v, p, 2); *out = v; return true; }
    case draco::DT_UINT16: { uint16_t v; std::memcpy(&v, p, 2); *out = v; return true; }
    case draco::DT_INT32: { int32_t v; std::memcpy(&v, p, 4); *out = v; return true; }
    case draco::DT_UINT32: { uint32_t v; std::memcpy(&v, p, 4); *out = v; return true; }
    case draco::DT_FLOAT32: { float v; std::memcpy(&v, p, 4); *out = v; return true; }
    default: return false;
  }
}

int intMember(const tinygltf::Value& o, const char* key, int fallback) {
  const tinygltf::Value& v = o.Get(key);
  return v.IsInt() ? v.GetNumberAsInt() : v.IsNumber() ? -1 : fallback;
}

// Appends `bytes` to the model as a buffer with one bufferView; returns the view's index.
int appendView(tinygltf::Model& m, std::vector<unsigned char> bytes) {
  tinygltf::Buffer b;
  tinygltf::BufferView v;
  v.buffer = int(m.buffers.size());
  v.byteLength = bytes.size();
  b.data = std::move(bytes);
  m.buffers.push_back(std::move(b));
  m.bufferViews.push_back(v);
  return int(m.bufferViews.size()) - 1;
}

// A copy of accessor `index` that reads `view` (`count` tight FLOAT or UNSIGNED_INT values); the
// declared one keeps its count (the loader compares the two: LoadStats::dracoCountMismatch) and
// loses its bounds (nothing of it is read). Returns the copy's index.
int replaceAccessor(tinygltf::Model& m, int index, int view, bool integer, size_t count) {
  tinygltf::Accessor a = m.accessors[size_t(index)];
  a.count = count;
  m.accessors[size_t(index)].minValues.clear();
  m.accessors[size_t(index)].maxValues.clear();
  a.bufferView = view;
  a.byteOffset = 0;
  a.componentType = integer ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.normalized = false;
  a.sparse = {};
  a.minValues.clear();
  a.maxValues.clear();
  m.accessors.push_back(a);
  return int(m.accessors.size()) - 1;
}

// Attribute `name` (accessor `index`) from Draco attribute `att`, per point, as the declared
// accessor's values: floats (normalized integers mapped as glTF says) or exact unsigned integers.
// One value per decoded point, whatever count the accessor declares: three.js draws the decoded
// geometry too; only a different component count is an error.
Result<std::vector<unsigned char>> attributeValues(const tinygltf::Model& m, const draco::Mesh& mesh,
                                                   const draco::PointAttribute& att, int index,
                                                   const std::string& name) {
  using R = Result<std::vector<unsigned char>>;
  const tinygltf::Accessor& acc = m.accessors[size_t(index)];
  const std::string who = "accessor " + std::to_string(index) + " (" + name + ")";
  const int comps = typeComponents(acc.type);
  if (comps != att.num_components())
    return R::fail(who + " declares " + std::to_string(acc.count) + " elements of " + std::to_string(comps) +
                   " components, the Draco data has " + std::to_string(mesh.num_points()) + " of " +
                   std::to_string(int(att.num_components())));
  const bool integer = acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !acc.normalized;
  const bool normalize = acc.normalized || att.normalized();
  const int storedType = gltfComponentType(att.data_type());
  const size_t typeBytes = size_t(draco::DataTypeLength(att.data_type()));
  std::vector<unsigned char> out(size_t(mesh.num_points()) * size_t(comps) * 4);
  for (uint32_t p = 0; p < mesh.num_points(); ++p) {
    const uint8_t* at = att.GetAddress(att.mapped_index(draco::PointIndex(p)));
    for (int c = 0; c < comps; ++c) {
      double v = 0;
      if (!component(at + size_t(c) * typeBytes, att.data_type(), &v))
        return R::fail(who + ": Draco data type " + std::to_string(int(att.data_type())) + " has no glTF equivalent");
      unsigned char* dst = out.data() + (size_t(p) * size_t(comps) + size_t(c)) * 4;
      if (integer) {
        if (!(v >= 0 && v <= 4294967295.0 && v == std::floor(v)))
          return R::fail(who + ": decoded value " + std::to_string(v) + " is not an unsigned integer");
        const uint32_t u = uint32_t(v);
        std::memcpy(dst, &u, 4);
      } else {
        const float f = float(normalize && storedType ? normalizedValue(v, storedType) : v);
        std::memcpy(dst, &f, 4);
      }
    }
  }
  return out;
}

Status decodePrimitive(tinygltf::Model& m, tinygltf::Primitive& prim, CompressionStats& stats) {
  const tinygltf::Value& ext = prim.extensions.at(kDraco);
  if (!ext.IsObject()) return Status::fail("the extension is not an object");
  const int view = intMember(ext, "bufferView", -1);
  if (view < 0 || size_t(view) >= m.bufferViews.size())
    return Status::fail("bufferView " + std::to_string(view) + " does not exist");
  const tinygltf::BufferView& bv = m.bufferViews[size_t(view)];
  if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size())
    return Status::fail("bufferView " + std::to_string(view) + " refers to missing buffer " + std::to_string(bv.buffer));
  const auto& data = m.buffers[size_t(bv.buffer)].data;
  if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
    return Status::fail("bufferView " + std::to_string(view) + " lies outside buffer " + std::to_string(bv.buffer));
  for (const auto& [name, acc] : prim.attributes)
    if (acc < 0 || size_t(acc) >= m.accessors.size() || m.accessors[size_t(acc)].count > kMaxAccessorCount)
      return Status::fail("accessor " + std::to_string(acc) + " (" + name + ") does not exist or is too large");

  const size_t compressedBytes = bv.byteLength;  // bv and data move when buffers are appended
  draco::DecoderBuffer in;
  in.Init(reinterpret_cast<const char*>(data.data() + bv.byteOffset), compressedBytes);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&in);
  if (!decoded.ok()) return Status::fail("Draco data does not decode: " + decoded.status().error_msg_string());
  const draco::Mesh& mesh = *decoded.value();
  if (mesh.num_faces() == 0 || mesh.num_points() == 0)
    return Status::fail("Draco data holds no triangles (" + std::to_string(mesh.num_faces()) + " faces, " +
                        std::to_string(mesh.num_points()) + " points)");
  uint64_t decodedBytes = 0;

  const tinygltf::Value& ids = ext.Get("attributes");
  if (!ids.IsObject()) return Status::fail("the extension has no 'attributes' object");
  for (const std::string& name : ids.Keys()) {
    auto it = prim.attributes.find(name);
    if (it == prim.attributes.end()) continue;  // only the primitive's own attributes are used
    const int id = intMember(ids, name.c_str(), -1);
    const draco::PointAttribute* att = id >= 0 ? mesh.GetAttributeByUniqueId(uint32_t(id)) : nullptr;
    if (!att) return Status::fail(name + ": the Draco data has no attribute with id " + std::to_string(id));
    auto values = attributeValues(m, mesh, *att, it->second, name);
    if (!values) return Status::fail(values.error());
    const tinygltf::Accessor& acc = m.accessors[size_t(it->second)];
    const bool integer = acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !acc.normalized;
    decodedBytes += values->size();
    it->second = replaceAccessor(m, it->second, appendView(m, values.take()), integer, mesh.num_points());
  }

  // Indices: the decoded faces, in order (a non-indexed primitive draws them as stored).
  std::vector<unsigned char> indices(size_t(mesh.num_faces()) * 12);
  for (uint32_t f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.face(draco::FaceIndex(f))[k].value();
      std::memcpy(indices.data() + (size_t(f) * 3 + size_t(k)) * 4, &v, 4);
    }
  if (prim.indices >= 0) {
    if (size_t(prim.indices) >= m.accessors.size())
      return Status::fail("indices accessor " + std::to_string(prim.indices) + " does not exist");
    const tinygltf::Accessor& acc = m.accessors[size_t(prim.indices)];
    if (acc.type != TINYGLTF_TYPE_SCALAR)  // a count other than 3 x the decoded faces: the faces are used
      return Status::fail("indices accessor " + std::to_string(prim.indices) + " is not SCALAR");
  }
  decodedBytes += indices.size();
  const int indexView = appendView(m, std::move(indices));
  if (prim.indices >= 0) {
    prim.indices = replaceAccessor(m, prim.indices, indexView, true, size_t(mesh.num_faces()) * 3);
  } else {  // the glTF had no indices accessor: one is made for the decoded faces
    tinygltf::Accessor a;
    a.bufferView = indexView;
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = size_t(mesh.num_faces()) * 3;
    m.accessors.push_back(a);
    prim.indices = int(m.accessors.size()) - 1;
  }
  prim.mode = kTriangles;  // Draco holds triangle lists (strips and fans arrive as lists)
  ++stats.dracoPrimitives;
  stats.dracoCompressedBytes += compressedBytes;
  stats.dracoDecodedBytes += decodedBytes;
  return {};
}

}  // namespace

Status decodeDracoPrimitives(tinygltf::Model& m, CompressionStats& stats) {
  for (size_t mi = 0; mi < m.meshes.size(); ++mi)
    for (size_t pi = 0; pi < m.meshes[mi].primitives.size(); ++pi) {
      tinygltf::Primitive& prim = m.meshes[mi].primitives[pi];
      if (!prim.extensions.count(kDraco)) continue;
      if (prim.mode != kTriangles && prim.mode != kStrip && prim.mode != kFan && prim.mode != -1) continue;
      if (Status s = decodePrimitive(m, prim, stats); !s)
        return Status::fail("mesh " + std::to_string(mi) + " primitive " + std::to_string(pi) + ": " + kDraco + ": " +
                            s.error());
    }
  return {};
}

}  // namespace mb
