#include "harness/ops/shader_variants.h"

namespace mb::opsv {
namespace {

using D = std::vector<std::pair<std::string, std::string>>;

const std::string kMatrixMain =
    "main() divides the position by w and normalises normal and tangent for the varyings "
    "(motor.vs leaves normalisation to forward.fs, which normalises both anyway)";
const std::string kAffineMain =
    "main() normalises normal and tangent for the varyings, as matrix.vs (the position's w is 1: no divide)";
const std::string kCurvedMain =
    "main() adds the projection u_Projection * position (mat4 * vec4: 16 mul, 12 add), the same on both "
    "sides of a space";
const std::string kHandedness =
    "the exact fallback (pipelines/motor/linear_fallback.h); main() also takes the frame's handedness, "
    "motorHandedness (1 div, 1 sign), outside the counted kernel";
const std::string kTexels = "the 16 control points are texelFetch (no arithmetic)";
// Instanced draws (EXT_mesh_gpu_instancing, --instances): the rigid transform with its per-draw
// data read from per-instance attributes; the same arithmetic as the non-instanced variant.
const std::string kInstanced = "the per-draw transform read from per-instance attributes (divisor 1)";
// Morph targets (issue 37, morph.glsl): the ISA and SPIR-V of a morphing rigid vertex beside the
// rigid one, for matrix and the motor family's two methods. Two targets, as morph_torus.
const std::vector<std::pair<std::string, std::string>> kMorph = {{"MB_MORPH", ""}, {"MB_MORPH_TARGETS", "2"}};
const std::string kMorphSums =
    "morph.glsl's delta sums, per target with a non-zero weight 1 mul + 1 add per float of the target "
    "(storage-buffer reads by the vertex index), before the transform";

void matrixVariants(std::vector<ShaderVariant>& out) {
  const std::string ref = "the Sample Viewer's: skin, then u_ModelMatrix per vertex";
  const std::string world = "joint world * inverse bind; no model matrix per vertex";
  const std::string clip = "matrixWorldToClip";
  out.insert(out.end(), {
      {"matrix", "matrix.vs", {}, "rigid", {"matrixRigidVertex", clip}, kMatrixMain},
      {"matrix", "matrix.vs", {{"SKINNED", ""}}, "skinned", {"matrixSkinnedVertex", clip},
       kMatrixMain + "; = skinned, reference"},
      {"matrix", "matrix.vs", {{"SKINNED", ""}}, "skinned, reference", {"matrixSkinnedVertex", clip}, ref},
      {"matrix", "matrix.vs", D{{"SKINNED", ""}, {"MB_WORLD_PALETTE", ""}}, "skinned, world palette",
       {"matrixSkinnedVertexWorld", clip}, world},
      {"matrix", "matrix.vs", D{{"MB_NO_TANGENT", ""}}, "rigid, no tangent", {"matrixRigidVertexNoTangent", clip}},
      {"matrix", "matrix.vs", D{{"SKINNED", ""}, {"MB_NO_TANGENT", ""}}, "skinned, no tangent",
       {"matrixSkinnedVertexNoTangent", clip}, ref},
      {"matrix", "matrix.vs", D{{"SKINNED", ""}, {"MB_WORLD_PALETTE", ""}, {"MB_NO_TANGENT", ""}},
       "skinned, world palette, no tangent", {"matrixSkinnedVertexWorldNoTangent", clip}, world},
      {"matrix", "matrix_patch.vs", {}, "bezier patch", {"bezierPatch", "matrixPatchVertex", clip},
       kMatrixMain + "; " + kTexels},
      {"matrix", "matrix.vs", {{"MB_INSTANCED", ""}}, "rigid, instanced", {"matrixRigidVertex", clip},
       kMatrixMain + "; " + kInstanced},
      {"matrix", "matrix.vs", D{{"MB_INSTANCED", ""}, {"MB_NO_TANGENT", ""}}, "rigid, no tangent, instanced",
       {"matrixRigidVertexNoTangent", clip}, kInstanced},
      {"matrix", "matrix.vs", kMorph, "rigid, morph", {"matrixRigidVertex", clip}, kMatrixMain + "; " + kMorphSums},
  });
}

// affine, qtangent and hybrid share affine.vs; hybrid draws exactly as qtangent.
void affineVariants(std::vector<ShaderVariant>& out) {
  const std::string clip = "matrixWorldToClip";
  out.insert(out.end(), {
      {"affine", "affine.vs", {}, "rigid", {"matrixAffineVertex", clip}, kAffineMain},
      {"affine", "affine.vs", {{"MB_SKINNED", ""}}, "skinned", {"affineSkinnedVertex", clip}, kAffineMain},
      {"affine", "affine.vs", {{"MB_NO_TANGENT", ""}}, "rigid, no tangent", {"affineVertexNoTangent", clip},
       "8-float vertex (position, normal, uv) as matrix.vs's MB_NO_TANGENT"},
      {"affine", "affine.vs", D{{"MB_SKINNED", ""}, {"MB_NO_TANGENT", ""}}, "skinned, no tangent",
       {"affineSkinnedVertexNoTangent", clip}, "8-float vertex"},
      {"affine", "affine_patch.vs", {}, "bezier patch", {"bezierPatch", "affinePatchVertex", clip},
       kAffineMain + "; " + kTexels},
      {"affine", "affine.vs", {{"MB_INSTANCED", ""}}, "rigid, instanced", {"matrixAffineVertex", clip},
       kAffineMain + "; " + kInstanced},
      {"affine", "affine.vs", D{{"MB_INSTANCED", ""}, {"MB_NO_TANGENT", ""}}, "rigid, no tangent, instanced",
       {"affineVertexNoTangent", clip}, "8-float vertex; " + kInstanced},
  });
  for (const char* p : {"qtangent", "hybrid"}) {
    const std::string note = kAffineMain + (std::string(p) == "hybrid" ? "; the GPU side of qtangent" : "");
    out.insert(out.end(), {
        {p, "affine.vs", {{"MB_QTANGENT", ""}}, "rigid", {"qtangentRigidVertex", clip}, note},
        {p, "affine.vs", D{{"MB_QTANGENT", ""}, {"MB_SKINNED", ""}}, "skinned", {"qtangentSkinnedVertex", clip}, note},
        {p, "affine_patch.vs", {}, "bezier patch", {"bezierPatch", "affinePatchVertex", clip},
         note + "; a patch vertex stores no frame: affine_patch.vs, as affine; " + kTexels},
        {p, "affine.vs", D{{"MB_QTANGENT", ""}, {"MB_INSTANCED", ""}}, "rigid, instanced",
         {"qtangentRigidVertex", clip}, note + "; " + kInstanced},
    });
  }
}

// motor and motor_q share motor.vs and motor_patch.vs (motor_q differs in the vertex format).
void motorVariants(std::vector<ShaderVariant>& out) {
  const std::string clip = "motorWorldToClipConstants";
  for (const char* p : {"motor", "motor_q"}) {
    out.insert(out.end(), {
        {p, "motor.vs", {}, "rigid", {"motorRigidVertex", clip}},
        {p, "motor.vs", {{"MB_SKINNED", ""}}, "skinned", {"motorSkinnedVertex", clip}, "= skinned, world palette"},
        {p, "motor.vs", D{{"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}}, "skinned, reference",
         {"motorSkinnedVertexReference", clip}, "the paper's: gp(toWorld, blend) per vertex"},
        {p, "motor.vs", {{"MB_SKINNED", ""}}, "skinned, world palette", {"motorSkinnedVertex", clip},
         "joint world * inverse bind motors"},
        {p, "motor.vs", {{"MB_SCALE_FALLBACK", ""}}, "scaled fallback", {"motorScaledVertex", clip}},
        {p, "motor.vs", D{{"MB_SKINNED", ""}, {"MB_SCALE_FALLBACK", ""}}, "skinned+scaled",
         {"motorBlendJoints", "motorScaledVertex", clip}},
        {p, "motor_patch.vs", {}, "bezier patch", {"bezierPatch", "motorPatchVertex", clip}, kTexels},
        {p, "motor_patch.vs", {{"MB_SCALE_FALLBACK", ""}}, "bezier patch, scaled fallback",
         {"bezierPatch", "motorScaledPatchVertex", clip}, kTexels},
        {p, "motor.vs", {{"MB_INSTANCED", ""}}, "rigid, instanced", {"motorRigidVertex", clip}, kInstanced},
        {p, "motor.vs", D{{"MB_INSTANCED", ""}, {"MB_SCALE_FALLBACK", ""}}, "scaled fallback, instanced",
         {"motorScaledVertex", clip}, kInstanced},
        {p, "motor.vs", {{"MB_LINEAR_FALLBACK", ""}}, "linear fallback", {"motorLinearRotorVertex", clip},
         kHandedness},
        {p, "motor.vs", D{{"MB_SKINNED", ""}, {"MB_LINEAR_FALLBACK", ""}}, "skinned, linear fallback",
         {"motorBlendJoints", "motorBlendLinear", "motorBlendLinear", "motorLinearRotorVertex", clip},
         "joint world motors and linear parts; " + kHandedness},
    });
  }
  D rotor = kMorph;
  rotor.push_back({"MB_MORPH_ROTOR", ""});
  out.insert(out.end(), {
      {"motor", "motor.vs", kMorph, "rigid, morph frame (a)", {"morphRotorFrame", "motorRigidVertex", clip},
       kMorphSums + " (position, normal, tangent deltas: 9 floats)"},
      {"motor", "motor.vs", rotor, "rigid, morph rotor (b)", {"morphRotorBlend", "motorRigidVertex", clip},
       kMorphSums + " (position, rotor deltas: 7 floats)"},
  });
}

// matrix_c (affine.vs) and motor_c (motor.vs) with MB_COMPACT (issue 29): rigid draws fold the
// mesh's cube into their transform, skinned and instanced draws run compactPosition.
void compactVariants(std::vector<ShaderVariant>& out) {
  const std::string mclip = "matrixWorldToClip", pclip = "motorWorldToClipConstants";
  const std::string cube = "compactPosition";
  out.insert(out.end(), {
      {"matrix_c", "affine.vs", {{"MB_COMPACT", ""}}, "rigid", {"compactRigidVertex", mclip}, kAffineMain},
      {"matrix_c", "affine.vs", D{{"MB_COMPACT", ""}, {"MB_SKINNED", ""}}, "skinned", {"compactSkinnedVertex", mclip},
       kAffineMain},
      {"matrix_c", "affine_patch.vs", {}, "bezier patch", {"bezierPatch", "affinePatchVertex", mclip},
       kAffineMain + "; a patch vertex stores no frame: affine_patch.vs, as affine; " + kTexels},
      {"matrix_c", "affine.vs", D{{"MB_COMPACT", ""}, {"MB_INSTANCED", ""}}, "rigid, instanced",
       {cube, "compactRigidVertex", mclip}, kAffineMain + "; " + kInstanced},
      {"motor_c", "motor.vs", {{"MB_COMPACT", ""}}, "rigid", {"motorCompactVertex", pclip}},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_SKINNED", ""}}, "skinned",
       {"motorCompactSkinnedVertex", pclip}, "= skinned, world palette"},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}},
       "skinned, reference", {"motorCompactSkinnedVertexReference", pclip},
       "the paper's: gp(toWorld, blend) per vertex"},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_SCALE_FALLBACK", ""}}, "scaled fallback",
       {"motorCompactScaledVertex", pclip}},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_SKINNED", ""}, {"MB_SCALE_FALLBACK", ""}}, "skinned+scaled",
       {"motorBlendJoints", cube, "motorCompactScaledVertex", pclip}},
      {"motor_c", "motor_patch.vs", {}, "bezier patch", {"bezierPatch", "motorPatchVertex", pclip}, kTexels},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_SKINNED", ""}}, "skinned, world palette",
       {"motorCompactSkinnedVertex", pclip}, "joint world * inverse bind motors"},
      {"motor_c", "motor_patch.vs", {{"MB_SCALE_FALLBACK", ""}}, "bezier patch, scaled fallback",
       {"bezierPatch", "motorScaledPatchVertex", pclip}, kTexels},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_INSTANCED", ""}}, "rigid, instanced",
       {cube, "motorCompactVertex", pclip}, kInstanced},
      {"motor_c", "motor.vs", D{{"MB_COMPACT", ""}, {"MB_INSTANCED", ""}, {"MB_SCALE_FALLBACK", ""}},
       "scaled fallback, instanced", {cube, "motorCompactScaledVertex", pclip}, kInstanced},
  });
}

