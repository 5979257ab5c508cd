// Name -> factory for every pipeline. One line per pipeline.
#include "pipelines/matrix/matrix_pipeline.h"
#include "pipelines/motor/motor_pipeline.h"
#include "pipelines/pipeline.h"

namespace mb {
namespace {
struct Entry {
  const char* name;
  std::unique_ptr<Pipeline> (*make)();
};
const Entry kPipelines[] = {
    {"matrix", makeMatrixPipeline},
    {"motor", makeMotorPipeline},
};
}  // namespace

std::unique_ptr<Pipeline> createPipeline(const std::string& name) {
  for (const Entry& e : kPipelines)
    if (name == e.name) return e.make();
  return nullptr;
}

std::vector<std::string> pipelineNames() {
  std::vector<std::string> names;
  for (const Entry& e : kPipelines) names.push_back(e.name);
  return names;
}

}  // namespace mb
