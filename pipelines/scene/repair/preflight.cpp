#include "pipelines/scene/repair/preflight.h"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

namespace mb {
namespace {

uint32_t u32(const std::vector<uint8_t>& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

// GLB layout (glTF 2.0 section 4.4): 12-byte header, JSON chunk, optional BIN chunk. *restBegin
// .. *restEnd: the chunks after the JSON chunk (empty: no BIN chunk).
Status checkGlb(const std::vector<uint8_t>& b, size_t* jsonBegin, size_t* jsonLength, size_t* restBegin = nullptr,
                size_t* restEnd = nullptr) {
  if (b.size() < 12) return Status::fail("truncated GLB: " + std::to_string(b.size()) + " bytes, header needs 12");
  if (u32(b, 4) != 2) return Status::fail("unsupported GLB version " + std::to_string(u32(b, 4)));
  uint64_t length = u32(b, 8);
  if (length > b.size())
    return Status::fail("truncated GLB: header declares " + std::to_string(length) + " bytes, file has " +
                        std::to_string(b.size()));
  if (length < 20) return Status::fail("truncated GLB: no JSON chunk");
  uint64_t jsonLen = u32(b, 12);
  if (u32(b, 16) != 0x4E4F534Au) return Status::fail("GLB first chunk is not JSON");
  if (20 + jsonLen > length) return Status::fail("truncated GLB: JSON chunk runs past the end of the file");
  uint64_t at = 20 + ((jsonLen + 3) & ~uint64_t(3));
  if (at < length) {
    if (at + 8 > length) return Status::fail("truncated GLB: incomplete BIN chunk header");
    uint64_t binLen = u32(b, size_t(at));
    if (at + 8 + binLen > length) return Status::fail("truncated GLB: BIN chunk runs past the end of the file");
  }
  *jsonBegin = 20;
  *jsonLength = size_t(jsonLen);
  if (restBegin) *restBegin = size_t(std::min(at, length));
  if (restEnd) *restEnd = size_t(length);
  return {};
}

// A GLB whose BIN chunk length is not a multiple of 4 (glTF 2.0 4.4.3.1 requires it; three.js
// and the Sample Viewer read such files): the same file with the chunk zero-padded to the next
// multiple of 4 and the lengths patched; chunks after it are dropped (readers ignore them).
// Empty when the BIN chunk is aligned, absent, or not complete (truncation stays an error).
std::vector<uint8_t> padUnalignedBin(const std::vector<uint8_t>& b) {
  size_t jsonBegin = 0, jsonLength = 0, at = 0, end = 0;
  if (!checkGlb(b, &jsonBegin, &jsonLength, &at, &end) || at + 8 > end) return {};
  const uint32_t binLen = u32(b, at);
  if (binLen % 4 == 0 || u32(b, at + 4) != 0x004E4942u) return {};
  std::vector<uint8_t> out(b.begin(), b.begin() + long(at + 8 + binLen));
  out.resize(out.size() + (4 - binLen % 4), 0);
  const uint32_t padded = (binLen + 3) & ~3u, total = uint32_t(out.size());
  std::memcpy(out.data() + at, &padded, 4);
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

// A GLB whose JSON chunk length is not a multiple of 4 (glTF 2.0 4.4.3.1 requires trailing
// spaces): rewritten with the JSON space-padded and the lengths patched. The chunks that follow
// are taken from where the writer put them: right after the JSON's last byte (where three.js
// and tinygltf read them; the common case) or, when the bytes up to the next multiple of 4 are
// padding, at that boundary. Empty (no rewrite) when the length is aligned or the header does
// not fit the file (checkGlb names that); `*why` names a chunk layout that fits neither.
std::vector<uint8_t> padUnpaddedJson(const std::vector<uint8_t>& b, std::string* why) {
  if (b.size() < 20 || u32(b, 12) % 4 == 0) return {};
  const uint64_t length = u32(b, 8), jsonEnd = 20 + uint64_t(u32(b, 12)), aligned = (jsonEnd + 3) & ~uint64_t(3);
  if (length > b.size() || jsonEnd > length || u32(b, 16) != 0x4E4F534Au) return {};
  // A chunk header at `at` whose chunk ends inside the file; `bin`: it must be the BIN chunk.
  auto chunkFits = [&](uint64_t at, bool bin) {
    return at + 8 <= length && (!bin || u32(b, size_t(at) + 4) == 0x004E4942u) && at + 8 + u32(b, size_t(at)) <= length;
  };
  auto padding = [&] {
    for (uint64_t i = jsonEnd; i < aligned; ++i)
      if (b[size_t(i)] != ' ' && b[size_t(i)] != 0) return false;
    return aligned <= length;
  };
  uint64_t rest = 0;
  if (jsonEnd == length || chunkFits(jsonEnd, true)) rest = jsonEnd;
  else if (padding() && (aligned == length || chunkFits(aligned, false))) rest = aligned;
  else {
    const bool binHere = jsonEnd + 8 <= length && u32(b, size_t(jsonEnd) + 4) == 0x004E4942u;
    *why = binHere ? "truncated GLB: BIN chunk (after a JSON chunk of " + std::to_string(jsonEnd - 20) +
                         " bytes, not a multiple of 4) declares " + std::to_string(u32(b, size_t(jsonEnd))) +
                         " bytes, " + std::to_string(length - jsonEnd - 8) + " remain"
                   : "GLB JSON chunk length " + std::to_string(jsonEnd - 20) +
                         " is not a multiple of 4 and no chunk starts at byte " + std::to_string(jsonEnd) + " or " +
                         std::to_string(aligned);
    return {};
  }
  std::vector<uint8_t> out(b.begin(), b.begin() + long(jsonEnd));
  out.resize(size_t(aligned), ' ');
  out.insert(out.end(), b.begin() + long(rest), b.begin() + long(length));
  const uint32_t jsonLength = uint32_t(aligned - 20), total = uint32_t(out.size());
  std::memcpy(out.data() + 12, &jsonLength, 4);
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

uint64_t field(const nlohmann::json& o, const char* key, uint64_t fallback, bool* ok) {
  auto it = o.find(key);
  if (it == o.end()) return fallback;
  if (!it->is_number_unsigned()) *ok = false;
  return it->is_number_unsigned() ? it->get<uint64_t>() : 0;
}

// Deepest [ / { nesting outside strings. Parsers recurse per level, so depth is bounded first.
size_t nestingDepth(const uint8_t* p, size_t n) {
  size_t depth = 0, worst = 0;
  bool inString = false;
  for (size_t i = 0; i < n; ++i) {
    uint8_t c = p[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      worst = std::max(worst, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return worst;
}

constexpr size_t kMaxJsonDepth = 256;

// Accessors without bufferView are zeros (glTF 2.0 3.6.2.3): nothing in the file bounds their
// count, so their decoded size is capped: 2^24 values (64 MB as floats) over the whole file.
constexpr uint64_t kMaxZeroFilledValues = uint64_t(1) << 24;

uint64_t typeComponents(const std::string& t) {
  return t == "SCALAR" ? 1 : t == "VEC2" ? 2 : t == "VEC3" ? 3 : t == "VEC4" || t == "MAT2" ? 4
       : t == "MAT3" ? 9 : t == "MAT4" ? 16 : 1;
}

// Parser messages quote the offending bytes: keep them printable ASCII (and so valid UTF-8 for
// the JSON reports that carry error messages).
std::string printable(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if (c >= 0x20 && c < 0x7F) out += char(c);
    else out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

}  // namespace

Status preflightGltf(const std::vector<uint8_t>& bytes, const std::string& nameHint, bool* isGlb,
                     ConformedGltf* conformed) {
  *isGlb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (bytes.empty()) return Status::fail("empty file (0 bytes): neither a .glb nor a .gltf document");
  std::string unpaddedWhy;
  if (std::vector<uint8_t> padded = *isGlb ? padUnpaddedJson(bytes, &unpaddedWhy) : std::vector<uint8_t>{};
      !padded.empty()) {
    ConformedGltf local;
    if (!conformed) conformed = &local;
    Status s = preflightGltf(padded, nameHint, isGlb, conformed);
    if (conformed->bytes.empty()) conformed->bytes = std::move(padded);
    return s;  // the loader counts it from the original header (LoadStats::jsonChunkUnpadded)
  }
  if (!unpaddedWhy.empty()) return Status::fail(unpaddedWhy);
  if (std::vector<uint8_t> padded = *isGlb ? padUnalignedBin(bytes) : std::vector<uint8_t>{}; !padded.empty()) {
    ConformedGltf local;
    if (!conformed) conformed = &local;
    Status s = preflightGltf(padded, nameHint, isGlb, conformed);
    if (conformed->bytes.empty()) conformed->bytes = std::move(padded);
    conformed->binChunkPadded = true;
    return s;
  }
  size_t begin = 0, length = bytes.size(), restBegin = 0, restEnd = 0;
  if (*isGlb) {
    if (Status s = checkGlb(bytes, &begin, &length, &restBegin, &restEnd); !s) return s;
  } else if (endsWith(nameHint, ".glb")) {
    return Status::fail("bad GLB magic (expected 'glTF')");
  }
  if (nestingDepth(bytes.data() + begin, length) > kMaxJsonDepth)
    return Status::fail("invalid JSON: nesting depth exceeds " + std::to_string(kMaxJsonDepth));
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(bytes.begin() + long(begin), bytes.begin() + long(begin + length));
  } catch (const nlohmann::json::exception& e) {
    return Status::fail("invalid JSON: " + printable(e.what()));
  }
  if (!doc.is_object()) return Status::fail("invalid glTF: top-level JSON is not an object");
  // glTF 1.0 (dictionaries instead of arrays) would otherwise parse as an empty 2.0 scene.
  auto asset = doc.find("asset");
  if (asset != doc.end() && asset->is_object()) {
    auto v = asset->find("version"), mv = asset->find("minVersion");
    if (v != asset->end() && v->is_string() && v->get<std::string>().rfind("2.", 0) != 0)
      return Status::fail("unsupported glTF version " + v->get<std::string>() + " (2.0 required)");
    if (mv != asset->end() && mv->is_string() && mv->get<std::string>() != "2.0")
      return Status::fail("unsupported glTF minVersion " + mv->get<std::string>() + " (this loader reads glTF 2.0)");
  }
  // Valid files tinygltf would refuse (conformance.h): integers first, the checks below read them.
  bool changed = normaliseIntegers(doc);
  auto arr = [&](const char* key) {
    auto it = doc.find(key);
    return it != doc.end() && it->is_array() ? *it : nlohmann::json::array();
  };
  nlohmann::json buffers = arr("buffers"), views = arr("bufferViews"), accessors = arr("accessors");
  uint64_t zeroFilled = 0;
  for (const auto& a : accessors) {
    if (!a.is_object() || a.contains("bufferView")) continue;
    bool ok = true;
    uint64_t count = field(a, "count", 0, &ok);
    auto type = a.find("type");
    uint64_t comps = type != a.end() && type->is_string() ? typeComponents(type->get<std::string>()) : 1;
    zeroFilled += ok ? std::min(count, kMaxZeroFilledValues + 1) * comps : 0;
    if (zeroFilled > kMaxZeroFilledValues)
      return Status::fail("accessors without bufferView declare more than " + std::to_string(kMaxZeroFilledValues) +
                          " zero values: count too large (limit)");
  }
  for (size_t i = 0; i < views.size(); ++i) {
    std::string who = "bufferView " + std::to_string(i);
    const auto& v = views[i];
    bool ok = v.is_object();
    if (!ok) return Status::fail(who + " is not an object");
    uint64_t buf = field(v, "buffer", ~uint64_t(0), &ok);
    uint64_t off = field(v, "byteOffset", 0, &ok), len = field(v, "byteLength", 0, &ok);
    if (!ok) return Status::fail(who + ": malformed buffer/byteOffset/byteLength");
    if (buf >= buffers.size()) return Status::fail(who + " refers to missing buffer " + std::to_string(int64_t(buf)));
    bool bok = buffers[buf].is_object();
    uint64_t blen = bok ? field(buffers[buf], "byteLength", 0, &bok) : 0;
    if (!bok) return Status::fail("buffer " + std::to_string(buf) + ": malformed byteLength");
    if (off > blen || len > blen - off)
      return Status::fail(who + " (byteOffset " + std::to_string(off) + ", byteLength " + std::to_string(len) +
                          ") exceeds buffer " + std::to_string(buf) + " (" + std::to_string(blen) + " bytes)");
  }
  ConformedGltf unused;
  if (!conformed) conformed = &unused;
  if (Status s = conformDocument(doc, *isGlb, restBegin < restEnd, conformed, &changed); !s) return s;
  if (changed) conformed->bytes = serialiseDocument(doc, *isGlb, bytes, restBegin, restEnd);
  return {};
}

std::string explainRefusal(const std::vector<uint8_t>& bytes) {
  size_t begin = 0, length = bytes.size();
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0 && !checkGlb(bytes, &begin, &length)) return "";
  const nlohmann::json doc = nlohmann::json::parse(bytes.begin() + long(begin), bytes.begin() + long(begin + length),
                                                   nullptr, false);
  if (!doc.is_object()) return "";
  // The required properties of the glTF 2.0 schema that tinygltf 2.7 enforces without a message.
  struct Rule {
    const char* array;
    const char* what;
    std::vector<const char*> required;
  };
  static const Rule rules[] = {
      {"buffers", "buffer", {"byteLength"}},
      {"bufferViews", "bufferView", {"buffer", "byteLength"}},
      {"accessors", "accessor", {"componentType", "count", "type"}},
      {"meshes", "mesh", {"primitives"}},
      {"skins", "skin", {"joints"}},
      {"animations", "animation", {"channels", "samplers"}},
      {"cameras", "camera", {"type"}},
  };
  for (const Rule& r : rules) {
    auto arr = doc.find(r.array);
    if (arr == doc.end() || !arr->is_array()) continue;
    for (size_t i = 0; i < arr->size(); ++i) {
      const nlohmann::json& o = (*arr)[i];
      const std::string who = std::string(r.what) + " " + std::to_string(i);
      if (!o.is_object()) return who + " is not an object";
      for (const char* key : r.required) {
        if (o.contains(key)) continue;
        if (std::string(r.array) == "skins" && o.contains("jointNames"))
          return who + " has 'jointNames' but no 'joints': glTF 2.0 pre-release file";
        return who + " has no '" + key + "' (required by glTF 2.0)";
      }
      if (std::string(r.array) == "meshes")
        for (size_t p = 0; p < o["primitives"].size(); ++p)
          if (o["primitives"].is_array() && !o["primitives"][p].contains("attributes"))
            return who + " primitive " + std::to_string(p) + " has no 'attributes' (required by glTF 2.0)";
      if (std::string(r.array) == "animations" && o["channels"].is_array())
        for (size_t c = 0; c < o["channels"].size(); ++c)
          for (const char* key : {"sampler", "target"})
            if (!o["channels"][c].contains(key))
              return who + " channel " + std::to_string(c) + " has no '" + key + "' (required by glTF 2.0)";
    }
  }
  return "";
}

}  // namespace mb
