// vertex_frame and skinned vertices: a full vertex (position + frame) per item, over arrays in
// cache and far out of cache. Matrix: matrixRigidVertex of matrix_transform.glsl (model + normal
// mat4); motor: motorRigidVertex of motor_transform.glsl (one motor + uniform scale); glm: the
// Sample Viewer's products with GLM. Skinning in matched configurations, two pairs:
//   skinned_vertex            world palette on every side: joint world * inverse bind, no node
//                             transform per vertex (matrixSkinnedVertexWorld, motorSkinnedVertex,
//                             the simd sides); the motor pipelines' default
//   skinned_vertex_reference  the references' form on every side: palette relative to the mesh
//                             node, then the node's transform per vertex (matrixSkinnedVertex, the
//                             Sample Viewer's; motorSkinnedVertexReference, the paper's listing)
// Inputs are the vertex layouts the pipelines upload: matrix position + normal + tangent
// (10 floats), motor position + tangent rotor (7 floats), skin joints (4 x u16) + weights.
// Both sides write the same 10-float world vertex (position, normal, tangent + handedness).
// simd_matrix / simd_motor: the hand-vectorised kernels of kernels/simd on structure-of-arrays
// copies of the same vertices and palettes (same bytes per vertex): vertex_frame
// matrixAffineVertex (the same products as matrixRigidVertex for these affine uniforms) vs
// motorRigidVertex; skinned_vertex affineSkinnedVertex (mat4x3 joints, cofactor normals: the
// cheapest matrix LBS of the shaders, 12 floats per joint) vs motorSkinnedVertex, the palette
// held in registers; skinned_vertex_gather: the same simd pair gathering every palette entry.
#include <cstdint>

#include <glm/glm.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"
#include "kernels/simd/simd_kernels.h"

