// PLACEHOLDER until the motor pipeline lands: registers the name, creates nothing.
#include "pipelines/motor/motor_pipeline.h"

namespace mb {
std::unique_ptr<Pipeline> makeMotorPipeline() { return nullptr; }
}
