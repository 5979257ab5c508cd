// PLACEHOLDER until the matrix pipeline lands: registers the name, creates nothing.
#include "pipelines/matrix/matrix_pipeline.h"

namespace mb {
std::unique_ptr<Pipeline> makeMatrixPipeline() { return nullptr; }
}