namespace mb::bench {
namespace {

struct MatrixVertex {
  float p[3], n[3], t[4];
};
struct MotorVertex {
  float p[3], r[4];
};
struct SkinAttrs {
  uint16_t j[4];
  float w[4];
};
struct OutVertex {
  float p[3], n[3], t[4];
};

constexpr int kJoints = 32;
constexpr size_t kFrameMatrixBytes = sizeof(MatrixVertex) + sizeof(OutVertex);
constexpr size_t kFrameMotorBytes = sizeof(MotorVertex) + sizeof(OutVertex);
constexpr size_t kSkinMatrixBytes = kFrameMatrixBytes + sizeof(SkinAttrs);
constexpr size_t kSkinMotorBytes = kFrameMotorBytes + sizeof(SkinAttrs);

// One set of arrays per size, shared by both kernels and all sides: the count serves the
// largest in-cache and the smallest out-of-cache side.
struct Arrays {
  std::vector<MatrixVertex> matrix;
  std::vector<MotorVertex> motor;
  std::vector<SkinAttrs> skin;
  std::vector<OutVertex> out;
  explicit Arrays(size_t n) : matrix(n), motor(n), skin(n), out(n) {
    Rng r;
    for (size_t i = 0; i < n; ++i) {
      const Quat q = randomQuat(r);
      float c0[3], c1[3], c2[3];
      quatColumns(q, c0, c1, c2);
      // Handedness as in real meshes: runs of mirrored UV islands, not a coin toss per vertex.
      const float w = (i / 64) % 4 == 3 ? -1.0f : 1.0f;
      const float p[3] = {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
      // Frame: tangent = x column, normal = z column; the rotor's scalar sign is the handedness.
      PS::vec4 rot = rotorOf(q);
      if ((rot.x < 0.0f) != (w < 0.0f)) rot = -rot;
      matrix[i] = {{p[0], p[1], p[2]}, {c2[0], c2[1], c2[2]}, {c0[0], c0[1], c0[2], w}};
      motor[i] = {{p[0], p[1], p[2]}, {rot.x, rot.y, rot.z, rot.w}};
      // Skins are spatially coherent: runs of vertices share a joint set (a limb region);
      // weights vary per vertex.
      const int base = int(i / 32) * 3 % kJoints;
      float ws[4], sum = 0;
      for (float& x : ws) sum += x = r.uniform(0.05f, 1.0f);
      for (int k = 0; k < 4; ++k)
        skin[i].j[k] = uint16_t((base + k) % kJoints), skin[i].w[k] = ws[k] / sum;
    }
  }
};

Arrays& arrays(Size s) { return perSize<Arrays>(s, vertexCount(s, kFrameMotorBytes, kSkinMatrixBytes)); }

// Per-draw uniforms and the joint palettes, both ways.
struct Draw {
  MS::mat4 model, normal;
  glm::mat4 gModel, gNormal;
  PS::motor motor;
  float scale;
  MS::mat4 joint[kJoints], jointNormal[kJoints];
  glm::mat4 gJoint[kJoints], gJointNormal[kJoints];
  PS::motor jointMotor[kJoints];
  Draw() {
    Rng r;
    auto toGlm = [](const float* m) {
      glm::mat4 g;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) g[c][k] = m[c * 4 + k];
      return g;
    };
    const Transform t = randomTransform(r, 1.5f);
    model = toShim(t.matrix), normal = toShim(t.normal), motor = t.motor, scale = t.scale;
    gModel = toGlm(t.matrix), gNormal = toGlm(t.normal);
    for (int j = 0; j < kJoints; ++j) {
      const Transform jt = randomTransform(r);
      joint[j] = toShim(jt.matrix), jointNormal[j] = toShim(jt.normal), jointMotor[j] = jt.motor;
      gJoint[j] = toGlm(jt.matrix), gJointNormal[j] = toGlm(jt.normal);
    }
  }
};

const Draw& draw() {
  static const Draw d;
  return d;
}

inline void store(OutVertex& o, const MS::mat3x4& v) {
  o = {{v[0].x, v[0].y, v[0].z}, {v[1].x, v[1].y, v[1].z}, {v[2].x, v[2].y, v[2].z, v[2].w}};
}
inline void store(OutVertex& o, const glm::vec4& p, const glm::vec4& n, const glm::vec4& t, float w) {
  o = {{p.x, p.y, p.z}, {n.x, n.y, n.z}, {t.x, t.y, t.z, w}};
}

// The pass over all vertices; `vertex(i)` transforms vertex i into out[i]. flatten inlines the
// whole shader function into the loop on every side alike: left to its heuristics, GCC keeps
// some shim functions out of line and returns their mat3x4 through the stack, where partial
// stores followed by vector loads stall store forwarding (a cost of the shim's codegen, not of
// the math).
template <class F> [[gnu::flatten]] void run(benchmark::State& state, Size s, size_t bytesPerItem, F vertex) {
  Arrays& a = arrays(s);
  const size_t n = a.out.size();
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) vertex(a, i);
    benchmark::DoNotOptimize(a.out.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, n, n * bytesPerItem, s);
}

// Per-draw uniforms are copied into the kernels' closures (locals that no store can alias),
// as a GPU keeps them in registers; joint palettes stay in memory, indexed per vertex.
void frameMatrix(benchmark::State& state, Size s) {
  const MS::mat4 model = draw().model, normal = draw().normal;
  MS S;
  run(state, s, kFrameMatrixBytes, [=](Arrays& a, size_t i) mutable {
    const MatrixVertex& v = a.matrix[i];
    store(a.out[i], S.matrixRigidVertex(model, normal, MS::vec3(v.p[0], v.p[1], v.p[2]),
                                        MS::vec3(v.n[0], v.n[1], v.n[2]),
                                        MS::vec4(v.t[0], v.t[1], v.t[2], v.t[3])));
  });
}

void frameMotor(benchmark::State& state, Size s) {
  const PS::motor motor = draw().motor;
  const float scale = draw().scale;
  PS P;
  run(state, s, kFrameMotorBytes, [=](Arrays& a, size_t i) mutable {
    const MotorVertex& v = a.motor[i];
    store(a.out[i], P.motorRigidVertex(motor, scale, PS::vec3(v.p[0], v.p[1], v.p[2]),
                                       PS::vec4(v.r[0], v.r[1], v.r[2], v.r[3])));
  });
}

void frameGlm(benchmark::State& state, Size s) {
  const glm::mat4 model = draw().gModel, normal = draw().gNormal;
  run(state, s, kFrameMatrixBytes, [=](Arrays& a, size_t i) {
    const MatrixVertex& v = a.matrix[i];
    store(a.out[i], model * glm::vec4(v.p[0], v.p[1], v.p[2], 1.0f),
          normal * glm::vec4(v.n[0], v.n[1], v.n[2], 0.0f),
          model * glm::vec4(v.t[0], v.t[1], v.t[2], 0.0f), v.t[3] * normal[3][3]);
  });
}

// Skinned vertex, both configurations per side (`reference`: the node's transform after the blend).
template <bool reference> void skinMatrix(benchmark::State& state, Size s) {
  const Draw& d = draw();
  const MS::mat4 model = d.model, normal = d.normal;
  MS S;
  run(state, s, kSkinMatrixBytes, [&, model, normal](Arrays& a, size_t i) {
    const MatrixVertex& v = a.matrix[i];
    const SkinAttrs& k = a.skin[i];
    const MS::vec4 w(k.w[0], k.w[1], k.w[2], k.w[3]);
    const MS::vec3 p(v.p[0], v.p[1], v.p[2]), n(v.n[0], v.n[1], v.n[2]);
    const MS::vec4 t(v.t[0], v.t[1], v.t[2], v.t[3]);
    const MS::mat4 *J = d.joint, *N = d.jointNormal;
    const uint16_t* j = k.j;
    if constexpr (reference)
      store(a.out[i], S.matrixSkinnedVertex(J[j[0]], J[j[1]], J[j[2]], J[j[3]], N[j[0]], N[j[1]], N[j[2]], N[j[3]],
                                            w, model, normal, p, n, t));
    else
      store(a.out[i], S.matrixSkinnedVertexWorld(J[j[0]], J[j[1]], J[j[2]], J[j[3]], N[j[0]], N[j[1]], N[j[2]],
                                                 N[j[3]], w, normal, p, n, t));
  });
}

template <bool reference> void skinMotor(benchmark::State& state, Size s) {
  const Draw& d = draw();
  const PS::motor toWorld = d.motor;
  const float scale = d.scale;
  PS P;
  run(state, s, kSkinMotorBytes, [&, toWorld, scale](Arrays& a, size_t i) {
    const MotorVertex& v = a.motor[i];
    const SkinAttrs& k = a.skin[i];
    const PS::motor* J = d.jointMotor;
    const uint16_t* j = k.j;
    const PS::vec4 w(k.w[0], k.w[1], k.w[2], k.w[3]), r(v.r[0], v.r[1], v.r[2], v.r[3]);
    const PS::vec3 p(v.p[0], v.p[1], v.p[2]);
    if constexpr (reference)
      store(a.out[i], P.motorSkinnedVertexReference(toWorld, J[j[0]], J[j[1]], J[j[2]], J[j[3]], w, scale, p, r));
    else
      store(a.out[i], P.motorSkinnedVertex(J[j[0]], J[j[1]], J[j[2]], J[j[3]], w, scale, p, r));
  });
}

template <bool reference> void skinGlm(benchmark::State& state, Size s) {
  const Draw& d = draw();
  const glm::mat4 model = d.gModel, normal = d.gNormal;
  run(state, s, kSkinMatrixBytes, [&, model, normal](Arrays& a, size_t i) {
    const MatrixVertex& v = a.matrix[i];
    const SkinAttrs& k = a.skin[i];
    const glm::mat4 skin = k.w[0] * d.gJoint[k.j[0]] + k.w[1] * d.gJoint[k.j[1]] +
                           k.w[2] * d.gJoint[k.j[2]] + k.w[3] * d.gJoint[k.j[3]];
    const glm::mat4 skinN = k.w[0] * d.gJointNormal[k.j[0]] + k.w[1] * d.gJointNormal[k.j[1]] +
                            k.w[2] * d.gJointNormal[k.j[2]] + k.w[3] * d.gJointNormal[k.j[3]];
    const glm::vec4 p = skin * glm::vec4(v.p[0], v.p[1], v.p[2], 1.0f);
    const glm::vec4 n = skinN * glm::vec4(v.n[0], v.n[1], v.n[2], 0.0f);
    const glm::vec4 t = skin * glm::vec4(v.t[0], v.t[1], v.t[2], 0.0f);
    if constexpr (reference)
      store(a.out[i], model * p, normal * n, model * t, v.t[3] * normal[3][3]);
    else
      store(a.out[i], p, n, t, v.t[3] * normal[3][3]);
  });
}


// ---- simd sides: planar copies of the same vertices and palettes -----------------------------

struct SoaArrays {
  size_t n, stride;
  AlignedVector<float> matrix, motor, weights, out;  // 10, 7, 4, 10 planes of n
  AlignedVector<uint16_t> joints;                    // 4 planes of n
  std::vector<float> paletteAffine, paletteMotor;  // 12, 8 planes of kJoints
  explicit SoaArrays(const Arrays& a)
      : n(a.out.size()), stride(planeStride(n)), matrix(10 * stride), motor(7 * stride), weights(4 * stride),
        out(10 * stride), joints(4 * stride),
        paletteAffine(12 * kJoints), paletteMotor(8 * kJoints) {
    for (size_t i = 0; i < n; ++i) {
      const MatrixVertex& m = a.matrix[i];
      const MotorVertex& p = a.motor[i];
      for (size_t c = 0; c < 3; ++c)
        matrix[c * stride + i] = m.p[c], matrix[(3 + c) * stride + i] = m.n[c], motor[c * stride + i] = p.p[c];
      for (size_t c = 0; c < 4; ++c)
        matrix[(6 + c) * stride + i] = m.t[c], motor[(3 + c) * stride + i] = p.r[c],
                                    weights[c * stride + i] = a.skin[i].w[c], joints[c * stride + i] = a.skin[i].j[c];
    }
    const Draw& d = draw();
    for (size_t j = 0; j < size_t(kJoints); ++j) {
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) paletteAffine[size_t(c * 3 + r) * kJoints + j] = d.joint[j][c][r];
      for (int k = 0; k < 4; ++k)
        paletteMotor[size_t(k) * kJoints + j] = d.jointMotor[j][0][k],
                     paletteMotor[size_t(4 + k) * kJoints + j] = d.jointMotor[j][1][k];
    }
  }
  simd::ConstPlanes in(const AlignedVector<float>& v) const { return {v.data(), stride}; }
  simd::Planes outPlanes() { return {out.data(), stride}; }
};

