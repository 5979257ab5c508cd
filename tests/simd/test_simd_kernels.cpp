// kernels/simd against the shader functions compiled as C++ through the shim (the reference
// the GPU source defines), on >= 100k seeded inputs per kernel, for every Highway target this
// CPU supports (each forced in turn). Tolerance: every output vector (or matrix column / motor
// half) within 1e-5 of max(1, its reference length): the kernels fuse multiply-adds and
// refine inversesqrt by a Newton step where the shim rounds every operation.
#include <gtest/gtest.h>


#include <algorithm>
#include <cmath>
#include <memory>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "harness/bench/bench_shaders.h"
#include "kernels/simd/simd_kernels.h"
#include "kernels/simd/simd_targets.h"

namespace {

using MS = mb::MatrixShader<float>;
using AS = mb::AffineShader<float>;
using PS = mb::MotorShader<float>;
using mb::simd::ConstPlanes;
using mb::simd::Planes;

constexpr size_t kItems = 100003;  // not a multiple of any vector width: the tail runs too
constexpr double kTol = 1e-5;

// `comps` planes of `n` floats.
struct Planar {
  size_t n, comps;
  std::vector<float> v;
  Planar(size_t n_, size_t c) : n(n_), comps(c), v(n_ * c) {}
  float& at(size_t c, size_t i) { return v[c * n + i]; }
  float at(size_t c, size_t i) const { return v[c * n + i]; }
  Planes planes() { return {v.data(), n}; }
  ConstPlanes cplanes() const { return {v.data(), n}; }
};

// Worst error over the run, relative to max(1, |reference vector|).
struct Worst {
  double err = 0;
  std::string where;
  void vec(const float* got, const float* ref, int k, const std::string& what, size_t i) {
    double len = 0, d = 0;
    for (int c = 0; c < k; ++c) {
      len += double(ref[c]) * ref[c];
      const double g = std::fabs(double(got[c]) - ref[c]);
      d = std::isnan(g) || std::isnan(d) ? g + d : std::max(d, g);  // a NaN (poisoned output) stays
    }
    const double e = d / std::max(1.0, std::sqrt(len));
    if (!(e <= err)) err = std::isnan(e) ? 1e30 : e, where = what + " item " + std::to_string(i);
  }
  // Item i of a 10-plane output vertex against a shader's mat3x4 (position, normal, tangent + w).
  template <class P, class M> void vertex(const P& out, size_t i, const M& e) {
    float got[10];
    for (size_t c = 0; c < 10; ++c) got[c] = out.at(c, i);
    for (int k = 0; k < 3; ++k) {
      const float ref[4] = {e[k].x, e[k].y, e[k].z, e[k].w};
      vec(got + 3 * k, ref, k == 2 ? 4 : 3, "column " + std::to_string(k), i);
    }
  }
};

struct Rng {
  std::mt19937 g{20240613};
  float u(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(g); }
  PS::vec4 quat() {  // unit (x, y, z, w)
    std::normal_distribution<float> n;
    PS::vec4 q(n(g), n(g), n(g), n(g));
    return q * (1.0f / std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w));
  }
  // A unit motor T R and its affine matrix (mat4, column-major, uniform scale s).
  PS::motor motor(float* m16 = nullptr, float s = 1.0f) {
    const PS::vec4 q = quat();
    const float t[3] = {u(-5, 5), u(-5, 5), u(-5, 5)};
    PS P;
    const PS::motor R(PS::vec4(q.w, -q.x, -q.y, -q.z), PS::vec4(0.0f));
    const PS::motor T(PS::vec4(1, 0, 0, 0), PS::vec4(-0.5f * t[0], -0.5f * t[1], -0.5f * t[2], 0.0f));
    if (m16) {
      const float x = q.x, y = q.y, z = q.z, w = q.w;
      const float c[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                          2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                          2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m16[i * 4 + j] = c[i * 3 + j] * s;
        m16[i * 4 + 3] = 0, m16[12 + i] = t[i];
      }
      m16[15] = 1;
    }
    return P.gp_tr(T, R);
  }
};

