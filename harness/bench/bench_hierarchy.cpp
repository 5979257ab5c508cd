// hierarchy: a scene-graph update of a deep hierarchy (kNodes nodes, parents before children,
// mostly chains, so the depth is in the hundreds). Per frame and node: the local transform
// from its animated TRS, composed with the parent's world transform.
// Matrix: T R S as a mat4, parent * local with matrix_transform.glsl's matrixCompose (the full
// mat4 product the Sample Viewer's GLM code does). Motor: T R as gp_tr of pga.glsl, uniform
// scale tracked as one float (the parent's scale scales the local translation), gp_mm.
// glm: mat4_cast + scale + translation, GLM's mat4 product.
#include <algorithm>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"

namespace mb::bench {
namespace {

constexpr int kNodes = 1536;

struct Hierarchy {
  std::vector<int> parent;
  std::vector<Quat> q;
  std::vector<PS::vec3> t;
  std::vector<float> s;
  int depth = 0;
  std::vector<MS::mat4> matrixWorld;
  std::vector<PS::motor> motorWorld;
  std::vector<float> motorScale;
  std::vector<glm::mat4> glmWorld;
  Hierarchy() {
    Rng r;
    std::vector<int> d(kNodes, 0);
    for (int i = 0; i < kNodes; ++i) {
      // Three in four nodes continue the chain; the rest branch off a recent node.
      parent.push_back(i == 0 ? -1 : r.index(4) ? i - 1 : std::max(0, i - 1 - r.index(16)));
      d[size_t(i)] = i == 0 ? 0 : d[size_t(parent.back())] + 1;
      depth = std::max(depth, d[size_t(i)]);
      q.push_back(randomQuat(r));
      t.push_back(PS::vec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)));
      s.push_back(r.uniform(0.9f, 1.1f));
    }
    matrixWorld.resize(kNodes), motorWorld.resize(kNodes), motorScale.resize(kNodes);
    glmWorld.resize(kNodes);
  }
};

Hierarchy& hierarchy() {
  static Hierarchy h;
  return h;
}

// T R S from a unit quaternion (x, y, z, w), translation and uniform scale, on shim floats.
MS::mat4 trsMatrix(const Quat& q, const PS::vec3& t, float s) {
  const float x2 = q.x + q.x, y2 = q.y + q.y, z2 = q.z + q.z;
  const float xx = q.x * x2, yy = q.y * y2, zz = q.z * z2, xy = q.x * y2, xz = q.x * z2,
              yz = q.y * z2, wx = q.w * x2, wy = q.w * y2, wz = q.w * z2;
  return MS::mat4(MS::vec4(MS::vec3(1.0f - (yy + zz), xy + wz, xz - wy) * s, 0.0f),
                  MS::vec4(MS::vec3(xy - wz, 1.0f - (xx + zz), yz + wx) * s, 0.0f),
                  MS::vec4(MS::vec3(xz + wy, yz - wx, 1.0f - (xx + yy)) * s, 0.0f),
                  MS::vec4(t, 1.0f));
}

// One update of the whole hierarchy per iteration: node(k, parent) sets node k's world
// transform (parent < 0: a root), parents always first.
template <class Node> [[gnu::flatten]] void hierarchyPass(benchmark::State& state, Node node) {
  Hierarchy& h = hierarchy();
  for (auto _ : state) {
    for (size_t k = 0; k < size_t(kNodes); ++k) node(k, h.parent[k]);
    benchmark::ClobberMemory();
  }
  setThroughput(state, kNodes, 0, Size::InCache);
  state.counters["depth"] = h.depth;
}

void hierarchyMatrix(benchmark::State& state) {
  Hierarchy& h = hierarchy();
  MS S;
  hierarchyPass(state, [&](size_t k, int p) {
    const MS::mat4 local = trsMatrix(h.q[k], h.t[k], h.s[k]);
    h.matrixWorld[k] = p < 0 ? local : S.matrixCompose(h.matrixWorld[size_t(p)], local);
  });
}

void hierarchyMotor(benchmark::State& state) {
  Hierarchy& h = hierarchy();
  PS P;
  hierarchyPass(state, [&](size_t k, int p) {
    const PS::motor T(PS::vec4(1.0f, 0.0f, 0.0f, 0.0f), PS::vec4(h.t[k] * -0.5f, 0.0f));
    const PS::motor local = P.gp_tr(T, PS::motor(rotorOf(h.q[k]), PS::vec4(0.0f)));
    if (p < 0) {
      h.motorWorld[k] = local, h.motorScale[k] = h.s[k];
      return;
    }
    // The parent's scale applies to the local translation (the motor's e0 half).
    const float ps = h.motorScale[size_t(p)];
    h.motorWorld[k] = P.gp_mm(h.motorWorld[size_t(p)], PS::motor(local[0], local[1] * ps));
    h.motorScale[k] = ps * h.s[k];
  });
}

void hierarchyGlm(benchmark::State& state) {
  Hierarchy& h = hierarchy();
  hierarchyPass(state, [&](size_t k, int p) {
    glm::mat4 local = glm::mat4_cast(glm::quat(h.q[k].w, h.q[k].x, h.q[k].y, h.q[k].z));
    local[0] *= h.s[k], local[1] *= h.s[k], local[2] *= h.s[k];
    local[3] = glm::vec4(h.t[k].x, h.t[k].y, h.t[k].z, 1.0f);
    h.glmWorld[k] = p < 0 ? local : h.glmWorld[size_t(p)] * local;
  });
}

}  // namespace

void registerHierarchyBenchmarks() {
  registerKernel("hierarchy/matrix", hierarchyMatrix);
  registerKernel("hierarchy/motor", hierarchyMotor);
  registerKernel("hierarchy/glm", hierarchyGlm);
}

}  // namespace mb::bench
