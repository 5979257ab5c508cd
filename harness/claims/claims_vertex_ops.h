// Ops per vertex of every registered pipeline, measured once per process (harness/ops: counted
// through the shim and, when the tools run, from SPIR-V) and shared by the speed and
// "vs strongest" rows. A pipeline whose count is 0 is left out: no vertex shader transforms for
// free, so 0 means its kernels were not joined, never a strongest baseline.
#pragma once
#include <map>
#include <string>

#include "harness/ops/ops_vertex.h"

namespace mb::claims {

const opsv::VertexOps& vertexOps();

// Total ops (mul + add + div + sqrt + other) per pipeline of the variant `label` ("rigid",
// "skinned": the whole vertex transform, object to clip), counted or SPIR-V; `zero` lists the
// pipelines left out for a count of 0.
std::map<std::string, double> opsPerPipeline(const std::string& label, bool spirv, std::string& zero);

}  // namespace mb::claims
