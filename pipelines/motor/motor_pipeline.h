#pragma once
#include <memory>
#include <string>

#include "pipelines/pipeline.h"
#include "pipelines/registry.h"

namespace mb {

// What distinguishes the motor pipelines: `motor` is the paper's form.
struct MotorVariant {
  std::string name = "motor";
  bool quantizedFrame = false;  // tangent rotor as int16x4 SNORM (motor_q_vertices.h)
  bool compact = false;         // motor_c: 16-byte vertices (motor_c_vertices.h, MB_COMPACT)
  bool fragmentRotor = false;   // motor_cf: with `compact`, the world tangent rotor is the varying
                                // and forward.fs unpacks it (MB_SIGNED_ROTOR, MB_FRAGMENT_ROTOR)
};

std::unique_ptr<Pipeline> makeMotorPipeline(const MotorVariant& variant);
// The registry entries of motor, motor_q, motor_c and motor_cf (motor_entry.cpp).
PipelineEntry motorEntry();
PipelineEntry motorQEntry();
PipelineEntry motorCEntry();
PipelineEntry motorCFEntry();
}