MS::mat4 mat4Of(const float* m) {
  MS::mat4 r;
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) r[c][k] = m[c * 4 + k];
  return r;
}
AS::mat4x3 mat4x3Of(const float* m12) {
  AS::mat4x3 r;
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 3; ++k) r[c][k] = m12[c * 3 + k];
  return r;
}
PS::motor motorOf(const float* m) { return PS::motor(PS::vec4(m[0], m[1], m[2], m[3]), PS::vec4(m[4], m[5], m[6], m[7])); }
void put(const PS::motor& m, float* out) {
  for (int k = 0; k < 4; ++k) out[k] = m[0][k], out[4 + k] = m[1][k];
}

// Every supported target in turn (and the dispatch reset afterwards).
template <class F> void forEachTarget(F check) {
  const auto targets = mb::simd::supportedTargets();
  ASSERT_FALSE(targets.empty());
  for (const auto& t : targets) {
    mb::simd::forceTarget(t.bits);
    SCOPED_TRACE("target " + t.name);
    EXPECT_EQ(mb::simd::currentTarget().name, t.name);
    check(t.name);
  }
  mb::simd::forceTarget(0);
}

// Vertex inputs: position, normal + tangent (matrix), tangent rotor (motor) of the same frame.
struct Vertices {
  Planar matrix{kItems, 10}, motor{kItems, 7};
  Vertices() {
    Rng r;
    for (size_t i = 0; i < kItems; ++i) {
      const PS::vec4 q = r.quat();
      PS::vec4 rot(q.w, -q.x, -q.y, -q.z);
      const float hand = i % 3 == 0 ? -1.0f : 1.0f;
      if ((rot.x < 0) != (hand < 0)) rot = -rot;
      PS P;
      const PS::motor fr(rot, PS::vec4(0.0f));
      const PS::mat2x3 nt = P.extractNormalTangent(fr);
      for (int c = 0; c < 3; ++c) {
        const float p = r.u(-2, 2);
        matrix.at(c, i) = motor.at(c, i) = p;
        matrix.at(3 + c, i) = 2 * nt[0][c], matrix.at(6 + c, i) = 2 * nt[1][c];
      }
      matrix.at(9, i) = hand;
      for (int c = 0; c < 4; ++c) motor.at(3 + c, i) = rot[c];
    }
  }
};

TEST(SimdKernels, TargetsAreListedBestFirst) {
  const auto t = mb::simd::supportedTargets();
  ASSERT_FALSE(t.empty());
  for (size_t i = 1; i < t.size(); ++i) EXPECT_LT(t[i - 1].bits, t[i].bits) << t[i - 1].name << " before " << t[i].name;
  EXPECT_EQ(mb::simd::currentTarget().name, t.front().name);
}

TEST(SimdKernels, PointsAndDirectionsMatchTheShader) {
  Rng r;
  float m16[16];
  const PS::motor motor = r.motor(m16);
  float mm[8];
  put(motor, mm);
  Planar in(kItems, 3), out(kItems, 3);
  for (size_t i = 0; i < kItems; ++i)
    for (int c = 0; c < 3; ++c) in.at(c, i) = r.u(-10, 10);
  MS S;
  PS P;
  forEachTarget([&](const std::string&) {
    for (int kind = 0; kind < 4; ++kind) {
      const bool point = kind % 2 == 0, isMotor = kind >= 2;
      if (!isMotor) (point ? mb::simd::pointsMatrix : mb::simd::directionsMatrix)(m16, in.cplanes(), out.planes(), kItems);
      else (point ? mb::simd::pointsMotor : mb::simd::directionsMotor)(mm, in.cplanes(), out.planes(), kItems);
      Worst w;
      for (size_t i = 0; i < kItems; ++i) {
        const MS::vec3 v(in.at(0, i), in.at(1, i), in.at(2, i));
        float ref[3], got[3] = {out.at(0, i), out.at(1, i), out.at(2, i)};
        if (!isMotor) {
          const MS::vec4 e = point ? S.matrixTransformPoint(mat4Of(m16), v) : S.matrixTransformDirection(mat4Of(m16), v);
          ref[0] = e.x, ref[1] = e.y, ref[2] = e.z;
        } else {
          const PS::vec3 e = point ? P.sw_mp(motor, PS::vec3(v.x, v.y, v.z)) : P.sw_md(motor, PS::vec3(v.x, v.y, v.z));
          ref[0] = e.x, ref[1] = e.y, ref[2] = e.z;
        }
        w.vec(got, ref, 3, point ? "point" : "direction", i);
      }
      EXPECT_LE(w.err, kTol) << (isMotor ? "motor " : "matrix ") << w.where;
    }
  });
}

