// The compact pipelines' encodings (pipelines/compact/compact_encoding.h) against
// closed-form error bounds, decoded by the shader's own functions (shaders/compact_frame.glsl
// through the shim): octahedral normal, diamond tangent, smallest-three rotor with its
// reflection bit (rotor scalar exactly +-0 included, and normal_torus's such frames through
// motor_c's vertex stream), int16 positions, the 16-byte layout.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "pipelines/compact/compact_encoding.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_c_vertices.h"
#include "pipelines/motor/motor_vertices.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

float angle(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

// Seeded uniform unit vectors.
std::vector<glm::vec3> unitVectors(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> out;
  while (int(out.size()) < n) {
    glm::vec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3f) out.push_back(glm::normalize(v));
  }
  return out;
}

// A unit vector perpendicular to `n`, turned by `a` in its plane.
glm::vec3 perpendicular(const glm::vec3& n, float a) {
  const glm::vec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  return std::cos(a) * u + std::sin(a) * glm::cross(n, u);
}

// The frame (normal = R z R~, tangent = R x R~) of a unit rotor (s, e23, e31, e12), as the
// quaternion (w = s, v = -(e23, e31, e12)) rotates: the closed form, independent of pga.glsl.
glm::mat2x3 rotorFrame(const glm::vec4& r) {
  const float w = r.x, x = -r.y, y = -r.z, z = -r.w;
  const glm::vec3 tangent(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y));
  const glm::vec3 normal(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
  return {normal, tangent};
}

}  // namespace

// Grid step h = 1/511 in the octahedral square: the nearest code is within h/sqrt 2; the
// octahedron's point moves at most sqrt 2 per unit, and the projection to the sphere stretches
// by at most sqrt 3 (|P| >= 1/sqrt 3): worst angle sqrt 3 / 511 rad (0.19 degrees).
TEST(CompactEncoding, OctahedralNormalWithinItsBoundAndAxesExact) {
  const float bound = std::sqrt(3.0f) / 511.0f;
  float worst = 0.0f;
  for (const glm::vec3& n : unitVectors(50000, 29)) {
    const compact::MatrixFrame f = compact::decodeMatrixFrame(compact::encodeMatrixFrame(n, glm::vec4(perpendicular(n, 0.3f), 1)));
    worst = std::max(worst, angle(n, f.normal));
  }
  std::printf("[ compact ] octahedral normal: worst %.4f deg (bound %.4f)\n", glm::degrees(worst), glm::degrees(bound));
  EXPECT_LE(worst, bound);
  for (int axis = 0; axis < 3; ++axis)
    for (float s : {1.0f, -1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = s;
      const compact::MatrixFrame f = compact::decodeMatrixFrame(compact::encodeMatrixFrame(n, glm::vec4(perpendicular(n, 1.0f), 1)));
      EXPECT_EQ(f.normal, n) << axis << " " << s;
    }
}

// The diamond code steps (1, 1) on a square of L1 radius 256 (Euclidean radius >= 256/sqrt 2):
// at most 1/256 rad per half step; the tangent also inherits the normal's error.
TEST(CompactEncoding, DiamondTangentWithinItsBoundAndHandednessBitExact) {
  const float bound = std::sqrt(3.0f) / 511.0f + 1.0f / 256.0f;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> turn(0.0f, 6.2831853f);
  float worst = 0.0f;
  int i = 0;
  for (const glm::vec3& n : unitVectors(50000, 30)) {
    const glm::vec3 t = perpendicular(n, turn(rng));
    const float w = (i++ % 2) ? -1.0f : 1.0f;
    const compact::MatrixFrame f = compact::decodeMatrixFrame(compact::encodeMatrixFrame(n, glm::vec4(t, w)));
    worst = std::max(worst, angle(t, f.tangent));
    ASSERT_EQ(f.handedness, w);
    ASSERT_LT(std::abs(glm::dot(f.normal, f.tangent)), 1e-5f);  // perpendicular to the decoded normal
  }
  std::printf("[ compact ] diamond tangent: worst %.4f deg (bound %.4f)\n", glm::degrees(worst), glm::degrees(bound));
  EXPECT_LE(worst, bound);
}

// Stored components: half steps of 1/(511 sqrt 2) (twice) and 1/(255 sqrt 2); the dropped one
// (>= 1/2) from the square root moves by at most |c| / d <= sqrt 3 times their error, so the
// rotor moves by at most 2 |e| and the rotation by at most twice that.
TEST(CompactEncoding, SmallestThreeRotorWithinItsBound) {
  const float e = std::sqrt(2.0f * std::pow(0.5f / (511.0f * std::sqrt(2.0f)), 2.0f) +
                            std::pow(0.5f / (255.0f * std::sqrt(2.0f)), 2.0f));
  const float bound = 4.0f * e;
  std::mt19937 rng(11);
  std::normal_distribution<float> g;
  float worst = 0.0f;
  for (int i = 0; i < 50000; ++i) {
    const glm::vec4 q = glm::normalize(glm::vec4(g(rng), g(rng), g(rng), g(rng)));
    const bool mirrored = i % 3 == 0;
    const compact::RotorFrame f = compact::decodeRotorFrame(compact::encodeRotorFrame(q, mirrored));
    ASSERT_NEAR(glm::length(f.rotor), 1.0f, 1e-5f);
    ASSERT_EQ(f.handedness, mirrored ? -1.0f : 1.0f);
    worst = std::max(worst, 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(f.rotor, q)))));
  }
  std::printf("[ compact ] smallest-three rotor: worst rotation %.4f deg (bound %.4f)\n", glm::degrees(worst),
              glm::degrees(bound));
  EXPECT_LE(worst, bound);
}

