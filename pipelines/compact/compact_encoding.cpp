#include "pipelines/compact/compact_encoding.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/packing.hpp>

#include "shaders/shim/compact.h"

namespace mb::compact {
namespace {

using CS = CompactShader<float>;
CS& shader() {  // the shim's functions are non-const members
  static CS s;
  return s;
}

glm::vec3 toGlm(const CS::vec3& v) { return {v.x, v.y, v.z}; }
float signNotZero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }

// The two integer codes either side of `f`, kept in [0, hi].
std::array<unsigned, 2> around(float f, unsigned hi) {
  const float lo = std::clamp(std::floor(f), 0.0f, float(hi));
  return {unsigned(lo), unsigned(std::min(lo + 1.0f, float(hi)))};
}

// Octahedral codes of unit `n` whose decoding is closest to it.
std::array<unsigned, 2> octCodes(const glm::vec3& n) {
  glm::vec2 p = glm::vec2(n.x, n.y) / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
  if (n.z < 0.0f)
    p = (1.0f - glm::abs(glm::vec2(p.y, p.x))) * glm::vec2(signNotZero(p.x), signNotZero(p.y));
  std::array<unsigned, 2> best{511, 511};
  float bestDot = -2.0f;
  for (unsigned cx : around(p.x * 511.0f + 511.0f, 1022))
    for (unsigned cy : around(p.y * 511.0f + 511.0f, 1022)) {
      const float d = glm::dot(toGlm(shader().compactOctNormal(float(cx), float(cy))), n);
      if (d > bestDot) bestDot = d, best = {cx, cy};
    }
  return best;
}

// Diamond code of the in-plane direction (x, y), the neighbour whose decoding is closest.
unsigned diamondCode(float x, float y) {
  if (x == 0.0f && y == 0.0f) x = 1.0f;
  const float u = x / (std::abs(x) + std::abs(y));
  const float p = y >= 0.0f ? (1.0f - u) * 0.25f : (3.0f + u) * 0.25f;
  const int c = int(std::lround(p * 1024.0f));
  const glm::vec2 want = glm::normalize(glm::vec2(x, y));
  unsigned best = 0;
  float bestDot = -2.0f;
  for (int k = c - 1; k <= c + 1; ++k) {
    const unsigned code = unsigned((k + 1024) % 1024);
    const CS::vec2 d = shader().compactDiamond(float(code));
    const float dot = glm::dot(glm::normalize(glm::vec2(d.x, d.y)), want);
    if (dot > bestDot) bestDot = dot, best = code;
  }
  return best;
}

}  // namespace

