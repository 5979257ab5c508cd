// The registry entries of affine, qtangent and matrix_c: their traits and the programs
// affine.vs and affine_patch.vs are linked as (affine_pipeline.cpp's defines()).
#include "pipelines/matrix/affine_pipeline.h"

namespace mb {
namespace {

using namespace variant_notes;

constexpr const char* kMain =
    "main() normalises normal and tangent for the varyings, as matrix.vs (the position's w is 1: no divide)";
constexpr const char* kNoFrame = "; a patch vertex stores no frame: affine_patch.vs, as affine";

constexpr const char *kVs = "affine.vs", *kClip = "matrixWorldToClip";

// The Bezier patch program: `note`, then what its control points cost.
ShaderVariant patchProgram(const std::string& note) {
  return {.stage = "affine_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "affinePatchVertex"},
          .note = note + "; " + kTexels};
}

}  // namespace

PipelineEntry affineEntry() {
  return {.name = "affine", .make = [] { return affine::makePipeline("affine", affine::FrameFormat::Float); },
          .skin = SkinMethod::LinearBlend, .family = PipelineFamily::Matrix, .vertexBytes = 48,
          .frame = {.fetched = "float frame"},
          .variants = programs(kVs, kClip, {
              {.draws = "rigid", .kernels = {"matrixAffineVertex"}, .note = kMain},
              {.defines = defines("MB_SKINNED"), .draws = "skinned", .kernels = {"affineSkinnedVertex"}, .note = kMain},
              {.defines = defines("MB_NO_TANGENT"), .draws = "rigid, no tangent", .kernels = {"affineVertexNoTangent"},
               .note = "8-float vertex (position, normal, uv) as matrix.vs's MB_NO_TANGENT"},
              {.defines = defines("MB_SKINNED MB_NO_TANGENT"), .draws = "skinned, no tangent",
               .kernels = {"affineSkinnedVertexNoTangent"}, .note = "8-float vertex"},
              patchProgram(kMain),
              {.defines = defines("MB_INSTANCED"), .draws = "rigid, instanced", .kernels = {"matrixAffineVertex"},
               .note = std::string(kMain) + "; " + kInstanced},
              {.defines = defines("MB_INSTANCED MB_NO_TANGENT"), .draws = "rigid, no tangent, instanced",
               .kernels = {"affineVertexNoTangent"}, .note = std::string("8-float vertex; ") + kInstanced},
          })};
}

std::vector<ShaderVariant> affine::qtangentVariants(const std::string& also) {
  const std::string note = kMain + also;
  return programs(kVs, kClip, {
      {.defines = defines("MB_QTANGENT"), .draws = "rigid", .kernels = {"qtangentRigidVertex"}, .note = note},
      {.defines = defines("MB_QTANGENT MB_SKINNED"), .draws = "skinned", .kernels = {"qtangentSkinnedVertex"},
       .note = note},
      patchProgram(note + kNoFrame),
      {.defines = defines("MB_QTANGENT MB_INSTANCED"), .draws = "rigid, instanced",
       .kernels = {"qtangentRigidVertex"}, .note = note + "; " + kInstanced},
  });
}

PipelineEntry qtangentEntry() {
  return {.name = "qtangent", .make = [] { return affine::makePipeline("qtangent", affine::FrameFormat::QTangent); },
          .skin = SkinMethod::LinearBlend, .family = PipelineFamily::Matrix, .vertexBytes = 28,
          .frame = {.decodeKernel = "qtangentFrame"}, .variants = affine::qtangentVariants("")};
}

// The 16-byte vertex (pipelines/compact): rigid draws fold the mesh's cube into their transform,
// skinned and instanced draws run compactPosition.
PipelineEntry matrixCEntry() {
  return {.name = "matrix_c", .make = [] { return affine::makePipeline("matrix_c", affine::FrameFormat::Compact); },
          .skin = SkinMethod::LinearBlend, .family = PipelineFamily::Matrix, .vertexBytes = 16,
          .frame = {.decodeKernel = "compactMatrixFrame"},
          .variants = programs(kVs, kClip, {
              {.defines = defines("MB_COMPACT"), .draws = "rigid", .kernels = {"compactRigidVertex"}, .note = kMain},
              {.defines = defines("MB_COMPACT MB_SKINNED"), .draws = "skinned", .kernels = {"compactSkinnedVertex"},
               .note = kMain},
              patchProgram(kMain + std::string(kNoFrame)),
              {.defines = defines("MB_COMPACT MB_INSTANCED"), .draws = "rigid, instanced",
               .kernels = {"compactPosition", "compactRigidVertex"}, .note = std::string(kMain) + "; " + kInstanced},
          })};
}

}  // namespace mb
