// hierarchy: a scene-graph update (parents before children) in three shapes: `hierarchy` deep
// (kNodes nodes, mostly chains, the depth in the hundreds), `hierarchy_wide` (kNodes nodes, a
// bushy tree a few levels deep) and `hierarchy_skeleton` (a character's node tree: the shape of
// a humanoid rig with a face, generated here). Per frame and node: the local transform from its animated TRS, composed
// with the parent's world transform.
// Matrix: T R S as a mat4, parent * local with matrix_transform.glsl's matrixCompose (the full
// mat4 product the Sample Viewer's GLM code does). Motor: T R as gp_tr of pga.glsl, uniform
// scale tracked as one float (the parent's scale scales the local translation), gp_mm.
// glm: mat4_cast + scale + translation, GLM's mat4 product. (No lanes_motor side here: its
// 4-lane product reads the local motor the loop has just built with scalar stores back as
// vectors, a store-forwarding stall the pipelines' update does not have — their locals are
// converted in an earlier pass. compose/lanes_motor times the product alone.)
// simd_matrix / simd_motor: kernels/simd's hierarchy update (the same TRS, locals and products)
// as ozz-animation's local-to-model job: locals computed a full vector of nodes at a time, then
// each node's product with its parent on 4-lane vectors, in the nodes' own order.
#include <algorithm>
#include <deque>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"
#include "kernels/simd/simd_kernels.h"

namespace mb::bench {
namespace {

constexpr int kNodes = 1536;

// The shapes timed: deep (chains: three in four nodes continue the chain, the rest branch off a
// recent node; depth in the hundreds), wide (every node's parent drawn among the first eighth of
// the nodes before it: a bushy tree a few levels deep, many siblings per parent) and skeleton
// (humanoidTree()).
enum class Shape { Deep, Wide, Skeleton };

// A humanoid character's node tree as a Mixamo-rigged file with a face rig carries it (81 nodes,
// depth 11): camera, lamp and character roots; under the character (scale 0.01) its mesh node
// and the hips; spine (3), neck (2) and head; under the head the eyes, 14 face joints and the jaw
// with 7 of its own; from the upper spine two shoulders, each with arm, forearm, hand and five
// fingers of three joints; from the hips two legs of four. Parents first, in breadth-first order
// (as a loader walks a file's tree). Generated, so every clone times the same tree; each entry
// the node's parent (-1: a root).
std::vector<int> humanoidTree() {
  std::vector<std::vector<int>> children(1);  // children[0]: the roots
  auto add = [&](int parentSlot) {            // parentSlot: the parent's index + 1
    children.emplace_back();
    children[size_t(parentSlot)].push_back(int(children.size()) - 2);
    return int(children.size()) - 1;
  };
  auto chain = [&](int from, int n) { for (int k = 0; k < n; ++k) from = add(from); return from; };
  add(0);                                    // camera
  const int character = add(0);
  add(0);                                    // lamp
  add(character);                            // the mesh node
  const int hips = add(character);
  const int upperSpine = chain(hips, 3);
  const int head = chain(upperSpine, 3);     // neck, neck1, head
  chain(head, 1), chain(head, 1);            // the eyes
  const int jaw = add(head);
  for (int k = 0; k < 7; ++k) add(jaw);      // tongue, lips, jaw end
  for (int k = 0; k < 14; ++k) add(head);    // lips, nostrils, cheeks, eyelids, brows
  for (int side = 0; side < 2; ++side) {
    const int hand = chain(upperSpine, 4);   // shoulder, arm, forearm, hand
    for (int finger = 0; finger < 5; ++finger) chain(hand, 3);
  }
  for (int side = 0; side < 2; ++side) chain(hips, 4);  // up leg, leg, foot, toe
  std::vector<int> order = children[0], slot(children.size() - 1), parent;
  for (size_t k = 0; k < order.size(); ++k)
    for (int c : children[size_t(order[k]) + 1]) order.push_back(c);
  for (size_t k = 0; k < order.size(); ++k) slot[size_t(order[k])] = int(k);
  std::vector<int> parentOf(order.size(), -1);
  for (size_t p = 1; p < children.size(); ++p)
    for (int c : children[p]) parentOf[size_t(c)] = int(p) - 1;
  for (int node : order) parent.push_back(parentOf[size_t(node)] < 0 ? -1 : slot[size_t(parentOf[size_t(node)])]);
  return parent;
}

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
  explicit Hierarchy(Shape shape) {
    Rng r;
    const std::vector<int> skeleton = shape == Shape::Skeleton ? humanoidTree() : std::vector<int>();
    const int n = shape == Shape::Skeleton ? int(skeleton.size()) : kNodes;
    std::vector<int> d(size_t(n), 0);
    for (int i = 0; i < n; ++i) {
      if (shape == Shape::Skeleton) parent.push_back(skeleton[size_t(i)]);
      else if (shape == Shape::Wide) parent.push_back(i == 0 ? -1 : r.index(std::max(1, i / 8)));
      else parent.push_back(i == 0 ? -1 : r.index(4) ? i - 1 : std::max(0, i - 1 - r.index(16)));
      d[size_t(i)] = parent.back() < 0 ? 0 : d[size_t(parent.back())] + 1;
      depth = std::max(depth, d[size_t(i)]);
      q.push_back(randomQuat(r));
      t.push_back(PS::vec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)));
      s.push_back(shape == Shape::Skeleton ? 1.0f : r.uniform(0.9f, 1.1f));  // a rig's rest scales are 1
    }
    allocate();
  }
  size_t size() const { return parent.size(); }
  void allocate() {
    matrixWorld.resize(size()), motorWorld.resize(size()), motorScale.resize(size());
    glmWorld.resize(size());
  }
};

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
template <class Node> [[gnu::flatten]] void hierarchyPass(benchmark::State& state, const Hierarchy& h, Node node) {
  const size_t n = h.size();
  const int* parent = h.parent.data();
  for (auto _ : state) {
    for (size_t k = 0; k < n; ++k) node(k, parent[k]);
    benchmark::ClobberMemory();
  }
  setThroughput(state, h.size(), 0, Size::InCache);
  state.counters["depth"] = h.depth;
}