// motor_cf (issue 29): motor_c's bytes, the world tangent rotor as the varying (forward.fs
// unpacks it per fragment: frame_shading.glsl); the scale fallback extracts per vertex.
void fragmentRotorVariants(std::vector<ShaderVariant>& out) {
  const std::string pclip = "motorWorldToClipConstants", cube = "compactPosition";
  const std::string perFragment = "no frame extracted per vertex: forward.fs runs rotorShadingNormal per fragment";
  const D rotor = {{"MB_COMPACT", ""}, {"MB_SIGNED_ROTOR", ""}, {"MB_FRAGMENT_ROTOR", ""}};
  auto with = [](D d, std::initializer_list<std::pair<std::string, std::string>> more) {
    d.insert(d.end(), more);
    return d;
  };
  const D scaled = {{"MB_COMPACT", ""}, {"MB_SIGNED_ROTOR", ""}, {"MB_SCALE_FALLBACK", ""}};
  out.insert(out.end(), {
      {"motor_cf", "motor.vs", rotor, "rigid", {"motorCompactRotorVertex", pclip}, perFragment},
      {"motor_cf", "motor.vs", with(rotor, {{"MB_SKINNED", ""}}), "skinned", {"motorCompactRotorSkinnedVertex", pclip},
       "= skinned, world palette; " + perFragment},
      {"motor_cf", "motor.vs", with(rotor, {{"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}}), "skinned, reference",
       {"motorCompactRotorSkinnedVertexReference", pclip}, "the paper's: gp(toWorld, blend) per vertex"},
      {"motor_cf", "motor.vs", scaled, "scaled fallback", {"compactSignedRotor", "motorScaledRotorVertex", pclip},
       "a non-uniform scale is no rotation: normal and tangent per vertex, as motor_c"},
      {"motor_cf", "motor.vs", with(scaled, {{"MB_SKINNED", ""}}), "skinned+scaled",
       {"motorBlendJoints", cube, "compactSignedRotor", "motorScaledRotorVertex", pclip}},
      {"motor_cf", "motor_patch.vs", {}, "bezier patch", {"bezierPatch", "motorPatchVertex", pclip}, kTexels},
      {"motor_cf", "motor.vs", with(rotor, {{"MB_SKINNED", ""}}), "skinned, world palette",
       {"motorCompactRotorSkinnedVertex", pclip}, "joint world * inverse bind motors"},
      {"motor_cf", "motor_patch.vs", {{"MB_SCALE_FALLBACK", ""}}, "bezier patch, scaled fallback",
       {"bezierPatch", "motorScaledPatchVertex", pclip}, kTexels},
      {"motor_cf", "motor.vs", with(rotor, {{"MB_INSTANCED", ""}}), "rigid, instanced",
       {cube, "motorCompactRotorVertex", pclip}, kInstanced},
      {"motor_cf", "motor.vs", with(scaled, {{"MB_INSTANCED", ""}}), "scaled fallback, instanced",
       {cube, "compactSignedRotor", "motorScaledRotorVertex", pclip}, kInstanced},
  });
}

void curvedVariants(std::vector<ShaderVariant>& out) {
  out.insert(out.end(), {
      {"s3_matrix", "curved_matrix.vs", {{"MB_KAPPA", "1"}}, "S3 instance", {"curvedMatrixVertex"}, kCurvedMain},
      {"s3_motor", "curved_motor.vs", {{"MB_KAPPA", "1"}}, "S3 instance", {"curvedMotorVertex"}, kCurvedMain},
      {"h3_matrix", "curved_matrix.vs", {{"MB_KAPPA", "-1"}}, "H3 instance", {"curvedMatrixVertex"}, kCurvedMain},
      {"h3_motor", "curved_motor.vs", {{"MB_KAPPA", "-1"}}, "H3 instance", {"curvedMotorVertex"}, kCurvedMain},
  });
}

}  // namespace

std::vector<ShaderVariant> shaderVariants() {
  std::vector<ShaderVariant> out;
  matrixVariants(out);
  motorVariants(out);
  affineVariants(out);
  compactVariants(out);
  fragmentRotorVariants(out);
  curvedVariants(out);
  return out;
}

}  // namespace mb::opsv
