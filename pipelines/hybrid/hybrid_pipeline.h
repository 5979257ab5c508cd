// `hybrid`: motors on the CPU exactly as the motor pipeline, matrices (mat4x3) on the GPU with
// pipelines/matrix's QTangent vertex path.
#pragma once
#include <memory>

#include <glm/glm.hpp>

#include "pipelines/motor/motor_kernels.h"
#include "pipelines/pipeline.h"
#include "pipelines/registry.h"

namespace mb {

namespace hybrid {
// motor(scale * x) as a mat4x3: the motor's matrix with its first three columns scaled.
glm::mat4x3 toMatrix(const mb::Motor& m, const glm::vec3& scale);
}  // namespace hybrid

std::unique_ptr<Pipeline> makeHybridPipeline();
PipelineEntry hybridEntry();

}  // namespace mb