TEST(SimdKernels, VertexFrameMatchesTheShader) {
  const Vertices v;
  Rng r;
  float model[16], normal[16];
  const PS::motor motor = r.motor(model, 1.5f);
  for (int k = 0; k < 16; ++k) normal[k] = k % 4 == 3 || k >= 12 ? (k == 15 ? -1.0f : 0.0f) : model[k] / (1.5f * 1.5f);
  float m12[12], n9[9], mirror, mm[8];
  mb::simd::mat4ToAffine(model, normal, m12, n9, &mirror);
  EXPECT_EQ(mirror, -1.0f);
  put(motor, mm);
  Planar out(kItems, 10);
  MS S;
  PS P;
  forEachTarget([&](const std::string&) {
    mb::simd::vertexFrameMatrix(m12, n9, mirror, v.matrix.cplanes(), out.planes(), kItems);
    Worst wRigid, wAffine;
    for (size_t i = 0; i < kItems; ++i) {
      const MS::vec3 p(v.matrix.at(0, i), v.matrix.at(1, i), v.matrix.at(2, i));
      const MS::vec3 n(v.matrix.at(3, i), v.matrix.at(4, i), v.matrix.at(5, i));
      const MS::vec4 t(v.matrix.at(6, i), v.matrix.at(7, i), v.matrix.at(8, i), v.matrix.at(9, i));
      // Both shader forms: the Sample Viewer's mat4 one and the affine one.
      const MS::mat3x4 a = S.matrixRigidVertex(mat4Of(model), mat4Of(normal), p, n, t);
      const AS::mat3x4 b = AS().matrixAffineVertex(mat4x3Of(m12), AS::mat3(n9[0], n9[1], n9[2], n9[3], n9[4], n9[5],
                                                                         n9[6], n9[7], n9[8]),
                                                   mirror, p, n, t);
      wRigid.vertex(out, i, a);
      wAffine.vertex(out, i, b);
    }
    EXPECT_LE(wRigid.err, kTol) << "matrixRigidVertex " << wRigid.where;
    EXPECT_LE(wAffine.err, kTol) << "matrixAffineVertex " << wAffine.where;

    mb::simd::vertexFrameMotor(mm, 1.5f, v.motor.cplanes(), out.planes(), kItems);
    Worst wm;
    size_t handedness = 0;
    for (size_t i = 0; i < kItems; ++i) {
      const PS::mat3x4 e = P.motorRigidVertex(
          motor, 1.5f, PS::vec3(v.motor.at(0, i), v.motor.at(1, i), v.motor.at(2, i)),
          PS::vec4(v.motor.at(3, i), v.motor.at(4, i), v.motor.at(5, i), v.motor.at(6, i)));
      wm.vertex(out, i, e);
      handedness += out.at(9, i) == e[2].w;
    }
    EXPECT_LE(wm.err, kTol) << "motorRigidVertex " << wm.where;
    EXPECT_EQ(handedness, kItems);  // exact: a sign
  });
}

