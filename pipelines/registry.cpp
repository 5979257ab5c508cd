// Name -> factory for every pipeline. One line per pipeline.
#include "pipelines/affine/affine_pipeline.h"
#include "pipelines/hybrid/hybrid_pipeline.h"
#include "pipelines/curved/curved_pipeline.h"
#include "pipelines/matrix/matrix_pipeline.h"
#include "pipelines/motor/motor_pipeline.h"
#include "pipelines/pipeline.h"
#include "pipelines/skin_method.h"

namespace mb {
namespace {
struct Entry {
  const char* name;
  std::unique_ptr<Pipeline> (*make)();
  Space space;  // the scenes it draws
  SkinMethod skin;  // how its vertex shader blends joints (skin_method.h)
};
constexpr SkinMethod kLbs = SkinMethod::LinearBlend, kMotors = SkinMethod::MotorBlend, kNoSkin = SkinMethod::None;
const Entry kPipelines[] = {
    {"matrix", makeMatrixPipeline, Space::Euclidean, kLbs},
    {"motor", makeMotorPipeline, Space::Euclidean, kMotors},
    {"affine", makeAffinePipeline, Space::Euclidean, kLbs},
    {"qtangent", makeQtangentPipeline, Space::Euclidean, kLbs},
    {"motor_q", makeMotorQPipeline, Space::Euclidean, kMotors},
    {"hybrid", makeHybridPipeline, Space::Euclidean, kLbs},
    {"matrix_c", makeMatrixCPipeline, Space::Euclidean, kLbs},
    {"motor_c", makeMotorCPipeline, Space::Euclidean, kMotors},
    {"motor_cf", makeMotorCFPipeline, Space::Euclidean, kMotors},
    {"s3_matrix", makeS3MatrixPipeline, Space::Spherical, kNoSkin},
    {"s3_motor", makeS3MotorPipeline, Space::Spherical, kNoSkin},
    {"h3_matrix", makeH3MatrixPipeline, Space::Hyperbolic, kNoSkin},
    {"h3_motor", makeH3MotorPipeline, Space::Hyperbolic, kNoSkin},
};
}  // namespace

std::unique_ptr<Pipeline> createPipeline(const std::string& name) {
  for (const Entry& e : kPipelines)
    if (name == e.name) return e.make();
  return nullptr;
}

SkinMethod skinMethodOf(const std::string& name) {
  for (const Entry& e : kPipelines)
    if (name == e.name) return e.skin;
  return SkinMethod::None;
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
