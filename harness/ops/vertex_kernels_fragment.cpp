// The counted per-fragment kernels of forward.fs: the shading normal from the interpolated
// frame (shaders/frame_shading.glsl), the TBN path every pipeline but motor_cf runs and the
// rotor path of motor_cf. Listed with the vertex kernels (one table, one counter);
// their probe is a vertex shader calling the same function, which SPIR-V counts alike.
#include "harness/ops/vertex_inputs.h"
#include "harness/ops/vertex_kernels.h"
#include "shaders/shim/frame_shading.h"

namespace mb::opsv::detail {

std::vector<VertexKernel> fragmentKernels() {
  using FC = FrameShading<Counted>;
  static FC F;
  // Generic inputs: an interpolated (not unit) frame, a normal-map sample, a back face.
  static const FC::vec3 normal(0.3, 0.5, 0.8), m(0.2, -0.3, 0.93);
  static const FC::vec4 tangent(0.8, -0.45, 0.1, -1.0), rotor(0.6, -0.3, 0.5, 0.4);
  const std::string decls =
      "#include \"frame_shading.glsl\"\n"
      "layout(location = 0) in vec3 a_normal; layout(location = 1) in vec4 a_tangent;\n"
      "layout(location = 2) in vec4 a_rotor; layout(location = 3) in vec3 a_m;\n"
      "layout(location = 4) in float a_facing; layout(location = 5) in float a_handedness;\n"
      "layout(location = 0) out vec4 o_0;\n";
  const std::string tbnPipes = "all but motor_cf";
  return {
      {tbnPipes, "fragment: normal-mapped normal (TBN)", "tbnShadingNormal",
       [&] { F.tbnShadingNormal(normal, tangent, m, -1.0); },
       "o_0 = vec4(tbnShadingNormal(a_normal, a_tangent, a_m, a_facing), 0.0);", decls,
       "per fragment: normalise n, Gram-Schmidt t, test it, normalise, bitangent, TBN * m, normalise"},
      {"motor_cf", "fragment: normal-mapped normal (rotor)", "rotorShadingNormal",
       [&] { F.rotorShadingNormal(rotor, -1.0, m, -1.0); },
       "o_0 = vec4(rotorShadingNormal(a_rotor, a_handedness, a_m, a_facing), 0.0);", decls,
       "per fragment: normalise the rotor, extractNormalTangent, bitangent, TBN * m, normalise"},
      {tbnPipes, "fragment: surface normal (TBN)", "tbnSurfaceNormal", [&] { F.tbnSurfaceNormal(normal, -1.0); },
       "o_0 = vec4(tbnSurfaceNormal(a_normal, a_facing), 0.0);", decls, "materials without a normal map"},
      {"motor_cf", "fragment: surface normal (rotor)", "rotorSurfaceNormal", [&] { F.rotorSurfaceNormal(rotor, -1.0); },
       "o_0 = vec4(rotorSurfaceNormal(a_rotor, a_facing), 0.0);", decls, "materials without a normal map"},
  };
}

}  // namespace mb::opsv::detail