// Palettes of 5, 16 and 48 joints are held in registers on the targets where they fit in at most
// four vectors per component (PaletteFetch, simd_math-inl.h), 300 joints are gathered everywhere:
// both fetches against the shader on every target.
TEST(SimdKernels, SkinnedVertexMatchesTheShader) {
  for (const size_t kJoints : {size_t(5), size_t(16), size_t(48), size_t(300)}) {
  SCOPED_TRACE(std::to_string(kJoints) + " joints");
    const Vertices v;
    Rng r;
    Planar palM(kJoints, 12), palP(kJoints, 8);
    std::vector<AS::mat4x3> jm(kJoints);
    std::vector<PS::motor> jp(kJoints);
    for (size_t j = 0; j < kJoints; ++j) {
      float m16[16];
      jp[j] = r.motor(m16);
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 3; ++k) palM.at(size_t(c * 3 + k), j) = jm[j][c][k] = m16[c * 4 + k];
      for (int k = 0; k < 4; ++k) palP.at(size_t(k), j) = jp[j][0][k], palP.at(size_t(4 + k), j) = jp[j][1][k];
    }
    std::vector<uint16_t> joints(4 * kItems);
    Planar weights(kItems, 4);
    for (size_t i = 0; i < kItems; ++i) {
      float w[4], sum = 0;
      for (float& x : w) sum += x = r.u(0.05f, 1.0f);
      for (size_t k = 0; k < 4; ++k)
        joints[k * kItems + i] = uint16_t(std::uniform_int_distribution<int>(0, kJoints - 1)(r.g)), weights.at(k, i) = w[k] / sum;
    }
    const mb::simd::JointPlanes jp4{joints.data(), kItems};
    Planar out(kItems, 10);
    AS A;
    PS P;
    // Both palette fetches (in registers where the palette fits, and always gathered) on every target.
    for (const auto mode : {mb::simd::PaletteFetchMode::InRegisters, mb::simd::PaletteFetchMode::Gathered})
    forEachTarget([&](const std::string&) {
      SCOPED_TRACE(mode == mb::simd::PaletteFetchMode::Gathered ? "gathered" : "in registers");
      std::fill(out.v.begin(), out.v.end(), std::nanf(""));
      mb::simd::skinnedVertexMatrix(palM.cplanes(), -1.0f, v.matrix.cplanes(), jp4, weights.cplanes(), out.planes(), kItems,
                                    mode);
      Worst wa;
      for (size_t i = 0; i < kItems; ++i) {
        auto J = [&](size_t k) { return jm[joints[k * kItems + i]]; };
        const AS::mat3x4 e = A.affineSkinnedVertex(
            J(0), J(1), J(2), J(3), AS::vec4(weights.at(0, i), weights.at(1, i), weights.at(2, i), weights.at(3, i)), -1.0f,
            AS::vec3(v.matrix.at(0, i), v.matrix.at(1, i), v.matrix.at(2, i)),
            AS::vec3(v.matrix.at(3, i), v.matrix.at(4, i), v.matrix.at(5, i)),
            AS::vec4(v.matrix.at(6, i), v.matrix.at(7, i), v.matrix.at(8, i), v.matrix.at(9, i)));
        wa.vertex(out, i, e);
      }
      EXPECT_LE(wa.err, kTol) << "affineSkinnedVertex " << wa.where;

      std::fill(out.v.begin(), out.v.end(), std::nanf(""));
      mb::simd::skinnedVertexMotor(palP.cplanes(), 1.25f, v.motor.cplanes(), jp4, weights.cplanes(), out.planes(), kItems,
                                   mode);
      Worst wm;
      for (size_t i = 0; i < kItems; ++i) {
        auto J = [&](size_t k) { return jp[joints[k * kItems + i]]; };
        const PS::mat3x4 e = P.motorSkinnedVertex(
            J(0), J(1), J(2), J(3), PS::vec4(weights.at(0, i), weights.at(1, i), weights.at(2, i), weights.at(3, i)), 1.25f,
            PS::vec3(v.motor.at(0, i), v.motor.at(1, i), v.motor.at(2, i)),
            PS::vec4(v.motor.at(3, i), v.motor.at(4, i), v.motor.at(5, i), v.motor.at(6, i)));
        wm.vertex(out, i, e);
      }
      EXPECT_LE(wm.err, kTol) << "motorSkinnedVertex " << wm.where;
    });
  }
}

