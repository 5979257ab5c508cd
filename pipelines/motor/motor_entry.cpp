// The registry entries of the motor family: motor and motor_q (motor.vs, motor_patch.vs; motor_q
// differs in the vertex format), motor_c and motor_cf (the 16-byte vertex, MB_COMPACT): their
// traits and the programs motor_pipeline.cpp's defines() links.
#include "pipelines/motor/motor_pipeline.h"

namespace mb {
namespace {

using namespace variant_notes;

constexpr const char* kCube = "compactPosition";
constexpr const char* kReference = "the paper's: gp(toWorld, blend) per vertex";
constexpr const char* kWorld = "joint world * inverse bind motors";
constexpr const char* kHandedness =
    "the exact fallback (pipelines/motor/linear_fallback.h); main() also takes the frame's handedness, "
    "motorHandedness (1 div, 1 sign), outside the counted kernel";

constexpr const char *kVs = "motor.vs", *kClip = "motorWorldToClipConstants";

// The patch programs every motor vertex shares (a patch vertex stores no frame).
ShaderVariant patchProgram() {
  return {.stage = "motor_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "motorPatchVertex"},
          .note = kTexels};
}

ShaderVariant scaledPatchProgram() {
  return {.stage = "motor_patch.vs", .defines = defines("MB_SCALE_FALLBACK"), .draws = "bezier patch, scaled fallback",
          .kernels = {"bezierPatch", "motorScaledPatchVertex"}, .note = kTexels};
}

// The programs of the float and int16 rotor vertices (motor, motor_q).
std::vector<ShaderVariant> rotorVariants() {
  return {
      {.draws = "rigid", .kernels = {"motorRigidVertex"}},
      {.defines = defines("MB_SKINNED"), .draws = "skinned", .kernels = {"motorSkinnedVertex"},
       .note = "= skinned, world palette"},
      {.defines = defines("MB_SKINNED MB_SKIN_REFERENCE"), .draws = "skinned, reference",
       .kernels = {"motorSkinnedVertexReference"}, .note = kReference},
      {.defines = defines("MB_SKINNED"), .draws = "skinned, world palette", .kernels = {"motorSkinnedVertex"},
       .note = kWorld},
      {.defines = defines("MB_SCALE_FALLBACK"), .draws = "scaled fallback", .kernels = {"motorScaledVertex"}},
      {.defines = defines("MB_SKINNED MB_SCALE_FALLBACK"), .draws = "skinned+scaled",
       .kernels = {"motorBlendJoints", "motorScaledVertex"}},
      patchProgram(),
      scaledPatchProgram(),
      {.defines = defines("MB_INSTANCED"), .draws = "rigid, instanced", .kernels = {"motorRigidVertex"},
       .note = kInstanced},
      {.defines = defines("MB_INSTANCED MB_SCALE_FALLBACK"), .draws = "scaled fallback, instanced",
       .kernels = {"motorScaledVertex"}, .note = kInstanced},
      {.defines = defines("MB_LINEAR_FALLBACK"), .draws = "linear fallback", .kernels = {"motorLinearRotorVertex"},
       .note = kHandedness},
      {.defines = defines("MB_SKINNED MB_LINEAR_FALLBACK"), .draws = "skinned, linear fallback",
       .kernels = {"motorBlendJoints", "motorBlendLinear", "motorBlendLinear", "motorLinearRotorVertex"},
       .note = std::string("joint world motors and linear parts; ") + kHandedness},
  };
}

}  // namespace

// The morph variants are motor's: its two methods, (a) frame and (b) rotor deltas.
PipelineEntry motorEntry() {
  std::vector<ShaderVariant> variants = rotorVariants();
  variants.push_back({.defines = defines(kMorph), .draws = "rigid, morph frame (a)",
                      .kernels = {"morphRotorFrame", "motorRigidVertex"},
                      .note = std::string(kMorphSums) + " (position, normal, tangent deltas: 9 floats)"});
  variants.push_back({.defines = defines(std::string(kMorph) + " MB_MORPH_ROTOR"), .draws = "rigid, morph rotor (b)",
                      .kernels = {"morphRotorBlend", "motorRigidVertex"},
                      .note = std::string(kMorphSums) + " (position, rotor deltas: 7 floats)"});
  return {.name = "motor", .make = [] { return makeMotorPipeline({}); }, .skin = SkinMethod::MotorBlend,
          .family = PipelineFamily::Motor, .vertexBytes = 36, .frame = {.fetched = "float frame"},
          .variants = programs(kVs, kClip, std::move(variants))};
}

PipelineEntry motorQEntry() {
  auto make = [] { return makeMotorPipeline({.name = "motor_q", .quantizedFrame = true}); };
  return {.name = "motor_q", .make = make, .skin = SkinMethod::MotorBlend, .family = PipelineFamily::Motor,
          .vertexBytes = 28, .frame = {.fetched = "SNORM16: the vertex fetch"},
          .variants = programs(kVs, kClip, rotorVariants())};
}

// Rigid draws fold the mesh's cube into their transform, skinned and instanced draws run
// compactPosition.
PipelineEntry motorCEntry() {
  std::vector<ShaderVariant> v = {
      {.defines = defines("MB_COMPACT"), .draws = "rigid", .kernels = {"motorCompactVertex"}},
      {.defines = defines("MB_COMPACT MB_SKINNED"), .draws = "skinned", .kernels = {"motorCompactSkinnedVertex"},
       .note = "= skinned, world palette"},
      {.defines = defines("MB_COMPACT MB_SKINNED MB_SKIN_REFERENCE"), .draws = "skinned, reference",
       .kernels = {"motorCompactSkinnedVertexReference"}, .note = kReference},
      {.defines = defines("MB_COMPACT MB_SCALE_FALLBACK"), .draws = "scaled fallback",
       .kernels = {"motorCompactScaledVertex"}},
      {.defines = defines("MB_COMPACT MB_SKINNED MB_SCALE_FALLBACK"), .draws = "skinned+scaled",
       .kernels = {"motorBlendJoints", kCube, "motorCompactScaledVertex"}},
      patchProgram(),
      {.defines = defines("MB_COMPACT MB_SKINNED"), .draws = "skinned, world palette",
       .kernels = {"motorCompactSkinnedVertex"}, .note = kWorld},
      scaledPatchProgram(),
      {.defines = defines("MB_COMPACT MB_INSTANCED"), .draws = "rigid, instanced",
       .kernels = {kCube, "motorCompactVertex"}, .note = kInstanced},
      {.defines = defines("MB_COMPACT MB_INSTANCED MB_SCALE_FALLBACK"), .draws = "scaled fallback, instanced",
       .kernels = {kCube, "motorCompactScaledVertex"}, .note = kInstanced},
  };
  auto make = [] { return makeMotorPipeline({.name = "motor_c", .compact = true}); };
  return {.name = "motor_c", .make = make, .skin = SkinMethod::MotorBlend, .family = PipelineFamily::Motor,
          .vertexBytes = 16, .frame = {.decodeKernel = "compactRotor"}, .variants = programs(kVs, kClip, std::move(v))};
}

// motor_c's bytes, the world tangent rotor as the varying (forward.fs unpacks it per fragment:
// frame_shading.glsl); the scale fallback extracts per vertex.
PipelineEntry motorCFEntry() {
  const std::string perFragment = "no frame extracted per vertex: forward.fs runs rotorShadingNormal per fragment";
  const std::string rotor = "MB_COMPACT MB_SIGNED_ROTOR MB_FRAGMENT_ROTOR";
  const std::string scaled = "MB_COMPACT MB_SIGNED_ROTOR MB_SCALE_FALLBACK";
  std::vector<ShaderVariant> v = {
      {.defines = defines(rotor), .draws = "rigid", .kernels = {"motorCompactRotorVertex"}, .note = perFragment},
      {.defines = defines(rotor + " MB_SKINNED"), .draws = "skinned", .kernels = {"motorCompactRotorSkinnedVertex"},
       .note = "= skinned, world palette; " + perFragment},
      {.defines = defines(rotor + " MB_SKINNED MB_SKIN_REFERENCE"), .draws = "skinned, reference",
       .kernels = {"motorCompactRotorSkinnedVertexReference"}, .note = kReference},
      {.defines = defines(scaled), .draws = "scaled fallback",
       .kernels = {"compactSignedRotor", "motorScaledRotorVertex"},
       .note = "a non-uniform scale is no rotation: normal and tangent per vertex, as motor_c"},
      {.defines = defines(scaled + " MB_SKINNED"), .draws = "skinned+scaled",
       .kernels = {"motorBlendJoints", kCube, "compactSignedRotor", "motorScaledRotorVertex"}},
      patchProgram(),
      {.defines = defines(rotor + " MB_SKINNED"), .draws = "skinned, world palette",
       .kernels = {"motorCompactRotorSkinnedVertex"}, .note = kWorld},
      scaledPatchProgram(),
      {.defines = defines(rotor + " MB_INSTANCED"), .draws = "rigid, instanced",
       .kernels = {kCube, "motorCompactRotorVertex"}, .note = kInstanced},
      {.defines = defines(scaled + " MB_INSTANCED"), .draws = "scaled fallback, instanced",
       .kernels = {kCube, "compactSignedRotor", "motorScaledRotorVertex"}, .note = kInstanced},
  };
  auto make = [] { return makeMotorPipeline({.name = "motor_cf", .compact = true, .fragmentRotor = true}); };
  return {.name = "motor_cf", .make = make, .skin = SkinMethod::MotorBlend, .family = PipelineFamily::Motor,
          .vertexBytes = 16, .frame = {.decodeKernel = "compactSignedRotor", .perFragment = true},
          .variants = programs(kVs, kClip, std::move(v))};
}

}  // namespace mb