void hierarchyMatrix(benchmark::State& state, Hierarchy& h) {
  MS S;
  hierarchyPass(state, h, [&](size_t k, int p) {
    const MS::mat4 local = trsMatrix(h.q[k], h.t[k], h.s[k]);
    h.matrixWorld[k] = p < 0 ? local : S.matrixCompose(h.matrixWorld[size_t(p)], local);
  });
}

void hierarchyMotor(benchmark::State& state, Hierarchy& h) {
  PS P;
  hierarchyPass(state, h, [&](size_t k, int p) {
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

void hierarchyGlm(benchmark::State& state, Hierarchy& h) {
  hierarchyPass(state, h, [&](size_t k, int p) {
    glm::mat4 local = glm::mat4_cast(glm::quat(h.q[k].w, h.q[k].x, h.q[k].y, h.q[k].z));
    local[0] *= h.s[k], local[1] *= h.s[k], local[2] *= h.s[k];
    local[3] = glm::vec4(h.t[k].x, h.t[k].y, h.t[k].z, 1.0f);
    h.glmWorld[k] = p < 0 ? local : h.glmWorld[size_t(p)] * local;
  });
}


// The hierarchy's TRS as planes for kernels/simd, in the nodes' own parents-first order.
struct TrsPlanes {
  size_t stride;
  std::vector<int32_t> parent;
  AlignedVector<float> trs, world;  // 8 planes; 16 floats (affine) or 12 (motor) per node
  explicit TrsPlanes(const Hierarchy& h)
      : stride(planeStride(h.size())), parent(h.parent.begin(), h.parent.end()), trs(8 * stride),
        world(h.size() * simd::kHierarchyAffineFloats) {
    for (size_t k = 0; k < h.size(); ++k) {
      const float v[8] = {h.q[k].x, h.q[k].y, h.q[k].z, h.q[k].w, h.t[k].x, h.t[k].y, h.t[k].z, h.s[k]};
      for (size_t c = 0; c < 8; ++c) trs[c * stride + k] = v[c];
    }
  }
};

template <bool kMotor> void hierarchySimd(benchmark::State& state, const Hierarchy& h, TrsPlanes& l) {
  const simd::ConstPlanes trs{l.trs.data(), l.stride};
  for (auto _ : state) {
    if (kMotor) simd::hierarchyMotor(trs, l.parent.data(), h.size(), l.world.data());
    else simd::hierarchyAffine(trs, l.parent.data(), h.size(), l.world.data());
    benchmark::ClobberMemory();
  }
  setSimdLabel(state);
  setThroughput(state, h.size(), 0, Size::InCache);
  state.counters["depth"] = h.depth;
}

// The five sides of one hierarchy; the data lives for the process (the benchmarks run after
// registration; a deque keeps its elements in place).
void registerHierarchy(const std::string& kernel, Hierarchy&& hierarchy) {
  static std::deque<Hierarchy> hierarchies;
  static std::deque<TrsPlanes> planes;
  Hierarchy* h = &hierarchies.emplace_back(std::move(hierarchy));
  TrsPlanes* l = &planes.emplace_back(*h);
  registerKernel(kernel + "/matrix", [h](benchmark::State& s) { hierarchyMatrix(s, *h); });
  registerKernel(kernel + "/motor", [h](benchmark::State& s) { hierarchyMotor(s, *h); });
  registerKernel(kernel + "/glm", [h](benchmark::State& s) { hierarchyGlm(s, *h); });
  registerKernel(kernel + "/" + kSimdMatrix, [h, l](benchmark::State& s) { hierarchySimd<false>(s, *h, *l); });
  registerKernel(kernel + "/" + kSimdMotor, [h, l](benchmark::State& s) { hierarchySimd<true>(s, *h, *l); });
}

}  // namespace

void registerHierarchyBenchmarks() {
  registerHierarchy("hierarchy", Hierarchy(Shape::Deep));
  registerHierarchy("hierarchy_wide", Hierarchy(Shape::Wide));
  registerHierarchy("hierarchy_skeleton", Hierarchy(Shape::Skeleton));
}

}  // namespace mb::bench