// Item i of planar operands: a mat4, an affine 4x3 as a mat4 with last row (0, 0, 0, 1), a motor.
MS::mat4 mat4At(const Planar& p, size_t i) {
  float m[16];
  for (int k = 0; k < 16; ++k) m[k] = p.at(size_t(k), i);
  return mat4Of(m);
}
MS::mat4 affineAt(const Planar& p, size_t i) {
  float m[16];
  for (int c = 0; c < 4; ++c) {
    for (int k = 0; k < 3; ++k) m[c * 4 + k] = p.at(size_t(c * 3 + k), i);
    m[c * 4 + 3] = c == 3 ? 1.0f : 0.0f;
  }
  return mat4Of(m);
}
PS::motor motorAt(const Planar& p, size_t i) {
  float m[8];
  for (int k = 0; k < 8; ++k) m[k] = p.at(size_t(k), i);
  return motorOf(m);
}

// Random operands for the compose and palette kernels: the same transforms as general mat4s
// (a16, b16), affine 4x3s (a12, b12) and motors (a8, b8), their outputs, and a random world
// index per palette item.
struct ComposeCase {
  Planar a16{kItems, 16}, b16{kItems, 16}, o16{kItems, 16}, a12{kItems, 12}, b12{kItems, 12}, o12{kItems, 12};
  Planar a8{kItems, 8}, b8{kItems, 8}, o8{kItems, 8};
  std::vector<int32_t> node = std::vector<int32_t>(kItems);
  MS S;
  PS P;

  ComposeCase() {
    Rng r;
    for (size_t i = 0; i < kItems; ++i) {
      float ma[16], mb[16];
      const PS::motor pa = r.motor(ma, r.u(0.5f, 2.0f)), pb = r.motor(mb, r.u(0.5f, 2.0f));
      // A general (projective) mat4 on the mat4 kernel: it multiplies all 16 entries.
      for (int k = 0; k < 16; ++k) a16.at(size_t(k), i) = k % 4 == 3 ? r.u(-1, 1) : ma[k], b16.at(size_t(k), i) = mb[k];
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 3; ++k) a12.at(size_t(c * 3 + k), i) = ma[c * 4 + k], b12.at(size_t(c * 3 + k), i) = mb[c * 4 + k];
      for (int k = 0; k < 4; ++k)
        a8.at(size_t(k), i) = pa[0][k], a8.at(size_t(4 + k), i) = pa[1][k], b8.at(size_t(k), i) = pb[0][k],
                  b8.at(size_t(4 + k), i) = pb[1][k];
      node[i] = int32_t(std::uniform_int_distribution<int>(0, int(kItems) - 1)(r.g));
    }
  }

  // The three compose kernels against matrixCompose (general and affine) and gp_mm.
  void checkCompose() {
    mb::simd::composeMat4(a16.cplanes(), b16.cplanes(), o16.planes(), kItems);
    mb::simd::composeAffine(a12.cplanes(), b12.cplanes(), o12.planes(), kItems);
    mb::simd::composeMotor(a8.cplanes(), b8.cplanes(), o8.planes(), kItems);
    Worst w4, w3, wm;
    for (size_t i = 0; i < kItems; ++i) {
      const MS::mat4 e4 = S.matrixCompose(mat4At(a16, i), mat4At(b16, i));
      const MS::mat4 e3 = S.matrixCompose(affineAt(a12, i), affineAt(b12, i));
      const PS::motor em = P.gp_mm(motorAt(a8, i), motorAt(b8, i));
      for (int c = 0; c < 4; ++c) {
        const float r4[4] = {e4[c].x, e4[c].y, e4[c].z, e4[c].w}, r3[3] = {e3[c].x, e3[c].y, e3[c].z};
        float g4[4], g3[3];
        for (int k = 0; k < 4; ++k) g4[k] = o16.at(size_t(c * 4 + k), i);
        for (int k = 0; k < 3; ++k) g3[k] = o12.at(size_t(c * 3 + k), i);
        w4.vec(g4, r4, 4, "column " + std::to_string(c), i);
        w3.vec(g3, r3, 3, "column " + std::to_string(c), i);
        EXPECT_EQ(e3[c].w, c == 3 ? 1.0f : 0.0f);  // the affine form drops an exact row
      }
      for (int h = 0; h < 2; ++h) {
        const float ref[4] = {em[h].x, em[h].y, em[h].z, em[h].w};
        float got[4];
        for (int k = 0; k < 4; ++k) got[k] = o8.at(size_t(4 * h + k), i);
        wm.vec(got, ref, 4, "half " + std::to_string(h), i);
      }
    }
    EXPECT_LE(w4.err, kTol) << "matrixCompose " << w4.where;
    EXPECT_LE(w3.err, kTol) << "matrixCompose (affine) " << w3.where;
    EXPECT_LE(wm.err, kTol) << "gp_mm " << wm.where;
  }

  void checkPalette() {
    // Palette: world[node[j]] * inverseBind[j], the operands AoS as the pipelines hold them
    // (worlds as the hierarchy kernels write them: the affine a12 as mat4s, the motor a8 with a
    // scale that gp_mm does not apply; the inverse binds b12 as mat4s, b8 as motors), the
    // outputs poisoned with NaN first.
    constexpr size_t WM = mb::simd::kHierarchyMotorFloats;
    std::vector<float> world16(16 * kItems), worldM(WM * kItems, 0.0f), ib16(16 * kItems), ib8(8 * kItems);
    for (size_t i = 0; i < kItems; ++i) {
      const MS::mat4 wa = affineAt(a12, i), ba = affineAt(b12, i);
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) world16[16 * i + size_t(4 * c + k)] = wa[c][k], ib16[16 * i + size_t(4 * c + k)] = ba[c][k];
      for (size_t k = 0; k < 8; ++k) worldM[WM * i + k] = a8.at(k, i), ib8[8 * i + k] = b8.at(k, i);
      worldM[WM * i + 8] = 3.0f;
    }
    std::vector<float> pout16(16 * kItems, std::nanf("")), pout8(8 * kItems, std::nanf(""));
    mb::simd::paletteAffine(world16.data(), node.data(), ib16.data(), pout16.data(), kItems);
    mb::simd::paletteMotor(worldM.data(), node.data(), ib8.data(), pout8.data(), kItems);
    Worst pa, pm;
    for (size_t i = 0; i < kItems; ++i) {
      const size_t k = size_t(node[i]);
      const MS::mat4 e4 = S.matrixCompose(affineAt(a12, k), affineAt(b12, i));
      const PS::motor em = P.gp_mm(motorAt(a8, k), motorAt(b8, i));
      for (int c = 0; c < 4; ++c) {
        const float r4[4] = {e4[c].x, e4[c].y, e4[c].z, e4[c].w};
        pa.vec(&pout16[16 * i + size_t(4 * c)], r4, 4, "column " + std::to_string(c), i);
      }
      for (int h = 0; h < 2; ++h) {
        const float ref[4] = {em[h].x, em[h].y, em[h].z, em[h].w};
        pm.vec(&pout8[8 * i + size_t(4 * h)], ref, 4, "half " + std::to_string(h), i);
      }
    }
    EXPECT_LE(pa.err, kTol) << "palette affine " << pa.where;
    EXPECT_LE(pm.err, kTol) << "palette motor " << pm.where;
  }
};

