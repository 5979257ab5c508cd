// The kernel families of `motorbench bench`, one file each (harness/bench/bench_*.cpp). Each call
// registers the family's matrix, motor and glm benchmarks (see bench_common.h for the names).
#pragma once

namespace mb::bench {

void registerTransformBenchmarks();   // compose, point, direction
void registerVertexBenchmarks();      // vertex_frame, skinned_vertex
void registerHierarchyBenchmarks();   // hierarchy (scene-graph update)
void registerAnimationBenchmarks();   // anim_blend (sample two animations and blend)
void registerTangentBenchmarks();     // load_frames (normal + tangent -> tangent rotor)

}  // namespace mb::bench
