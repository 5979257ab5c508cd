// The kernel families of `motorbench bench`, one file each (harness/bench/bench_*.cpp). Each call
// registers the family's matrix, motor and glm benchmarks (see bench_common.h for the names).
#pragma once

namespace mb::bench {

void registerTransformBenchmarks();   // compose, point, direction
void registerVertexBenchmarks();      // vertex_frame, skinned_vertex, skinned_vertex_gather
void registerHierarchyBenchmarks();   // hierarchy (scene-graph update)
void registerPaletteBenchmarks();     // palette (skin palette: joint world * inverse bind)
void registerAnimationBenchmarks();   // anim_blend (sample two animations and blend)
void registerTangentBenchmarks();     // load_frames (normal + tangent -> tangent rotor)

}  // namespace mb::bench
