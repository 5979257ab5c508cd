#include "harness/check/content_hash.h"

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

namespace mb::check {
namespace {

namespace fs = std::filesystem;

constexpr std::array<uint32_t, 64> kRound = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

uint32_t rotr(uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

void compress(std::array<uint32_t, 8>& h, const unsigned char* block) {
  uint32_t w[64];
  for (int i = 0; i < 16; ++i)
    w[i] = uint32_t(block[4 * i]) << 24 | uint32_t(block[4 * i + 1]) << 16 | uint32_t(block[4 * i + 2]) << 8 |
           uint32_t(block[4 * i + 3]);
  for (int i = 16; i < 64; ++i) {
    const uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
    const uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
    w[i] = w[i - 16] + s0 + w[i - 7] + s1;
  }
  uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], k = h[7];
  for (int i = 0; i < 64; ++i) {
    const uint32_t t1 = k + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + kRound[size_t(i)] + w[i];
    const uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    k = g, g = f, f = e, e = d + t1, d = c, c = b, b = a, a = t1 + t2;
  }
  const uint32_t add[8] = {a, b, c, d, e, f, g, k};
  for (size_t i = 0; i < 8; ++i) h[i] += add[i];
}

Result<std::string> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Result<std::string>::fail(path.string() + ": cannot read");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// "a%20b.bin" -> "a b.bin" (uris in glTF are URI-encoded).
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    unsigned value = 0;
    if (uri[i] == '%' && i + 2 < uri.size() && std::sscanf(uri.substr(i + 1, 2).c_str(), "%2x", &value) == 1) {
      out += char(value);
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// The JSON of a .gltf file, or of a .glb file's first chunk; discarded when there is none.
nlohmann::json documentOf(const std::string& bytes) {
  if (bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0) {
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);  // little-endian, as every platform built here
    if (bytes.compare(16, 4, "JSON") != 0 || length > bytes.size() - 20) return nlohmann::json(nlohmann::json::value_t::discarded);
    return nlohmann::json::parse(bytes.substr(20, length), nullptr, false);
  }
  return nlohmann::json::parse(bytes, nullptr, false);
}

// buffers[] then images[] uris that name files (not data: URIs).
std::vector<std::string> externalUris(const nlohmann::json& doc) {
  std::vector<std::string> uris;
  if (!doc.is_object()) return uris;
  for (const char* key : {"buffers", "images"}) {
    const auto list = doc.find(key);
    if (list == doc.end() || !list->is_array()) continue;
    for (const nlohmann::json& item : *list) {
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"].get<std::string>();
      if (!uri.starts_with("data:")) uris.push_back(uri);
    }
  }
  return uris;
}

}  // namespace

std::string sha256Hex(const std::string& bytes) {
  std::array<uint32_t, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                               0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  size_t whole = bytes.size() / 64 * 64;
  for (size_t i = 0; i < whole; i += 64) compress(h, data + i);
  unsigned char tail[128] = {};
  const size_t rest = bytes.size() - whole;
  std::memcpy(tail, data + whole, rest);
  tail[rest] = 0x80;
  const size_t tailLength = rest + 9 <= 64 ? 64 : 128;
  const uint64_t bits = uint64_t(bytes.size()) * 8;
  for (int i = 0; i < 8; ++i) tail[tailLength - 1 - size_t(i)] = (unsigned char)(bits >> (8 * i));
  for (size_t i = 0; i < tailLength; i += 64) compress(h, tail + i);
  std::string hex;
  char b[9];
  for (uint32_t v : h) {
    std::snprintf(b, sizeof b, "%08x", v);
    hex += b;
  }
  return hex;
}

Result<ContentHash> contentHash(const std::string& path) {
  auto bytes = readBytes(path);
  if (!bytes) return Result<ContentHash>::fail(bytes.error());
  ContentHash hash;
  hash.resources = externalUris(documentOf(*bytes));
  std::string all = std::move(*bytes);
  for (const std::string& uri : hash.resources) {
    auto resource = readBytes(fs::path(path).parent_path() / percentDecoded(uri));
    all += "\n" + uri + "\n" + (resource ? std::to_string(resource->size()) + "\n" + *resource : std::string("missing"));
  }
  hash.sha256 = sha256Hex(all);
  return hash;
}

}  // namespace mb::check