SoaArrays& soaArrays(Size s) {
  if (s == Size::InCache) {
    static SoaArrays small(arrays(s));
    return small;
  }
  static SoaArrays big(arrays(s));
  return big;
}

// One call of `kernel` per iteration over the whole batch.
template <class F> void runSimd(benchmark::State& state, Size s, size_t bytesPerItem, F kernel) {
  SoaArrays& a = soaArrays(s);
  timeSimdPass(state, a.out.data(), a.n, a.n * bytesPerItem, s, [&] { kernel(a); });
}

void frameSimdMatrix(benchmark::State& state, Size s) {
  float model[16], normal[16], m12[12], n9[9], mirror;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) model[c * 4 + r] = draw().model[c][r], normal[c * 4 + r] = draw().normal[c][r];
  simd::mat4ToAffine(model, normal, m12, n9, &mirror);
  runSimd(state, s, kFrameMatrixBytes, [&](SoaArrays& a) {
    simd::vertexFrameMatrix(m12, n9, mirror, a.in(a.matrix), a.outPlanes(), a.n);
  });
}

void frameSimdMotor(benchmark::State& state, Size s) {
  float m[8];
  for (int k = 0; k < 4; ++k) m[k] = draw().motor[0][k], m[4 + k] = draw().motor[1][k];
  runSimd(state, s, kFrameMotorBytes, [&](SoaArrays& a) {
    simd::vertexFrameMotor(m, draw().scale, a.in(a.motor), a.outPlanes(), a.n);
  });
}

