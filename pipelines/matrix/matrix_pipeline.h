#pragma once
#include <memory>

#include "pipelines/pipeline.h"
#include "pipelines/registry.h"

namespace mb {
std::unique_ptr<Pipeline> makeMatrixPipeline();
PipelineEntry matrixEntry();  // matrix_entry.cpp
}
