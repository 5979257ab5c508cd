// Name -> factory for every pipeline. One line per pipeline.
#include "pipelines/affine/affine_pipeline.h"
#include "pipelines/hybrid/hybrid_pipeline.h"
#include "pipelines/curved/curved_pipeline.h"
#include "pipelines/matrix/matrix_pipeline.h"
#include "pipelines/motor/motor_pipeline.h"
#include "pipelines/pipeline.h"

namespace mb {
namespace {
struct Entry {
  const char* name;
  std::unique_ptr<Pipeline> (*make)();
  Space space;  // the scenes it draws
};
const Entry kPipelines[] = {
    {"matrix", makeMatrixPipeline, Space::Euclidean},
    {"motor", makeMotorPipeline, Space::Euclidean},
    {"affine", makeAffinePipeline, Space::Euclidean},
    {"qtangent", makeQtangentPipeline, Space::Euclidean},
    {"motor_q", makeMotorQPipeline, Space::Euclidean},
    {"hybrid", makeHybridPipeline, Space::Euclidean},
    {"matrix_c", makeMatrixCPipeline, Space::Euclidean},
    {"motor_c", makeMotorCPipeline, Space::Euclidean},
    {"motor_cf", makeMotorCFPipeline, Space::Euclidean},
    {"s3_matrix", makeS3MatrixPipeline, Space::Spherical},
    {"s3_motor", makeS3MotorPipeline, Space::Spherical},
    {"h3_matrix", makeH3MatrixPipeline, Space::Hyperbolic},
    {"h3_motor", makeH3MotorPipeline, Space::Hyperbolic},
};
}  // namespace

std::unique_ptr<Pipeline> createPipeline(const std::string& name) {
  for (const Entry& e : kPipelines)
    if (name == e.name) return e.make();
  return nullptr;
}

std::vector<std::string> pipelineNames(Space space) {
  std::vector<std::string> names;
  for (const Entry& e : kPipelines)
    if (e.space == space) names.push_back(e.name);
  return names;
}

std::vector<std::string> allPipelineNames() {
  std::vector<std::string> names;
  for (const Entry& e : kPipelines) names.push_back(e.name);
  return names;
}

}  // namespace mb
