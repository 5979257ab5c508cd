#include "pipelines/scene/repair/conformance.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <set>

namespace mb {
namespace {

using nlohmann::json;

// Properties the glTF 2.0 schema types as integers (glTFid, counts, offsets, enums), and those
// holding arrays or maps of them. Matched by key anywhere: no other core property shares these
// keys with a non-integer number.
const std::set<std::string>& integerKeys() {
  static const std::set<std::string> k = {
      "scene", "bufferView", "byteOffset", "componentType", "count", "sampler", "node", "input", "output",
      "byteLength", "buffer", "byteStride", "target", "index", "texCoord", "indices", "material", "mode",
      "camera", "skin", "mesh", "magFilter", "minFilter", "wrapS", "wrapT", "inverseBindMatrices", "skeleton",
      "source"};
  return k;
}
const std::set<std::string>& integerArrayKeys() {
  static const std::set<std::string> k = {"nodes", "children", "joints"};
  return k;
}

// 2^53: every whole double up to here is exactly an integer.
constexpr double kExactIntegers = 9007199254740992.0;

bool toInteger(json& v) {
  if (!v.is_number_float()) return false;
  const double d = v.get<double>();
  if (!std::isfinite(d) || d != std::floor(d) || std::fabs(d) > kExactIntegers) return false;
  if (d >= 0) v = uint64_t(d);
  else v = int64_t(d);
  return true;
}

bool integersIn(json& container) {  // every element of an array or value of an object
  bool changed = false;
  for (auto& e : container) changed |= toInteger(e);
  return changed;
}

// Recursion depth is bounded by preflightGltf's nesting check (256).
bool normaliseNode(json& node) {
  bool changed = false;
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      json& v = it.value();
      if (integerKeys().count(it.key())) changed |= toInteger(v);
      if (v.is_array() && integerArrayKeys().count(it.key())) changed |= integersIn(v);
      if (v.is_object() && it.key() == "attributes") changed |= integersIn(v);
      if (v.is_array() && it.key() == "targets")
        for (json& t : v)
          if (t.is_object()) changed |= integersIn(t);
      changed |= normaliseNode(v);
    }
  } else if (node.is_array()) {
    for (json& e : node) changed |= normaliseNode(e);
  }
  return changed;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// For messages: printable ASCII, at most 64 characters.
std::string shown(const std::string& s) {
  std::string out;
  for (unsigned char c : s.substr(0, 64)) out += c >= 0x20 && c < 0x7F ? char(c) : '?';
  return s.size() > 64 ? out + "..." : out;
}

std::string base64Encode(const std::vector<uint8_t>& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
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

// Strict base64 (RFC 4648 alphabet, '=' padding only at the end); false on anything else.
bool base64Decode(const std::string& s, std::vector<uint8_t>* out) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
  };
  size_t n = s.size(), pad = 0;
  while (pad < 2 && n > 0 && s[n - 1] == '=') {
    --n;
    ++pad;
  }
  if ((pad && s.size() % 4) || n % 4 == 1) return false;
  uint32_t acc = 0;
  int bits = 0;
  out->reserve(n * 3 / 4);
  for (size_t i = 0; i < n; ++i) {
    const int v = value(s[i]);
    if (v < 0) return false;
    acc = (acc << 6) | uint32_t(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out->push_back(uint8_t(acc >> bits));
    }
  }
  return true;
}

// RFC 3986 percent-decoding; false on a malformed escape.
bool percentDecode(const std::string& s, std::string* out) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    c = char(std::tolower(static_cast<unsigned char>(c)));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
  };
  out->reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') {
      *out += s[i];
      continue;
    }
    if (i + 2 >= s.size() || hex(s[i + 1]) < 0 || hex(s[i + 2]) < 0) return false;
    *out += char(hex(s[i + 1]) * 16 + hex(s[i + 2]));
    i += 2;
  }
  return true;
}

// The data: URI forms tinygltf 2.7 decodes itself (IsDataURI); left as they are.
bool tinygltfDecodes(const std::string& uri) {
  static const char* prefixes[] = {"data:application/octet-stream;base64,", "data:image/jpeg;base64,",
                                   "data:image/png;base64,", "data:image/bmp;base64,", "data:image/gif;base64,",
                                   "data:text/plain;base64,", "data:application/gltf-buffer;base64,"};
  for (const char* p : prefixes)
    if (uri.rfind(p, 0) == 0) return true;
  return false;
}