TEST(SimdKernels, ComposeAndPaletteMatchTheShader) {
  ComposeCase c;
  forEachTarget([&](const std::string&) {
    c.checkCompose();
    c.checkPalette();
  });
}

}  // namespace

namespace {

// Batches writing >= 64 MiB to 64-byte aligned planes take the streaming-store path
// (simd_math-inl.h): the same results as the shader there too.
TEST(SimdKernels, LargeAlignedBatchesStreamWithTheSameResults) {
  constexpr size_t kBig = (size_t(64) << 20) / (3 * sizeof(float)) + 4097;  // 3 output planes > 64 MiB; odd
  constexpr size_t kStride = kBig + 10;                                      // a multiple of 16 floats
  static_assert(kStride % 16 == 0);
  struct Free {
    void operator()(float* p) const { ::operator delete(p, std::align_val_t(64)); }
  };
  auto alloc = [](size_t floats) {
    return std::unique_ptr<float, Free>(static_cast<float*>(::operator new(floats * sizeof(float), std::align_val_t(64))));
  };
  auto in = alloc(3 * kStride), out = alloc(3 * kStride);
  Rng r;
  for (size_t c = 0; c < 3; ++c)
    for (size_t i = 0; i < kBig; ++i) in.get()[c * kStride + i] = r.u(-10, 10);
  float m16[16], mm[8];
  const PS::motor motor = r.motor(m16);
  put(motor, mm);
  MS S;
  PS P;
  forEachTarget([&](const std::string&) {
    for (const bool isMotor : {false, true}) {
      if (isMotor) mb::simd::pointsMotor(mm, {in.get(), kStride}, {out.get(), kStride}, kBig);
      else mb::simd::pointsMatrix(m16, {in.get(), kStride}, {out.get(), kStride}, kBig);
      Worst w;
      auto check = [&](size_t i) {
        const float* x = in.get();
        float ref[3], got[3];
        if (isMotor) {
          const PS::vec3 e = P.sw_mp(motor, PS::vec3(x[i], x[kStride + i], x[2 * kStride + i]));
          ref[0] = e.x, ref[1] = e.y, ref[2] = e.z;
        } else {
          const MS::vec4 e = S.matrixTransformPoint(mat4Of(m16), MS::vec3(x[i], x[kStride + i], x[2 * kStride + i]));
          ref[0] = e.x, ref[1] = e.y, ref[2] = e.z;
        }
        for (size_t c = 0; c < 3; ++c) got[c] = out.get()[c * kStride + i];
        w.vec(got, ref, 3, "point", i);
      };
      for (size_t i = 0; i < kBig; i += 7) check(i);  // every lane position of the streamed loop
      check(kBig - 1);                                // the one-lane tail (ordinary stores)
      EXPECT_LE(w.err, kTol) << (isMotor ? "motor " : "matrix ") << w.where;
    }
  });
}

}  // namespace

