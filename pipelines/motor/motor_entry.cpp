// The registry entries of the motor family: motor and motor_q (motor.vs, motor_patch.vs; motor_q
// differs in the vertex format), motor_c and motor_cf (the 16-byte vertex, MB_COMPACT): their
// traits and the programs motor_pipeline.cpp's defines() links.
#include "pipelines/motor/motor_pipeline.h"

namespace mb {
namespace {

using namespace variant_notes;
using Defines = std::vector<std::pair<std::string, std::string>>;

constexpr const char *kClip = "motorWorldToClipConstants", *kVs = "motor.vs", *kPatch = "motor_patch.vs";
constexpr const char* kCube = "compactPosition";
constexpr const char* kReference = "the paper's: gp(toWorld, blend) per vertex";
constexpr const char* kWorld = "joint world * inverse bind motors";
constexpr const char* kHandedness =
    "the exact fallback (pipelines/motor/linear_fallback.h); main() also takes the frame's handedness, "
    "motorHandedness (1 div, 1 sign), outside the counted kernel";

Defines with(Defines d, const Defines& more) {
  d.insert(d.end(), more.begin(), more.end());
  return d;
}

PipelineEntry motorFamilyEntry(const char* name, std::unique_ptr<Pipeline> (*make)(), int vertexBytes,
                               FrameEncoding frame, std::vector<ShaderVariant> variants) {
  return {.name = name, .make = make, .space = Space::Euclidean, .skin = SkinMethod::MotorBlend,
          .family = PipelineFamily::Motor, .vertexBytes = vertexBytes, .frame = std::move(frame),
          .variants = std::move(variants)};
}

// The patch programs every motor vertex shares (a patch vertex stores no frame).
std::vector<ShaderVariant> patchVariants() {
  return {
      {.stage = kPatch, .draws = "bezier patch", .kernels = {"bezierPatch", "motorPatchVertex", kClip}, .note = kTexels},
      {.stage = kPatch, .defines = {{"MB_SCALE_FALLBACK", ""}}, .draws = "bezier patch, scaled fallback",
       .kernels = {"bezierPatch", "motorScaledPatchVertex", kClip}, .note = kTexels},
  };
}

// The programs of the float and int16 rotor vertices (motor, motor_q).
std::vector<ShaderVariant> rotorVariants() {
  std::vector<ShaderVariant> v = {
      {.stage = kVs, .draws = "rigid", .kernels = {"motorRigidVertex", kClip}},
      {.stage = kVs, .defines = {{"MB_SKINNED", ""}}, .draws = "skinned", .kernels = {"motorSkinnedVertex", kClip},
       .note = "= skinned, world palette"},
      {.stage = kVs, .defines = {{"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}}, .draws = "skinned, reference",
       .kernels = {"motorSkinnedVertexReference", kClip}, .note = kReference},
      {.stage = kVs, .defines = {{"MB_SKINNED", ""}}, .draws = "skinned, world palette",
       .kernels = {"motorSkinnedVertex", kClip}, .note = kWorld},
      {.stage = kVs, .defines = {{"MB_SCALE_FALLBACK", ""}}, .draws = "scaled fallback",
       .kernels = {"motorScaledVertex", kClip}},
      {.stage = kVs, .defines = {{"MB_SKINNED", ""}, {"MB_SCALE_FALLBACK", ""}}, .draws = "skinned+scaled",
       .kernels = {"motorBlendJoints", "motorScaledVertex", kClip}},
  };
  for (const ShaderVariant& p : patchVariants()) v.push_back(p);
  v.insert(v.end(), {
      {.stage = kVs, .defines = {{"MB_INSTANCED", ""}}, .draws = "rigid, instanced",
       .kernels = {"motorRigidVertex", kClip}, .note = kInstanced},
      {.stage = kVs, .defines = {{"MB_INSTANCED", ""}, {"MB_SCALE_FALLBACK", ""}}, .draws = "scaled fallback, instanced",
       .kernels = {"motorScaledVertex", kClip}, .note = kInstanced},
      {.stage = kVs, .defines = {{"MB_LINEAR_FALLBACK", ""}}, .draws = "linear fallback",
       .kernels = {"motorLinearRotorVertex", kClip}, .note = kHandedness},
      {.stage = kVs, .defines = {{"MB_SKINNED", ""}, {"MB_LINEAR_FALLBACK", ""}}, .draws = "skinned, linear fallback",
       .kernels = {"motorBlendJoints", "motorBlendLinear", "motorBlendLinear", "motorLinearRotorVertex", kClip},
       .note = std::string("joint world motors and linear parts; ") + kHandedness},
  });
  return v;
}

}  // namespace

// The morph variants are motor's: its two methods, (a) frame and (b) rotor deltas.
PipelineEntry motorEntry() {
  std::vector<ShaderVariant> variants = rotorVariants();
  variants.push_back({.stage = kVs, .defines = morphDefines(), .draws = "rigid, morph frame (a)",
                      .kernels = {"morphRotorFrame", "motorRigidVertex", kClip},
                      .note = std::string(kMorphSums) + " (position, normal, tangent deltas: 9 floats)"});
  variants.push_back({.stage = kVs, .defines = with(morphDefines(), {{"MB_MORPH_ROTOR", ""}}), .draws = "rigid, morph rotor (b)",
                      .kernels = {"morphRotorBlend", "motorRigidVertex", kClip},
                      .note = std::string(kMorphSums) + " (position, rotor deltas: 7 floats)"});
  return motorFamilyEntry("motor", [] { return makeMotorPipeline({}); }, 36, {.fetched = "float frame"},
                          std::move(variants));
}

PipelineEntry motorQEntry() {
  return motorFamilyEntry("motor_q", [] { return makeMotorPipeline({.name = "motor_q", .quantizedFrame = true}); },
                          28, {.fetched = "SNORM16: the vertex fetch"}, rotorVariants());
}

// Rigid draws fold the mesh's cube into their transform, skinned and instanced draws run
// compactPosition.
PipelineEntry motorCEntry() {
  const Defines c = {{"MB_COMPACT", ""}};
  std::vector<ShaderVariant> v = {
      {.stage = kVs, .defines = c, .draws = "rigid", .kernels = {"motorCompactVertex", kClip}},
      {.stage = kVs, .defines = with(c, {{"MB_SKINNED", ""}}), .draws = "skinned",
       .kernels = {"motorCompactSkinnedVertex", kClip}, .note = "= skinned, world palette"},
      {.stage = kVs, .defines = with(c, {{"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}}), .draws = "skinned, reference",
       .kernels = {"motorCompactSkinnedVertexReference", kClip}, .note = kReference},
      {.stage = kVs, .defines = with(c, {{"MB_SCALE_FALLBACK", ""}}), .draws = "scaled fallback",
       .kernels = {"motorCompactScaledVertex", kClip}},
      {.stage = kVs, .defines = with(c, {{"MB_SKINNED", ""}, {"MB_SCALE_FALLBACK", ""}}), .draws = "skinned+scaled",
       .kernels = {"motorBlendJoints", kCube, "motorCompactScaledVertex", kClip}},
      patchVariants()[0],
      {.stage = kVs, .defines = with(c, {{"MB_SKINNED", ""}}), .draws = "skinned, world palette",
       .kernels = {"motorCompactSkinnedVertex", kClip}, .note = kWorld},
      patchVariants()[1],
      {.stage = kVs, .defines = with(c, {{"MB_INSTANCED", ""}}), .draws = "rigid, instanced",
       .kernels = {kCube, "motorCompactVertex", kClip}, .note = kInstanced},
      {.stage = kVs, .defines = with(c, {{"MB_INSTANCED", ""}, {"MB_SCALE_FALLBACK", ""}}),
       .draws = "scaled fallback, instanced", .kernels = {kCube, "motorCompactScaledVertex", kClip}, .note = kInstanced},
  };
  return motorFamilyEntry("motor_c", [] { return makeMotorPipeline({.name = "motor_c", .compact = true}); }, 16,
                          {.decodeKernel = "compactRotor"}, std::move(v));
}

// motor_c's bytes, the world tangent rotor as the varying (forward.fs unpacks it per fragment:
// frame_shading.glsl); the scale fallback extracts per vertex.
PipelineEntry motorCFEntry() {
  const std::string perFragment = "no frame extracted per vertex: forward.fs runs rotorShadingNormal per fragment";
  const Defines rotor = {{"MB_COMPACT", ""}, {"MB_SIGNED_ROTOR", ""}, {"MB_FRAGMENT_ROTOR", ""}};
  const Defines scaled = {{"MB_COMPACT", ""}, {"MB_SIGNED_ROTOR", ""}, {"MB_SCALE_FALLBACK", ""}};
  std::vector<ShaderVariant> v = {
      {.stage = kVs, .defines = rotor, .draws = "rigid", .kernels = {"motorCompactRotorVertex", kClip},
       .note = perFragment},
      {.stage = kVs, .defines = with(rotor, {{"MB_SKINNED", ""}}), .draws = "skinned",
       .kernels = {"motorCompactRotorSkinnedVertex", kClip}, .note = "= skinned, world palette; " + perFragment},
      {.stage = kVs, .defines = with(rotor, {{"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}}),
       .draws = "skinned, reference", .kernels = {"motorCompactRotorSkinnedVertexReference", kClip},
       .note = kReference},
      {.stage = kVs, .defines = scaled, .draws = "scaled fallback",
       .kernels = {"compactSignedRotor", "motorScaledRotorVertex", kClip},
       .note = "a non-uniform scale is no rotation: normal and tangent per vertex, as motor_c"},
      {.stage = kVs, .defines = with(scaled, {{"MB_SKINNED", ""}}), .draws = "skinned+scaled",
       .kernels = {"motorBlendJoints", kCube, "compactSignedRotor", "motorScaledRotorVertex", kClip}},
      patchVariants()[0],
      {.stage = kVs, .defines = with(rotor, {{"MB_SKINNED", ""}}), .draws = "skinned, world palette",
       .kernels = {"motorCompactRotorSkinnedVertex", kClip}, .note = kWorld},
      patchVariants()[1],
      {.stage = kVs, .defines = with(rotor, {{"MB_INSTANCED", ""}}), .draws = "rigid, instanced",
       .kernels = {kCube, "motorCompactRotorVertex", kClip}, .note = kInstanced},
      {.stage = kVs, .defines = with(scaled, {{"MB_INSTANCED", ""}}), .draws = "scaled fallback, instanced",
       .kernels = {kCube, "compactSignedRotor", "motorScaledRotorVertex", kClip}, .note = kInstanced},
  };
  auto make = [] { return makeMotorPipeline({.name = "motor_cf", .compact = true, .fragmentRotor = true}); };
  return motorFamilyEntry("motor_cf", make, 16,
                          {.decodeKernel = "compactSignedRotor", .perFragment = true}, std::move(v));
}

}  // namespace mb