// The paper's rule keeps the handedness in the sign of the scalar part; a frame turned half a
// turn about an axis in the tangent plane has scalar exactly +-0, which an integer cannot keep.
// Here the handedness is its own bit: both signs of zero, both handednesses, the frame exact.
TEST(CompactEncoding, ZeroScalarRotorKeepsHandednessAndFrame) {
  for (glm::vec4 r : {glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1),
                      glm::vec4(0, 0.6f, 0.8f, 0), glm::vec4(-0.0f, 0, 0.8f, 0.6f)})
    for (bool mirrored : {false, true}) {
      const compact::RotorFrame f = compact::decodeRotorFrame(compact::encodeRotorFrame(r, mirrored));
      EXPECT_EQ(f.handedness, mirrored ? -1.0f : 1.0f);
      const glm::mat2x3 want = rotorFrame(r), got = rotorFrame(f.rotor);
      EXPECT_LT(angle(want[0], got[0]), 0.004f) << r.y << r.z << r.w;
      EXPECT_LT(angle(want[1], got[1]), 0.004f) << r.y << r.z << r.w;
    }
}

TEST(CompactEncoding, PositionsWithinHalfAStepOfTheirCube) {
  const std::vector<glm::vec3> p = {{-3.0f, 0.5f, 2.0f}, {5.0f, -1.0f, 2.5f}, {0.1f, 0.2f, 0.3f}, {4.9f, 0.0f, 2.1f}};
  const compact::PositionCube cube = compact::positionCube(p);
  EXPECT_EQ(cube.center.x, 1.0f);  // x spans -3..5, y -1..0.5, z 0.3..2.5: x sets the extent
  EXPECT_EQ(cube.center.y, -0.25f);
  EXPECT_NEAR(cube.center.z, 1.4f, 1e-6f);
  EXPECT_EQ(cube.extent, 4.0f);
  for (const glm::vec3& v : p) {
    int16_t q[4];
    compact::quantizePosition(v, cube, q);
    const glm::vec3 back = compact::dequantizePosition(q, cube);
    for (int i = 0; i < 3; ++i) EXPECT_LE(std::abs(back[i] - v[i]), cube.extent * (0.5f / 32767.0f) + 1e-6f);
  }
}

