#pragma once
#include <memory>

#include "pipelines/pipeline.h"

namespace mb {
std::unique_ptr<Pipeline> makeMatrixPipeline();
}