PositionCube positionCube(const std::vector<glm::vec3>& positions) {
  PositionCube cube;
  if (positions.empty()) return cube;
  glm::vec3 lo = positions.front(), hi = lo;
  for (const glm::vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  cube.center = 0.5f * (lo + hi);
  const glm::vec3 half = 0.5f * (hi - lo);
  cube.extent = std::max({half.x, half.y, half.z});
  if (!(cube.extent > 0.0f)) cube.extent = 1.0f;  // one point: any cube holds it
  return cube;
}

std::vector<std::vector<PositionCube>> primitiveCubes(const Scene& scene) {
  std::vector<std::vector<PositionCube>> out;
  for (const Mesh& m : scene.meshes) {
    out.emplace_back();
    for (const Primitive& p : m.primitives) out.back().push_back(positionCube(p.positions));
  }
  return out;
}

void quantizePosition(const glm::vec3& p, const PositionCube& cube, int16_t out[4], float w) {
  const glm::vec3 q = (p - cube.center) / cube.extent;
  for (int i = 0; i < 3; ++i) out[i] = gl::snorm16(q[i]);
  out[3] = gl::snorm16(w);
}

glm::vec3 dequantizePosition(const int16_t q[4], const PositionCube& cube) {
  return cube.center +
         cube.extent * glm::vec3(gl::fromSnorm16(q[0]), gl::fromSnorm16(q[1]), gl::fromSnorm16(q[2]));
}

uint32_t packWord(unsigned x, unsigned y, unsigned z, unsigned w) {
  return (x & 1023u) | (y & 1023u) << 10 | (z & 1023u) << 20 | (w & 3u) << 30;
}

glm::vec4 wordFields(uint32_t word) {
  return {float(word & 1023u), float(word >> 10 & 1023u), float(word >> 20 & 1023u), float(word >> 30)};
}

uint32_t encodeMatrixFrame(const glm::vec3& normal, const glm::vec4& tangent) {
  const float len = glm::length(normal);
  const glm::vec3 n = len > 0.0f ? normal / len : glm::vec3(0.0f, 0.0f, 1.0f);
  const std::array<unsigned, 2> oct = octCodes(n);
  // The tangent's direction in the decoded normal's plane, in the shader's basis.
  const CS::mat2x3 b = shader().compactTangentBasis(shader().compactOctNormal(float(oct[0]), float(oct[1])));
  const glm::vec3 t(tangent);
  const unsigned diamond = diamondCode(glm::dot(t, toGlm(b[0])), glm::dot(t, toGlm(b[1])));
  return packWord(oct[0], oct[1], diamond, tangent.w < 0.0f ? 1u : 0u);
}

MatrixFrame decodeMatrixFrame(uint32_t word) {
  const glm::vec4 f = wordFields(word);
  const CS::mat2x4 d = shader().compactMatrixFrame(CS::vec4(f.x, f.y, f.z, f.w));
  return {glm::vec3(d[0].x, d[0].y, d[0].z), glm::normalize(glm::vec3(d[1].x, d[1].y, d[1].z)), d[1].w};
}

uint32_t encodeRotorFrame(const glm::vec4& rotor, bool mirrored) {
  glm::vec4 q = glm::normalize(rotor);
  int k = 0;
  for (int i = 1; i < 4; ++i)
    if (std::abs(q[i]) > std::abs(q[k])) k = i;
  if (q[k] < 0.0f) q = -q;  // the dropped component is the positive root
  float c[3];
  for (int i = 0, j = 0; i < 4; ++i)
    if (i != k) c[j++] = q[i];
  const float s10 = shader().kRotorStep10, s9 = shader().kRotorStep9;
  uint32_t best = 0;
  float bestDot = -2.0f;
  for (unsigned a : around(c[0] / s10 + 511.0f, 1022))
    for (unsigned b : around(c[1] / s10 + 511.0f, 1022))
      for (unsigned z : around(c[2] / s9 + 255.0f, 510)) {
        const uint32_t word = packWord(a, b, z + (mirrored ? 512u : 0u), unsigned(k));
        const float d = glm::dot(decodeRotorFrame(word).rotor, q);
        if (d > bestDot) bestDot = d, best = word;
      }
  return best;
}

RotorFrame decodeRotorFrame(uint32_t word) {
  const glm::vec4 f = wordFields(word);
  const CS::mat2x4 d = shader().compactRotor(CS::vec4(f.x, f.y, f.z, f.w));
  return {glm::vec4(d[0].x, d[0].y, d[0].z, d[0].w), d[1].x};
}

uint32_t encodeSignedRotorFrame(const glm::vec4& rotor) {
  const uint32_t word = encodeRotorFrame(rotor, false);  // the bit plays no part in the search
  return glm::dot(decodeRotorFrame(word).rotor, rotor) < 0.0f ? word | 512u << 20 : word;
}

glm::vec4 decodeSignedRotorFrame(uint32_t word) {
  const glm::vec4 f = wordFields(word);
  const CS::vec4 r = shader().compactSignedRotor(CS::vec4(f.x, f.y, f.z, f.w));
  return {r.x, r.y, r.z, r.w};
}

std::vector<gl::PackedAttribute> attributes() {
  return {{0, 4, GL_SHORT, true}, {1, 4, GL_UNSIGNED_INT_2_10_10_10_REV, false}, {2, 2, GL_HALF_FLOAT, false}};
}

void appendVertex(std::vector<uint8_t>& out, const glm::vec3& position, const PositionCube& cube, uint32_t frame,
                  const glm::vec2& uv0, float positionW) {
  int16_t p[4];
  quantizePosition(position, cube, p, positionW);
  const uint16_t uv[2] = {uint16_t(glm::packHalf1x16(uv0.x)), uint16_t(glm::packHalf1x16(uv0.y))};
  gl::appendBytes(out, p, 4);
  gl::appendBytes(out, &frame, 1);
  gl::appendBytes(out, uv, 2);
}

}  // namespace mb::compact
