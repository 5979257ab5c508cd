// The registry entries of affine, qtangent and matrix_c: their traits and the programs
// affine.vs and affine_patch.vs are linked as (affine_pipeline.cpp's defines()).
#include "pipelines/matrix/affine_pipeline.h"

namespace mb {
namespace {

using namespace variant_notes;

constexpr const char* kClip = "matrixWorldToClip";
constexpr const char* kMain =
    "main() normalises normal and tangent for the varyings, as matrix.vs (the position's w is 1: no divide)";

std::string patchNoFrame() {
  return std::string("; a patch vertex stores no frame: affine_patch.vs, as affine; ") + kTexels;
}

PipelineEntry matrixFamilyEntry(const char* name, std::unique_ptr<Pipeline> (*make)(), int vertexBytes,
                                FrameEncoding frame, std::vector<ShaderVariant> variants) {
  return {.name = name, .make = make, .space = Space::Euclidean, .skin = SkinMethod::LinearBlend,
          .family = PipelineFamily::Matrix, .vertexBytes = vertexBytes, .frame = std::move(frame),
          .variants = std::move(variants)};
}

}  // namespace

PipelineEntry affineEntry() {
  const std::string vs = "affine.vs";
  return matrixFamilyEntry(
      "affine", [] { return affine::makePipeline("affine", affine::FrameFormat::Float); }, 48,
      {.fetched = "float frame"},
      {
          {.stage = vs, .draws = "rigid", .kernels = {"matrixAffineVertex", kClip}, .note = kMain},
          {.stage = vs, .defines = {{"MB_SKINNED", ""}}, .draws = "skinned", .kernels = {"affineSkinnedVertex", kClip},
           .note = kMain},
          {.stage = vs, .defines = {{"MB_NO_TANGENT", ""}}, .draws = "rigid, no tangent",
           .kernels = {"affineVertexNoTangent", kClip},
           .note = "8-float vertex (position, normal, uv) as matrix.vs's MB_NO_TANGENT"},
          {.stage = vs, .defines = {{"MB_SKINNED", ""}, {"MB_NO_TANGENT", ""}}, .draws = "skinned, no tangent",
           .kernels = {"affineSkinnedVertexNoTangent", kClip}, .note = "8-float vertex"},
          {.stage = "affine_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "affinePatchVertex", kClip},
           .note = std::string(kMain) + "; " + kTexels},
          {.stage = vs, .defines = {{"MB_INSTANCED", ""}}, .draws = "rigid, instanced",
           .kernels = {"matrixAffineVertex", kClip}, .note = std::string(kMain) + "; " + kInstanced},
          {.stage = vs, .defines = {{"MB_INSTANCED", ""}, {"MB_NO_TANGENT", ""}}, .draws = "rigid, no tangent, instanced",
           .kernels = {"affineVertexNoTangent", kClip}, .note = std::string("8-float vertex; ") + kInstanced},
      });
}

std::vector<ShaderVariant> affine::qtangentVariants(const std::string& also) {
  const std::string vs = "affine.vs", note = kMain + also;
  return {
      {.stage = vs, .defines = {{"MB_QTANGENT", ""}}, .draws = "rigid", .kernels = {"qtangentRigidVertex", kClip},
       .note = note},
      {.stage = vs, .defines = {{"MB_QTANGENT", ""}, {"MB_SKINNED", ""}}, .draws = "skinned",
       .kernels = {"qtangentSkinnedVertex", kClip}, .note = note},
      {.stage = "affine_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "affinePatchVertex", kClip},
       .note = note + patchNoFrame()},
      {.stage = vs, .defines = {{"MB_QTANGENT", ""}, {"MB_INSTANCED", ""}}, .draws = "rigid, instanced",
       .kernels = {"qtangentRigidVertex", kClip}, .note = note + "; " + kInstanced},
  };
}

PipelineEntry qtangentEntry() {
  return matrixFamilyEntry(
      "qtangent", [] { return affine::makePipeline("qtangent", affine::FrameFormat::QTangent); }, 28,
      {.decodeKernel = "qtangentFrame"}, affine::qtangentVariants(""));
}

// The 16-byte vertex (pipelines/compact): rigid draws fold the mesh's cube into their transform,
// skinned and instanced draws run compactPosition.
PipelineEntry matrixCEntry() {
  const std::string vs = "affine.vs";
  return matrixFamilyEntry(
      "matrix_c", [] { return affine::makePipeline("matrix_c", affine::FrameFormat::Compact); }, 16,
      {.decodeKernel = "compactMatrixFrame"},
      {
          {.stage = vs, .defines = {{"MB_COMPACT", ""}}, .draws = "rigid", .kernels = {"compactRigidVertex", kClip},
           .note = kMain},
          {.stage = vs, .defines = {{"MB_COMPACT", ""}, {"MB_SKINNED", ""}}, .draws = "skinned",
           .kernels = {"compactSkinnedVertex", kClip}, .note = kMain},
          {.stage = "affine_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "affinePatchVertex", kClip},
           .note = kMain + patchNoFrame()},
          {.stage = vs, .defines = {{"MB_COMPACT", ""}, {"MB_INSTANCED", ""}}, .draws = "rigid, instanced",
           .kernels = {"compactPosition", "compactRigidVertex", kClip}, .note = std::string(kMain) + "; " + kInstanced},
      });
}

}  // namespace mb
