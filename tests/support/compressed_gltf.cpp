// Compressed versions of a GLB (tests/support/compressed_gltf.h). Compiled once (mb_test_hostile,
// tests/CMakeLists.txt): Draco's encoder and OpenImageIO's headers stay out of the test files.
#include "tests/support/compressed_gltf.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <meshoptimizer.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>

namespace mb::compressed {

Glb splitGlb(const Bytes& glb) {
  const uint32_t jsonLen = hostile::get32(glb, 12);
  Glb g;
  g.json = Json::parse(glb.begin() + 20, glb.begin() + 20 + jsonLen);
  const size_t bin = 20 + ((jsonLen + 3) & ~3u);
  if (bin + 8 <= glb.size()) g.bin.assign(glb.begin() + long(bin) + 8, glb.begin() + long(bin + 8 + hostile::get32(glb, bin)));
  return g;
}

Bytes joinGlb(Glb g) {
  while (g.bin.size() % 4) g.bin.push_back(0);
  g.json["buffers"][0]["byteLength"] = g.bin.size();
  return hostile::glbContainer(g.json.dump(), g.bin);
}

int componentBytes(int type) { return type == 5121 || type == 5120 ? 1 : type == 5123 || type == 5122 ? 2 : 4; }
int typeComponents(const std::string& t) {
  return t == "SCALAR" ? 1 : t == "VEC2" ? 2 : t == "VEC3" ? 3 : t == "VEC4" ? 4 : 16;
}

Span accessorSpan(const Glb& g, int a) {
  const Json& acc = g.json["accessors"][size_t(a)];
  const Json& view = g.json["bufferViews"][acc["bufferView"].get<size_t>()];
  if (view.value("byteStride", 0) != 0) throw std::runtime_error("interleaved views are not handled");
  Span s;
  s.offset = view.value("byteOffset", size_t(0)) + acc.value("byteOffset", size_t(0));
  s.elementBytes = size_t(componentBytes(acc["componentType"]) * typeComponents(acc["type"]));
  s.count = acc["count"];
  return s;
}

static void appendView(Glb& g, const Bytes& data, Json* viewOut = nullptr) {
  while (g.bin.size() % 4) g.bin.push_back(0);
  Json v = {{"buffer", 0}, {"byteOffset", g.bin.size()}, {"byteLength", data.size()}};
  g.bin.insert(g.bin.end(), data.begin(), data.end());
  if (viewOut) *viewOut = v;
  else g.json["bufferViews"].push_back(v);
}

static void requireExtension(Json& j, const std::string& ext) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    if (!j.contains(key)) j[key] = Json::array();
    j[key].push_back(ext);
  }
}

static draco::DataType dracoType(int componentType) {
  switch (componentType) {
    case 5121: return draco::DT_UINT8;
    case 5123: return draco::DT_UINT16;
    case 5125: return draco::DT_UINT32;
    default: return draco::DT_FLOAT32;
  }
}

static draco::GeometryAttribute::Type dracoSemantic(const std::string& name) {
  if (name == "POSITION") return draco::GeometryAttribute::POSITION;
  if (name == "NORMAL") return draco::GeometryAttribute::NORMAL;
  if (name.rfind("TEXCOORD_", 0) == 0) return draco::GeometryAttribute::TEX_COORD;
  return draco::GeometryAttribute::GENERIC;
}