// RFC 2397: data:[<mediatype>][;base64],<data>. *type is the media type without parameters,
// lower case ("text/plain" when absent, as the RFC defaults). Returns "" or why it failed.
std::string decodeDataUri(const std::string& uri, std::string* type, std::vector<uint8_t>* bytes) {
  const size_t comma = uri.find(',');
  if (comma == std::string::npos) return "malformed data: URI (no ',')";
  std::string header = uri.substr(5, comma - 5);
  bool base64 = false;
  if (header.size() >= 7 && lower(header.substr(header.size() - 7)) == ";base64") {
    base64 = true;
    header.resize(header.size() - 7);
  }
  *type = lower(header.substr(0, header.find(';')));
  type->erase(std::remove(type->begin(), type->end(), ' '), type->end());
  if (type->empty()) *type = "text/plain";
  std::string payload;
  if (!percentDecode(uri.substr(comma + 1), &payload)) return "data: URI with a malformed %-escape";
  if (!base64) {
    bytes->assign(payload.begin(), payload.end());
    return "";
  }
  if (!base64Decode(payload, bytes)) return "data: URI is not valid base64";
  return "";
}

// The EXT_/KHR_meshopt_compression object of a bufferView, nullptr when it has none. Such a
// view reads the extension's buffer; its own buffer is only the uncompressed fallback, which may
// have no data (meshopt_decode.cpp decodes the extension).
const json* meshoptExtension(const json& view) {
  auto e = view.find("extensions");
  if (e == view.end() || !e->is_object()) return nullptr;
  for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
    if (auto m = e->find(name); m != e->end() && m->is_object()) return &*m;
  return nullptr;
}

// The index of the first bufferView reading each buffer (-1: none).
std::vector<long> firstReaders(const json& doc, size_t bufferCount) {
  std::vector<long> reader(bufferCount, -1);
  auto views = doc.find("bufferViews");
  if (views == doc.end() || !views->is_array()) return reader;
  for (size_t v = 0; v < views->size(); ++v) {
    const json* view = &(*views)[v];
    if (view->is_object())
      if (const json* m = meshoptExtension(*view)) view = m;
    auto b = view->is_object() ? view->find("buffer") : view->end();
    if (!view->is_object() || b == view->end() || !b->is_number_unsigned()) continue;
    const uint64_t i = b->get<uint64_t>();
    if (i < bufferCount && reader[i] < 0) reader[i] = long(v);
  }
  return reader;
}

Status conformBuffers(json& doc, bool glb, bool hasBinChunk, ConformedGltf* out, bool* changed) {
  auto buffers = doc.find("buffers");
  if (buffers == doc.end() || !buffers->is_array()) return {};
  const std::vector<long> reader = firstReaders(doc, buffers->size());
  for (size_t i = 0; i < buffers->size(); ++i) {
    json& b = (*buffers)[i];
    if (!b.is_object()) continue;  // tinygltf refuses it with its own message
    const std::string who = "buffer " + std::to_string(i);
    auto uri = b.find("uri");
    if (uri == b.end()) {
      const bool binChunk = glb && i == 0 && hasBinChunk;
      const auto length = b.find("byteLength");
      if (reader[i] < 0 && length != b.end() && length->is_number_unsigned()) {  // a placeholder: nothing reads it
        b["uri"] = "data:application/octet-stream;base64,AAAA";
        b["byteLength"] = 3;
        out->placeholderBuffers.push_back(int(i));
        *changed = true;
      } else if (!binChunk) {
        const std::string readBy = ", but bufferView " + std::to_string(reader[i]) + " reads it";
        if (!glb) return Status::fail(who + " has no uri (a .gltf buffer needs one)" + readBy);
        if (i == 0) return Status::fail(who + " has no uri and the GLB has no BIN chunk" + readBy);
        return Status::fail(who + " has no uri and is not the GLB's BIN chunk (only buffer 0 is)" + readBy);
      }
      continue;
    }
    if (!uri->is_string()) continue;
    const std::string text = uri->get<std::string>();
    const std::string scheme = uriScheme(text);
    if (scheme.empty() || tinygltfDecodes(text)) continue;
    if (scheme != "data")
      return Status::fail(who + ": uri '" + shown(text) + "' is not a relative path or a data: URI (" + scheme +
                          ": is not read; only files beside the glTF and embedded data are)");
    std::string type;
    std::vector<uint8_t> bytes;
    if (std::string why = decodeDataUri(text, &type, &bytes); !why.empty()) return Status::fail(who + ": " + why);
    if (type != "application/octet-stream" && type != "application/gltf-buffer")
      return Status::fail(who + ": data: URI media type '" + shown(type) +
                          "' is not application/octet-stream or application/gltf-buffer");
    auto length = b.find("byteLength");
    if (length == b.end() || !length->is_number_unsigned() || length->get<uint64_t>() != bytes.size())
      return Status::fail(who + ": data: URI holds " + std::to_string(bytes.size()) + " bytes, byteLength is " +
                          (length == b.end() ? std::string("missing") : shown(length->dump())));
    *uri = "data:application/octet-stream;base64," + base64Encode(bytes);
    *changed = true;
  }
  return {};
}

