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
  return {.name = "matrix", .make = makeMatrixPipeline, .skin = SkinMethod::LinearBlend,
          .family = PipelineFamily::Matrix, .vertexBytes = 48, .frame = {.fetched = "float frame"},
          .variants = programs("matrix.vs", "matrixWorldToClip", {
              {.draws = "rigid", .kernels = {"matrixRigidVertex"}, .note = main},
              {.defines = defines("SKINNED"), .draws = "skinned", .kernels = {"matrixSkinnedVertex"},
               .note = main + "; = skinned, reference"},
              {.defines = defines("SKINNED"), .draws = "skinned, reference", .kernels = {"matrixSkinnedVertex"},
               .note = ref},
              {.defines = defines("SKINNED MB_WORLD_PALETTE"), .draws = "skinned, world palette",
               .kernels = {"matrixSkinnedVertexWorld"}, .note = world},
              {.defines = defines("MB_NO_TANGENT"), .draws = "rigid, no tangent",
               .kernels = {"matrixRigidVertexNoTangent"}},
              {.defines = defines("SKINNED MB_NO_TANGENT"), .draws = "skinned, no tangent",
               .kernels = {"matrixSkinnedVertexNoTangent"}, .note = ref},
              {.defines = defines("SKINNED MB_WORLD_PALETTE MB_NO_TANGENT"),
               .draws = "skinned, world palette, no tangent", .kernels = {"matrixSkinnedVertexWorldNoTangent"},
               .note = world},
              {.stage = "matrix_patch.vs", .draws = "bezier patch", .kernels = {"bezierPatch", "matrixPatchVertex"},
               .note = main + "; " + kTexels},
              {.defines = defines("MB_INSTANCED"), .draws = "rigid, instanced", .kernels = {"matrixRigidVertex"},
               .note = main + "; " + kInstanced},
              {.defines = defines("MB_INSTANCED MB_NO_TANGENT"), .draws = "rigid, no tangent, instanced",
               .kernels = {"matrixRigidVertexNoTangent"}, .note = kInstanced},
              {.defines = defines(kMorph), .draws = "rigid, morph", .kernels = {"matrixRigidVertex"},
               .note = main + "; " + kMorphSums},
          })};
}

}  // namespace mb
