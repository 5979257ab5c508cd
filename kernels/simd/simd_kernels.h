// Batch CPU kernels hand-vectorised with Google Highway (runtime dispatch: the best target the
// CPU has among those compiled, SSSE3/SSE4/AVX2/AVX-512; simd_targets.h lists and forces them).
// Every kernel computes the same math as a shader function of shaders/*.glsl (named at each
// function; tests/simd checks them against the shim-compiled functions), over
// structure-of-arrays batches: component c of item i is at `planes.base[c * stride + i]`.
//
// Fairness between the matrix and the motor kernel of a pair (one comment per pair below says
// what is shared): the same planar layout, the same loop (one full vector per step, a one-lane
// tail), the same software prefetch of every input plane, the same per-draw uniforms broadcast
// once before the loop, fused multiply-add wherever the math has a product plus a sum, and the
// same palette fetch for joint palettes (held in registers and permuted where the palette fits
// in four vectors per component, else one GatherIndex per component), and the same store
// rule: non-temporal (streaming) stores when a call writes >= 64 MiB to planes aligned to 64
// bytes (no write-allocate read of the lines it overwrites), ordinary stores otherwise.
#pragma once
#include <cstddef>
#include <cstdint>

namespace mb::simd {

// `components` planes of `stride` floats each (stride >= the item count).
struct Planes {
  float* base = nullptr;
  size_t stride = 0;
  float* operator[](size_t c) const { return base + c * stride; }
};
struct ConstPlanes {
  const float* base = nullptr;
  size_t stride = 0;
  ConstPlanes() = default;
  ConstPlanes(const float* b, size_t s) : base(b), stride(s) {}
  ConstPlanes(Planes p) : base(p.base), stride(p.stride) {}  // NOLINT: a read view
  const float* operator[](size_t c) const { return base + c * stride; }
};
// Four joint-index planes (uint16, as the pipelines upload JOINTS_0).
struct JointPlanes {
  const uint16_t* base = nullptr;
  size_t stride = 0;
  const uint16_t* operator[](size_t c) const { return base + c * stride; }
};

// Uniform layouts (column-major like GLSL): mat4 16 floats; mat4x3 (affine, 4 columns of 3
// rows) 12 floats; mat3 9 floats; motor 8 floats [s, e23, e31, e12, e01, e02, e03, e0123].

// ---- point and direction (pair: 3 planes in, 3 planes out) ---------------------------------
// Matrix: xyz of matrixTransformPoint / matrixTransformDirection (matrix_transform.glsl) for an
// affine `model` (its last row (0, 0, 0, 1) is not read: 9 multiply-adds per item).
// Motor: sw_mp / sw_md of pga.glsl, `motor` normalised.
void pointsMatrix(const float model[16], ConstPlanes in, Planes out, size_t n);
void pointsMotor(const float motor[8], ConstPlanes in, Planes out, size_t n);
void directionsMatrix(const float model[16], ConstPlanes in, Planes out, size_t n);
void directionsMotor(const float motor[8], ConstPlanes in, Planes out, size_t n);

// ---- vertex frame (pair: the output is 10 planes, position xyz, normal xyz, tangent xyzw) ---
// Matrix: matrixAffineVertex (matrix_transform.glsl): `model` mat4x3, `normal` mat3, `mirror`
// = sign(det(model)); in: position xyz, normal xyz, tangent xyzw (10 planes). For an affine
// model it also equals xyz of matrixRigidVertex with the mat4 model and normal matrix (whose
// [3][3] is the mirror): mat4ToAffine below gives the arguments.
// Motor: motorRigidVertex (motor_transform.glsl): unit `motor`, uniform `scale` > 0; in:
// position xyz, tangent rotor (s, e23, e31, e12) (7 planes).
void vertexFrameMatrix(const float model[12], const float normal[9], float mirror, ConstPlanes in,
                       Planes out, size_t n);
void vertexFrameMotor(const float motor[8], float scale, ConstPlanes in, Planes out, size_t n);
// mat4 model + mat4 normal matrix -> mat4x3 model, mat3 normal matrix, mirror ([3][3]).
void mat4ToAffine(const float model[16], const float normal[16], float model12[12], float normal9[9],
                  float* mirror);

// ---- skinned vertex, 4 joints, world-space palette (output as vertex frame) ---------------
// Matrix: affineSkinnedVertex (affine_transform.glsl): linear blend of four mat4x3 joints,
// normal through the cofactor of the blended linear part; `palette`: 12 planes of `joints`
// floats (component c of joint j at palette[c][j]).
// Motor: motorSkinnedVertex (motor_transform.glsl): blend of four joint motors with the
// hemisphere rule, normalize_m, motorRigidVertex; `palette`: 8 planes.
// Both: `joints` 4 planes of indices < the palette size, `weights` 4 planes summing to 1.
// `fetch`: how each lane's palette entry is read, the same on both sides. InRegisters (the
// default, the faster: kernels/simd/README.md) holds a palette of at most four vectors per
// component in registers and permutes lanes, gathering larger palettes; Gathered always gathers
// (one GatherIndex per component and joint slot), kept to measure the two side by side.
enum class PaletteFetchMode { InRegisters, Gathered };
void skinnedVertexMatrix(ConstPlanes palette, float mirror, ConstPlanes in, JointPlanes joints,
                         ConstPlanes weights, Planes out, size_t n,
                         PaletteFetchMode fetch = PaletteFetchMode::InRegisters);
void skinnedVertexMotor(ConstPlanes palette, float scale, ConstPlanes in, JointPlanes joints,
                        ConstPlanes weights, Planes out, size_t n,
                        PaletteFetchMode fetch = PaletteFetchMode::InRegisters);

// ---- compose: out[i] = a[i] b[i] ----------------------------------------------------------
// mat4: matrixCompose (16 planes each). Affine: the same product for mat4x3 operands (12 planes
// each; equals matrixCompose's first three rows when both last rows are (0, 0, 0, 1)).
// Motor: gp_mm of pga.glsl (8 planes each).
void composeMat4(ConstPlanes a, ConstPlanes b, Planes out, size_t n);
void composeAffine(ConstPlanes a, ConstPlanes b, Planes out, size_t n);
void composeMotor(ConstPlanes a, ConstPlanes b, Planes out, size_t n);

// ---- skin palette: out[j] = world[node[j]] inverseBind[j] ---------------------------------
// Both operands as the pipelines hold them: `world` as hierarchyAffine / hierarchyMotor write it
// (kHierarchyAffineFloats / kHierarchyMotorFloats per node, AoS), indexed by `node` (n indices),
// and the inverse binds AoS. One 4-lane product per joint on both sides (simd_hierarchy.cpp).
// Affine: matrixCompose (matrix_transform.glsl) with `inverseBind` n column-major mat4s
// (glTF's inverseBindMatrices, affine: their last row is not read); out n mat4s (16 floats).
// Motor: gp_mm (pga.glsl) of the world's motor (its scale not applied) and `inverseBind` n
// motors (8 floats); out n motors.
void paletteAffine(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n);
void paletteMotor(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n);

// ---- hierarchy update: world = parent world * local, parents first -----------------------
// Nodes in parents-first order (parent[k] < k; -1: a root), n of them. The nodes are walked in
// groups of one full vector: the group's local transforms computed together (structure of
// arrays), then each node's product with its parent's world on 4-lane vectors (ozz-animation's
// local-to-model job; simd_hierarchy.cpp). Wide and deep (chain) hierarchies alike.
// `trs`: 8 planes, quaternion x, y, z, w (unit), translation xyz, uniform scale.
// Affine: local = T R S (the bench's trsMatrix), world = matrixCompose(parent, local) as a mat4:
// 16 floats per node (column-major, last row 0 0 0 1).
// Motor: local = gp_tr(T, R) with the parent's uniform scale applied to its e0 half, world =
// gp_mm(parent, local), world scale = parent scale * scale: 12 floats per node (the motor's 8,
// the scale, 3 unused).
inline constexpr size_t kHierarchyAffineFloats = 16, kHierarchyMotorFloats = 12;
void hierarchyAffine(ConstPlanes trs, const int32_t* parent, size_t n, float* world);
void hierarchyMotor(ConstPlanes trs, const int32_t* parent, size_t n, float* world);

}  // namespace mb::simd
