// hierarchy: a scene-graph update of a deep hierarchy (kNodes nodes, parents before children,
// mostly chains, so the depth is in the hundreds). Per frame and node: the local transform
// from its animated TRS, composed with the parent's world transform.
// Matrix: T R S as a mat4, parent * local with matrix_transform.glsl's matrixCompose (the full
// mat4 product the Sample Viewer's GLM code does). Motor: T R as gp_tr of pga.glsl, uniform
// scale tracked as one float (the parent's scale scales the local translation), gp_mm.
// glm: mat4_cast + scale + translation, GLM's mat4 product. (No lanes_motor side here: its
// 4-lane product reads the local motor the loop has just built with scalar stores back as
// vectors, a store-forwarding stall the pipelines' update does not have — their locals are
// converted in an earlier pass. compose/lanes_motor times the product alone.)
// simd_matrix / simd_motor: kernels/simd's hierarchy update (the same TRS, locals and products,
// mat4x3 for the matrix side) level by level: the nodes of one depth are one SIMD batch, so
// this chain-heavy hierarchy (about one node per level) runs mostly one lane at a time.
#include <algorithm>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"
#include "kernels/simd/simd_kernels.h"

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


// The hierarchy grouped by depth (parents first), as planes for kernels/simd.
struct LevelOrder {
  size_t stride = planeStride(kNodes);
  std::vector<int32_t> parent;
  std::vector<uint32_t> levelEnd;
  AlignedVector<float> trs, world;  // 8 planes; 12 (affine) or 9 (motor + scale) planes
  LevelOrder() : parent(kNodes), trs(8 * stride), world(12 * stride) {
    const Hierarchy& h = hierarchy();
    std::vector<int> depth(kNodes);
    std::vector<size_t> order(kNodes), slot(kNodes);
    for (size_t i = 0; i < size_t(kNodes); ++i) {
      depth[i] = h.parent[i] < 0 ? 0 : depth[size_t(h.parent[i])] + 1;
      order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return depth[a] < depth[b]; });
    for (size_t k = 0; k < size_t(kNodes); ++k) slot[order[k]] = k;
    for (size_t k = 0; k < size_t(kNodes); ++k) {
      const size_t i = order[k];
      parent[k] = h.parent[i] < 0 ? -1 : int32_t(slot[size_t(h.parent[i])]);
      if (k + 1 == size_t(kNodes) || depth[order[k + 1]] != depth[i]) levelEnd.push_back(uint32_t(k + 1));
      const float v[8] = {h.q[i].x, h.q[i].y, h.q[i].z, h.q[i].w, h.t[i].x, h.t[i].y, h.t[i].z, h.s[i]};
      for (size_t c = 0; c < 8; ++c) trs[c * stride + k] = v[c];
    }
  }
};

template <bool kMotor> void hierarchySimd(benchmark::State& state) {
  static LevelOrder l;
  const simd::ConstPlanes trs{l.trs.data(), l.stride};
  const simd::Planes world{l.world.data(), l.stride};
  for (auto _ : state) {
    if (kMotor) simd::hierarchyMotor(trs, l.parent.data(), l.levelEnd.data(), l.levelEnd.size(), world);
    else simd::hierarchyAffine(trs, l.parent.data(), l.levelEnd.data(), l.levelEnd.size(), world);
    benchmark::ClobberMemory();
  }
  setSimdLabel(state);
  setThroughput(state, kNodes, 0, Size::InCache);
  state.counters["depth"] = hierarchy().depth;
}

}  // namespace

void registerHierarchyBenchmarks() {
  registerKernel("hierarchy/matrix", hierarchyMatrix);
  registerKernel("hierarchy/motor", hierarchyMotor);
  registerKernel("hierarchy/glm", hierarchyGlm);
  registerKernel(std::string("hierarchy/") + kSimdMatrix, hierarchySimd<false>);
  registerKernel(std::string("hierarchy/") + kSimdMotor, hierarchySimd<true>);
}

}  // namespace mb::bench