// Every primitive with indices -> KHR_draco_mesh_compression (sequential connectivity, so the
// point order and count stay those of the accessors). The accessors keep count, type and
// min/max and lose their bufferView, as the extension's files have them.
Bytes dracoCompressed(const Bytes& glb, DracoBits bits) {
  Glb g = splitGlb(glb);
  std::set<size_t> zero;  // accessors whose bytes the compressed file no longer reads
  for (Json& mesh : g.json["meshes"])
    for (Json& prim : mesh["primitives"]) {
      if (!prim.contains("indices") || prim.value("mode", 4) != 4) continue;
      const Span idx = accessorSpan(g, prim["indices"]);
      draco::Mesh m;
      const size_t points = accessorSpan(g, prim["attributes"]["POSITION"]).count;
      m.set_num_points(uint32_t(points));
      Json ids = Json::object();
      for (auto& [name, a] : prim["attributes"].items()) {
        const Json& acc = g.json["accessors"][a.get<size_t>()];
        const Span s = accessorSpan(g, a);
        draco::GeometryAttribute ga;
        const int comps = typeComponents(acc["type"]);
        ga.Init(dracoSemantic(name), nullptr, int8_t(comps), dracoType(acc["componentType"]), false,
                int64_t(s.elementBytes), 0);
        const int id = m.AddAttribute(ga, true, uint32_t(points));
        for (size_t i = 0; i < points; ++i)
          m.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), g.bin.data() + s.offset + i * s.elementBytes);
        ids[name] = m.attribute(id)->unique_id();
        zero.insert(a.get<size_t>());
      }
      for (size_t t = 0; t + 2 < idx.count; t += 3) {
        draco::Mesh::Face f;
        for (size_t k = 0; k < 3; ++k) {
          uint32_t v = 0;
          std::memcpy(&v, g.bin.data() + idx.offset + (t + k) * idx.elementBytes, idx.elementBytes);
          f[k] = draco::PointIndex(v);
        }
        m.AddFace(f);
      }
      zero.insert(prim["indices"].get<size_t>());
      draco::Encoder enc;
      enc.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
      enc.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits.position);
      enc.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, bits.normal);
      enc.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, bits.texcoord);
      draco::EncoderBuffer out;
      if (!enc.EncodeMeshToBuffer(m, &out).ok()) throw std::runtime_error("Draco encoding failed");
      appendView(g, Bytes(out.data(), out.data() + out.size()));
      prim["extensions"]["KHR_draco_mesh_compression"] = {
          {"bufferView", g.json["bufferViews"].size() - 1}, {"attributes", ids}};
    }
  for (size_t a : zero) {
    const Span s = accessorSpan(g, int(a));
    std::memset(g.bin.data() + s.offset, 0, s.count * s.elementBytes);
    g.json["accessors"][a].erase("bufferView");
    g.json["accessors"][a].erase("byteOffset");
  }
  requireExtension(g.json, "KHR_draco_mesh_compression");
  return joinGlb(g);
}