// `fetch`: the palette in registers (skinned_vertex, the default) or gathered per component
// (skinned_vertex_gather), the same on both sides.
template <simd::PaletteFetchMode fetch> void skinSimdMatrix(benchmark::State& state, Size s) {
  runSimd(state, s, kSkinMatrixBytes, [&](SoaArrays& a) {
    simd::skinnedVertexMatrix({a.paletteAffine.data(), size_t(kJoints)}, draw().normal[3][3], a.in(a.matrix),
                              {a.joints.data(), a.stride}, a.in(a.weights), a.outPlanes(), a.n, fetch);
  });
}

template <simd::PaletteFetchMode fetch> void skinSimdMotor(benchmark::State& state, Size s) {
  runSimd(state, s, kSkinMotorBytes, [&](SoaArrays& a) {
    simd::skinnedVertexMotor({a.paletteMotor.data(), size_t(kJoints)}, draw().scale, a.in(a.motor),
                             {a.joints.data(), a.stride}, a.in(a.weights), a.outPlanes(), a.n, fetch);
  });
}

}  // namespace

void registerVertexBenchmarks() {
  using Fn = void (*)(benchmark::State&, Size);
  const struct {
    const char* name;
    Fn matrix, motor, glm, simdMatrix, simdMotor;  // simd: nullptr where kernels/simd has no such form
  } families[] = {{"vertex_frame", frameMatrix, frameMotor, frameGlm, frameSimdMatrix, frameSimdMotor},
                  {"skinned_vertex", skinMatrix<false>, skinMotor<false>, skinGlm<false>,
                   skinSimdMatrix<simd::PaletteFetchMode::InRegisters>, skinSimdMotor<simd::PaletteFetchMode::InRegisters>},
                  {"skinned_vertex_gather", nullptr, nullptr, nullptr, skinSimdMatrix<simd::PaletteFetchMode::Gathered>,
                   skinSimdMotor<simd::PaletteFetchMode::Gathered>},
                  {"skinned_vertex_reference", skinMatrix<true>, skinMotor<true>, skinGlm<true>, nullptr, nullptr}};
  for (const auto& f : families)
    for (Size s : {Size::InCache, Size::OutOfCache}) {
      const std::string prefix = std::string(f.name) + "/" + sizeName(s) + "/";
      const std::pair<const char*, Fn> sides[] = {
          {kMatrix, f.matrix}, {kMotor, f.motor}, {kGlm, f.glm}, {kSimdMatrix, f.simdMatrix}, {kSimdMotor, f.simdMotor}};
      for (const auto& [side, fn] : sides)
        if (fn) registerKernel(prefix + side, [s, fn = fn](benchmark::State& st) { fn(st, s); });
    }
}

}  // namespace mb::bench