namespace {

// Hierarchy update against the shader products node by node: matrixCompose of the T R S
// matrices, and gp_mm of gp_tr(T, R) with the parent's scale on the e0 half. The nodes in level
// order (every level wide) and in their own order (a random forest: parents anywhere before).
TEST(SimdKernels, HierarchyMatchesTheShaderProducts) {
  constexpr size_t kNodes = 30011;
  Rng r;
  // A random forest, parents before children; then grouped by depth (the kernels' order).
  std::vector<int> parent0(kNodes), depth(kNodes);
  for (size_t i = 0; i < kNodes; ++i) {
    parent0[i] = i < 7 ? -1 : std::uniform_int_distribution<int>(0, int(i) - 1)(r.g);
    depth[i] = parent0[i] < 0 ? 0 : depth[size_t(parent0[i])] + 1;
  }
  std::vector<size_t> order(kNodes), slot(kNodes);
  for (size_t i = 0; i < kNodes; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return depth[a] < depth[b]; });
  for (size_t k = 0; k < kNodes; ++k) slot[order[k]] = k;
  std::vector<int32_t> parent(kNodes);
  std::vector<uint32_t> levelEnd;
  Planar trs(kNodes, 8);
  for (size_t k = 0; k < kNodes; ++k) {
    const size_t i = order[k];
    parent[k] = parent0[i] < 0 ? -1 : int32_t(slot[size_t(parent0[i])]);
    if (k + 1 == kNodes || depth[order[k + 1]] != depth[i]) levelEnd.push_back(uint32_t(k + 1));
    const PS::vec4 q = r.quat();
    for (size_t c = 0; c < 4; ++c) trs.at(c, k) = q[int(c)];
    for (size_t c = 4; c < 7; ++c) trs.at(c, k) = r.u(-1, 1);
    trs.at(7, k) = r.u(0.9f, 1.1f);
  }
  ASSERT_GT(levelEnd.size(), 3u);
  MS S;
  PS P;
  // Scalar references in level order (parents first).
  std::vector<MS::mat4> refM(kNodes);
  std::vector<PS::motor> refP(kNodes);
  std::vector<float> refS(kNodes);
  for (size_t k = 0; k < kNodes; ++k) {
    const float x = trs.at(0, k), y = trs.at(1, k), z = trs.at(2, k), w = trs.at(3, k), s = trs.at(7, k);
    const float x2 = x + x, y2 = y + y, z2 = z + z;
    const float xx = x * x2, yy = y * y2, zz = z * z2, xy = x * y2, xz = x * z2, yz = y * z2, wx = w * x2,
                wy = w * y2, wz = w * z2;
    const MS::mat4 local(MS::vec4(MS::vec3(1.0f - (yy + zz), xy + wz, xz - wy) * s, 0.0f),
                         MS::vec4(MS::vec3(xy - wz, 1.0f - (xx + zz), yz + wx) * s, 0.0f),
                         MS::vec4(MS::vec3(xz + wy, yz - wx, 1.0f - (xx + yy)) * s, 0.0f),
                         MS::vec4(trs.at(4, k), trs.at(5, k), trs.at(6, k), 1.0f));
    const PS::motor T(PS::vec4(1, 0, 0, 0), PS::vec4(-0.5f * trs.at(4, k), -0.5f * trs.at(5, k), -0.5f * trs.at(6, k), 0.0f));
    const PS::motor lm = P.gp_tr(T, PS::motor(PS::vec4(w, -x, -y, -z), PS::vec4(0.0f)));
    const int p = parent[k];
    if (p < 0) {
      refM[k] = local, refP[k] = lm, refS[k] = s;
      continue;
    }
    ASSERT_LT(size_t(p), k);
    refM[k] = S.matrixCompose(refM[size_t(p)], local);
    refP[k] = P.gp_mm(refP[size_t(p)], PS::motor(lm[0], lm[1] * refS[size_t(p)]));
    refS[k] = refS[size_t(p)] * s;
  }
  // The same nodes in their own (random forest) order: node i is level-order node slot[i].
  Planar trsOwn(kNodes, 8);
  for (size_t i = 0; i < kNodes; ++i)
    for (size_t c = 0; c < 8; ++c) trsOwn.at(c, i) = trs.at(c, slot[i]);
  constexpr size_t WA = mb::simd::kHierarchyAffineFloats, WM = mb::simd::kHierarchyMotorFloats;
  std::vector<float> wm(kNodes * WA), wp(kNodes * WM);
  forEachTarget([&](const std::string& target) {
   for (const bool own : {false, true}) {
    SCOPED_TRACE(target + (own ? ", own order" : ", level order"));
    if (own) {
      mb::simd::hierarchyAffine(trsOwn.cplanes(), parent0.data(), kNodes, wm.data());
      mb::simd::hierarchyMotor(trsOwn.cplanes(), parent0.data(), kNodes, wp.data());
      // Back to level order for the comparison.
      std::vector<float> m2(wm.size()), p2(wp.size());
      for (size_t i = 0; i < kNodes; ++i) {
        std::copy_n(&wm[i * WA], WA, &m2[slot[i] * WA]);
        std::copy_n(&wp[i * WM], WM, &p2[slot[i] * WM]);
      }
      wm.swap(m2), wp.swap(p2);
    } else {
      mb::simd::hierarchyAffine(trs.cplanes(), parent.data(), kNodes, wm.data());
      mb::simd::hierarchyMotor(trs.cplanes(), parent.data(), kNodes, wp.data());
    }
    Worst a, m;
    for (size_t k = 0; k < kNodes; ++k) {
      for (int c = 0; c < 4; ++c) {
        const float ref[4] = {refM[k][c].x, refM[k][c].y, refM[k][c].z, refM[k][c].w};
        a.vec(&wm[k * WA + size_t(4 * c)], ref, 4, "column " + std::to_string(c), k);
      }
      for (int h = 0; h < 2; ++h) {
        const float ref[4] = {refP[k][h].x, refP[k][h].y, refP[k][h].z, refP[k][h].w};
        m.vec(&wp[k * WM + size_t(4 * h)], ref, 4, "half " + std::to_string(h), k);
      }
      const float rs[1] = {refS[k]};
      m.vec(&wp[k * WM + 8], rs, 1, "scale", k);
    }
    EXPECT_LE(a.err, kTol) << "hierarchy affine " << a.where;
    EXPECT_LE(m.err, kTol) << "hierarchy motor " << m.where;
   }
  });
}

}  // namespace