// Every bufferView a primitive reads (attributes: ATTRIBUTES mode; indices: TRIANGLES) ->
// EXT_meshopt_compression (lossless: no filters). The views move to buffer 1, the fallback
// buffer without data; the compressed bytes are appended to buffer 0 (the BIN chunk).
Bytes meshoptCompressed(const Bytes& glb) {
  Glb g = splitGlb(glb);
  std::map<size_t, std::string> views;  // view -> mode
  std::map<size_t, size_t> stride;
  for (const Json& mesh : g.json["meshes"])
    for (const Json& prim : mesh["primitives"]) {
      for (const auto& [name, a] : prim["attributes"].items()) {
        const Json& acc = g.json["accessors"][a.get<size_t>()];
        views[acc["bufferView"]] = "ATTRIBUTES";
        stride[acc["bufferView"]] = accessorSpan(g, a).elementBytes;
      }
      if (prim.contains("indices")) {
        const Json& acc = g.json["accessors"][prim["indices"].get<size_t>()];
        views[acc["bufferView"]] = "TRIANGLES";
        stride[acc["bufferView"]] = size_t(componentBytes(acc["componentType"]));
      }
    }
  const size_t original = g.bin.size();
  g.json["buffers"].push_back({{"byteLength", original}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  for (const auto& [v, mode] : views) {
    Json& view = g.json["bufferViews"][v];
    const size_t off = view.value("byteOffset", size_t(0)), len = view["byteLength"], s = stride[v], count = len / s;
    Bytes packed;
    if (mode == "ATTRIBUTES") {
      packed.resize(meshopt_encodeVertexBufferBound(count, s));
      packed.resize(meshopt_encodeVertexBuffer(packed.data(), packed.size(), g.bin.data() + off, count, s));
    } else {
      std::vector<uint32_t> idx(count);
      for (size_t i = 0; i < count; ++i) std::memcpy(&idx[i], g.bin.data() + off + i * s, s), idx[i] &= s == 2 ? 0xFFFFu : ~0u;
      size_t vertices = 0;
      for (uint32_t i : idx) vertices = std::max<size_t>(vertices, i + 1);
      packed.resize(meshopt_encodeIndexBufferBound(count, vertices));
      packed.resize(meshopt_encodeIndexBuffer(packed.data(), packed.size(), idx.data(), count));
    }
    if (packed.empty()) throw std::runtime_error("meshopt encoding failed");
    std::memset(g.bin.data() + off, 0, len);
    Json ext;
    appendView(g, packed, &ext);
    ext.erase("buffer");
    ext["buffer"] = 0;
    ext["byteStride"] = s;
    ext["count"] = count;
    ext["mode"] = mode;
    view["buffer"] = 1;
    if (mode == "ATTRIBUTES") view["byteStride"] = s;
    view["extensions"]["EXT_meshopt_compression"] = ext;
  }
  requireExtension(g.json, "EXT_meshopt_compression");
  return joinGlb(g);
}

// RGBA8 pixels as a WebP in OpenImageIO's lossless mode (VP8L), written to memory. OpenImageIO
// 2.4's writer is not bit-exact even so (measured: channels off by up to a few steps / 255).
Bytes losslessWebp(int width, int height, const Bytes& rgba) {
  std::vector<unsigned char> out;
  OIIO::Filesystem::IOVecOutput memory(out);
  OIIO::Filesystem::IOProxy* proxy = &memory;
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("compression", "lossless");
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto w = OIIO::ImageOutput::create("webp");
  if (!w || !w->open("memory.webp", spec) || !w->write_image(OIIO::TypeDesc::UINT8, rgba.data()) || !w->close())
    throw std::runtime_error("OpenImageIO could not write WebP: " + OIIO::geterror());
  return Bytes(out.begin(), out.end());
}

Bytes base64Decode(const std::string& s) {
  Bytes out;
  uint32_t acc = 0;
  int bits = 0;
  for (char c : s) {
    const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* at = c ? std::strchr(t, c) : nullptr;
    if (!at) continue;  // '=' padding
    acc = (acc << 6) | uint32_t(at - t);
    if ((bits += 6) >= 8) out.push_back(uint8_t(acc >> (bits -= 8)));
  }
  return out;
}

// The encoded bytes of `image`: its base64 data: URI or its bufferView.
Bytes imageBytes(const Glb& g, const Json& image) {
  if (image.contains("uri")) {
    const std::string uri = image["uri"];
    return base64Decode(uri.substr(uri.find(',') + 1));
  }
  const Json& view = g.json["bufferViews"][image["bufferView"].get<size_t>()];
  const size_t at = view.value("byteOffset", size_t(0));
  return Bytes(g.bin.begin() + long(at), g.bin.begin() + long(at + view["byteLength"].get<size_t>()));
}

// `image` decoded by the loader's decoder (image_decode.h); throws when it does not decode.
DecodedImage decodedImage(const Glb& g, const Json& image) {
  const Bytes bytes = imageBytes(g, image);
  auto decoded = decodeImage(bytes.data(), bytes.size());
  if (!decoded) throw std::runtime_error(decoded.error());
  return decoded.take();
}

// Every image (PNG or JPEG, in a bufferView or a base64 data: URI) re-encoded as lossless WebP,
// kept where it was (a data: URI becomes data:image/webp); each texture names its image only
// inside EXT_texture_webp (no `source`), as files that require the extension do.
Bytes webpTextured(const Bytes& glb) {
  Glb g = splitGlb(glb);
  for (Json& image : g.json["images"]) {
    const DecodedImage decoded = decodedImage(g, image);
    const Bytes webp = losslessWebp(decoded.width, decoded.height, decoded.rgba);
    if (image.contains("uri")) {
      image["uri"] = "data:image/webp;base64," + hostile::base64(webp);
    } else {
      appendView(g, webp);
      image["bufferView"] = g.json["bufferViews"].size() - 1;
      image["mimeType"] = "image/webp";
    }
  }
  for (Json& t : g.json["textures"]) {
    t["extensions"]["EXT_texture_webp"] = {{"source", t["source"]}};
    t.erase("source");
  }
  requireExtension(g.json, "EXT_texture_webp");
  return joinGlb(g);
}

// The reference for a webpTextured file: the same file with each WebP image replaced by a PNG of
// the pixels it decodes to (stored, lossless) and the textures' `source` restored, so rendering
// both must give identical images if WebP textures take the PNG path through every pipeline.
Bytes pngOfWebpTextured(const Bytes& webpGlb) {
  Glb g = splitGlb(webpGlb);
  for (Json& image : g.json["images"]) {
    const DecodedImage decoded = decodedImage(g, image);
    const Bytes png = hostile::png(uint32_t(decoded.width), uint32_t(decoded.height), decoded.rgba);
    image.erase("bufferView");
    image["mimeType"] = "image/png";
    image["uri"] = "data:image/png;base64," + hostile::base64(png);
  }
  for (Json& t : g.json["textures"]) {
    t["source"] = t["extensions"]["EXT_texture_webp"]["source"];
    t.erase("extensions");
  }
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) g.json.erase(key);
  return joinGlb(g);
}

}  // namespace mb::compressed