// Images stay drawable without their data (1x1 white, counted): URIs that cannot be read are
// noted, and data: URIs in a form tinygltf does not know are re-encoded.
void conformImages(json& doc, ConformedGltf* out, bool* changed) {
  auto images = doc.find("images");
  if (images == doc.end() || !images->is_array()) return;
  for (size_t i = 0; i < images->size(); ++i) {
    json& im = (*images)[i];
    auto uri = im.is_object() ? im.find("uri") : im.end();
    if (!im.is_object() || uri == im.end() || !uri->is_string()) continue;
    const std::string text = uri->get<std::string>(), who = "image " + std::to_string(i);
    const std::string scheme = uriScheme(text);
    if (scheme.empty() || tinygltfDecodes(text)) continue;
    if (scheme != "data") {
      out->notes.push_back(who + ": uri '" + shown(text) + "' is not a relative path or a data: URI (not read)");
      continue;
    }
    std::string type;
    std::vector<uint8_t> bytes;
    std::string why = decodeDataUri(text, &type, &bytes);
    if (why.empty() && type != "image/png" && type != "image/jpeg" && type != "image/webp")
      why = "data: URI media type '" + shown(type) + "' is not image/png, image/jpeg or image/webp";
    if (!why.empty()) {
      out->notes.push_back(who + ": " + why + " (not decoded)");
      continue;
    }
    // tinygltf 2.7 knows no image/webp data: URI; the bytes go to decodeImage, which tells the
    // format from the bytes, so WebP travels under a media type tinygltf accepts.
    *uri = "data:" + (type == "image/webp" ? std::string("image/png") : type) + ";base64," + base64Encode(bytes);
    *changed = true;
  }
}

void conformIndices(json& doc, ConformedGltf* out, bool* changed) {
  auto meshes = doc.find("meshes"), accessors = doc.find("accessors");
  if (meshes == doc.end() || !meshes->is_array() || accessors == doc.end() || !accessors->is_array()) return;
  for (size_t m = 0; m < meshes->size(); ++m) {
    json& mesh = (*meshes)[m];
    auto prims = mesh.is_object() ? mesh.find("primitives") : mesh.end();
    if (!mesh.is_object() || prims == mesh.end() || !prims->is_array()) continue;
    for (size_t p = 0; p < prims->size(); ++p) {
      json& prim = (*prims)[p];
      auto idx = prim.is_object() ? prim.find("indices") : prim.end();
      if (!prim.is_object() || idx == prim.end() || !idx->is_number_unsigned()) continue;
      const uint64_t a = idx->get<uint64_t>();
      if (a >= accessors->size() || !(*accessors)[a].is_object() || (*accessors)[a].contains("bufferView")) continue;
      out->indices.push_back({int(m), int(p), int(a)});
      prim.erase(idx);
      *changed = true;
    }
  }
}

}  // namespace

std::string uriScheme(const std::string& uri) {
  const size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return "";
  for (size_t i = 1; i < colon; ++i) {
    const char c = uri[i];
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return "";
  }
  return lower(uri.substr(0, colon));
}

bool normaliseIntegers(json& doc) { return normaliseNode(doc); }

Status conformDocument(json& doc, bool glb, bool hasBinChunk, ConformedGltf* out, bool* changed) {
  if (Status s = conformBuffers(doc, glb, hasBinChunk, out, changed); !s) return s;
  conformImages(doc, out, changed);
  conformIndices(doc, out, changed);
  return {};
}

std::vector<uint8_t> serialiseDocument(const json& doc, bool glb, const std::vector<uint8_t>& original,
                                       size_t restBegin, size_t restEnd) {
  std::string text = doc.dump(-1, ' ', false, json::error_handler_t::replace);
  if (!glb) return std::vector<uint8_t>(text.begin(), text.end());
  while (text.size() % 4) text += ' ';
  std::vector<uint8_t> out;
  const size_t rest = restEnd > restBegin ? restEnd - restBegin : 0;
  out.reserve(20 + text.size() + rest);
  auto u32 = [&](uint64_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
  };
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(20 + text.size() + rest);
  u32(text.size());
  u32(0x4E4F534Au);
  out.insert(out.end(), text.begin(), text.end());
  if (rest) out.insert(out.end(), original.begin() + long(restBegin), original.begin() + long(restEnd));
  return out;
}

void applyConformance(const ConformedGltf& c, tinygltf::Model& model) {
  for (const ConformedGltf::Indices& i : c.indices)
    if (size_t(i.mesh) < model.meshes.size() && size_t(i.primitive) < model.meshes[size_t(i.mesh)].primitives.size())
      model.meshes[size_t(i.mesh)].primitives[size_t(i.primitive)].indices = i.accessor;
  for (int b : c.placeholderBuffers)
    if (size_t(b) < model.buffers.size()) model.buffers[size_t(b)].data.clear();
}

}  // namespace mb
