// The matrix pipeline's registry entry: its traits and the programs matrix.vs and
// matrix_patch.vs are linked as (matrix_pipeline.cpp's defines()).
#include "pipelines/matrix/matrix_pipeline.h"

namespace mb {

PipelineEntry matrixEntry() {
  using namespace variant_notes;
  const std::string main = "main() divides the position by w and normalises normal and tangent for the varyings "
                           "(motor.vs leaves normalisation to forward.fs, which normalises both anyway)";
  const std::string ref = "the Sample Viewer's: skin, then u_ModelMatrix per vertex";
  const std::string world = "joint world * inverse bind; no model matrix per vertex";
  const std::string clip = "matrixWorldToClip", vs = "matrix.vs";
  return {.name = "matrix", .make = makeMatrixPipeline, .space = Space::Euclidean, .skin = SkinMethod::LinearBlend,
          .family = PipelineFamily::Matrix, .vertexBytes = 48, .frame = {.fetched = "float frame"},
          .variants = {
              {.stage = vs, .draws = "rigid", .kernels = {"matrixRigidVertex", clip}, .note = main},
              {.stage = vs, .defines = {{"SKINNED", ""}}, .draws = "skinned", .kernels = {"matrixSkinnedVertex", clip},
               .note = main + "; = skinned, reference"},
              {.stage = vs, .defines = {{"SKINNED", ""}}, .draws = "skinned, reference",
               .kernels = {"matrixSkinnedVertex", clip}, .note = ref},
              {.stage = vs, .defines = {{"SKINNED", ""}, {"MB_WORLD_PALETTE", ""}}, .draws = "skinned, world palette",
               .kernels = {"matrixSkinnedVertexWorld", clip}, .note = world},
              {.stage = vs, .defines = {{"MB_NO_TANGENT", ""}}, .draws = "rigid, no tangent",
               .kernels = {"matrixRigidVertexNoTangent", clip}},
              {.stage = vs, .defines = {{"SKINNED", ""}, {"MB_NO_TANGENT", ""}}, .draws = "skinned, no tangent",
               .kernels = {"matrixSkinnedVertexNoTangent", clip}, .note = ref},
              {.stage = vs, .defines = {{"SKINNED", ""}, {"MB_WORLD_PALETTE", ""}, {"MB_NO_TANGENT", ""}},
               .draws = "skinned, world palette, no tangent", .kernels = {"matrixSkinnedVertexWorldNoTangent", clip},
               .note = world},
              {.stage = "matrix_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "matrixPatchVertex", clip},
               .note = main + "; " + kTexels},
              {.stage = vs, .defines = {{"MB_INSTANCED", ""}}, .draws = "rigid, instanced",
               .kernels = {"matrixRigidVertex", clip}, .note = main + "; " + kInstanced},
              {.stage = vs, .defines = {{"MB_INSTANCED", ""}, {"MB_NO_TANGENT", ""}},
               .draws = "rigid, no tangent, instanced", .kernels = {"matrixRigidVertexNoTangent", clip},
               .note = kInstanced},
              {.stage = vs, .defines = morphDefines(), .draws = "rigid, morph", .kernels = {"matrixRigidVertex", clip},
               .note = main + "; " + kMorphSums},
          }};
}

}  // namespace mb
