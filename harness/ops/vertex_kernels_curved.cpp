// The counted per-vertex kernels of the curved-space pipelines:
// shaders/curved_transform.glsl, position and normal, for S3 (kappa = 1) and H3 (kappa = -1).
#include "harness/ops/vertex_inputs.h"
#include "harness/ops/vertex_kernels.h"
#include "shaders/shim/pga_kappa.h"

namespace mb::opsv::detail {
namespace {

inline const char* kCurvedDecls =
    "layout(location = 0) in vec4 a_position; layout(location = 1) in vec4 a_normal;\n"
    "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n";
inline std::string curvedIncl(int kappa) {
  return std::string("#define MB_KAPPA ") + (kappa > 0 ? "1" : "-1") + "\n#include \"curved_transform.glsl\"\n";
}
// Matrix side: view * (instance * v) for the position and the normal.
template <int K> VertexKernel curvedMatrix(const std::string& pipeline) {
  return {pipeline, "instance vertex (pos + normal)", "curvedMatrixVertex",
          [] {
            using P = PgaK<Counted, K>;
            static const typename P::mat4 m(Counted(0.5));
            static const typename P::vec4 p(0.1, 0.2, 0.3, 0.9), n(0.3, 0.2, 0.1, 0.0);
            pgaK<Counted, K>.curvedMatrixVertex(m, m, p, n);
          },
          "mat2x4 v = curvedMatrixVertex(u_view, a_instance, a_position, a_normal); o_0 = v[0]; "
          "o_1 = v[1];",
          curvedIncl(K) + kCurvedDecls + "uniform mat4 u_view; layout(location = 2) in mat4 a_instance;\n",
          "two mat4 * vec4 per vector"};
}
// Motor side: one product (S3: pairs, H3: motors) and two sandwiches.
template <int K> VertexKernel curvedMotor(const std::string& pipeline) {
  return {pipeline, "instance vertex (pos + normal)", "curvedMotorVertex",
          [] {
            using P = PgaK<Counted, K>;
            static const typename P::motor a(typename P::vec4(0.5, 0.1, 0.2, 0.3),
                                             typename P::vec4(0.4, 0.5, 0.6, 0.7));
            static const typename P::vec4 p(0.1, 0.2, 0.3, 0.9), n(0.3, 0.2, 0.1, 0.0);
            pgaK<Counted, K>.curvedMotorVertex(a, a, p, n);
          },
          "mat2x4 v = curvedMotorVertex(mat2x4(u_camera[0], u_camera[1]), mat2x4(a_i0, a_i1), "
          "a_position, a_normal); o_0 = v[0]; o_1 = v[1];",
          curvedIncl(K) + kCurvedDecls +
              "uniform vec4 u_camera[2]; layout(location = 2) in vec4 a_i0; "
              "layout(location = 3) in vec4 a_i1;\n",
          K > 0 ? "gp_pair + 2 sw_pair" : "gp_mm_k + 2 sw_mp_k"};
}

}  // namespace

std::vector<VertexKernel> curvedKernels() {
  return {curvedMatrix<1>("s3_matrix"), curvedMotor<1>("s3_motor"), curvedMatrix<-1>("h3_matrix"),
          curvedMotor<-1>("h3_motor")};
}

}  // namespace mb::opsv::detail