TEST(CompactEncoding, SixteenBytesPerVertexInTheWordLayoutGlReads) {
  size_t bytes = 0;
  for (const gl::PackedAttribute& a : compact::attributes()) bytes += a.bytes();
  EXPECT_EQ(bytes, compact::kVertexBytes);
  EXPECT_EQ(compact::wordFields(compact::packWord(1, 1023, 512, 3)), glm::vec4(1, 1023, 512, 3));
  EXPECT_EQ(compact::packWord(1, 2, 3, 2), 1u | 2u << 10 | 3u << 20 | 2u << 30);
  const compact::PositionCube cube = compact::positionCube({{0, 0, 0}, {1, 1, 1}});
  std::vector<uint8_t> s;
  compact::appendVertex(s, {0, 0, 0}, cube, 7, {0.5f, 2.0f});
  compact::appendVertex(s, {1, 1, 1}, cube, 9, {0, 0});
  ASSERT_EQ(s.size(), 2 * compact::kVertexBytes);
  uint32_t frame = 0;
  uint16_t uv[2];
  std::memcpy(&frame, s.data() + 8, 4);
  std::memcpy(uv, s.data() + 12, 4);
  EXPECT_EQ(frame, 7u);
  EXPECT_EQ(uv[0], 0x3800);  // half 0.5
  EXPECT_EQ(uv[1], 0x4000);  // half 2.0
}

// normal_torus has frames whose tangent rotor has a scalar part of exactly 0 (the paper's
// signed-zero case, companion.h). Through motor_c's whole vertex path (the 16 bytes uploaded,
// decoded by the shader's function) every frame keeps its handedness and its normal and tangent
// stay within the rotor's bound, the zero-scalar frames included.
TEST(CompactEncoding, NormalTorusZeroScalarFramesCorrectInFourBytes) {
  auto scene = loadScene("normal_torus");
  ASSERT_TRUE(scene) << scene.error();
  const float bound = 0.0068f;  // SmallestThreeRotorWithinItsBound's rotation bound, rounded up
  int zeroScalar = 0, checked = 0;
  for (const Mesh& mesh : scene->meshes)
    for (const Primitive& p : mesh.primitives) {
      if (p.tangents.empty()) continue;
      const gl::PackedStream stream = motor::interleaveCompact(p);
      const motor::VertexStream floats = motor::interleaveVertices(p);
      ASSERT_EQ(stream.bytes.size(), p.positions.size() * compact::kVertexBytes);
      zeroScalar += stream.zeroScalarFrames;
      for (size_t v = 0; v < p.positions.size(); ++v) {
        uint32_t word = 0;
        std::memcpy(&word, stream.bytes.data() + v * compact::kVertexBytes + 8, 4);
        const compact::RotorFrame f = compact::decodeRotorFrame(word);
        const glm::mat2x3 got = rotorFrame(f.rotor);
        const bool zero = std::abs(floats.data[v * motor::kFloatsPerVertex]) == companion::kMinTangentScalar;
        ASSERT_EQ(f.handedness, p.tangents[v].w < 0.0f ? -1.0f : 1.0f) << "vertex " << v << (zero ? " (zero scalar)" : "");
        ASSERT_LT(angle(got[0], p.normals[v]), bound) << "vertex " << v;
        ASSERT_LT(angle(got[1], glm::vec3(p.tangents[v])), bound) << "vertex " << v;
        ++checked;
      }
    }
  EXPECT_GT(zeroScalar, 0) << "normal_torus no longer has zero-scalar frames: the case is not exercised";
  std::printf("[ compact ] normal_torus: %d frames checked, %d with scalar part exactly 0\n", checked, zeroScalar);
}
