// anim_blend: sample two animations and blend them, per node, into the local transform a
// hierarchy update consumes. Keyframe sampling (key search, lerp of translations, shortest-arc
// nlerp of rotations) is the same code for every side; what differs is the blend and the
// representation: matrix blends TRS (lerp, shortest-arc nlerp) and builds a mat4; motor
// builds a motor per sample (gp_tr) and blends motors (shortest arc, normalize_m), the
// paper's method; glm uses glm::mix + glm::slerp and mat4_cast.
#include <algorithm>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"

namespace mb::bench {
namespace {

constexpr int kNodes = 1024, kKeys = 32;
constexpr float kFps = 30.0f;

using V3 = PS::vec3;
using V4 = PS::vec4;  // quaternion (x, y, z, w)

struct Clip {
  std::vector<V3> t;  // [node * kKeys + key]
  std::vector<V4> q;
};

struct Animations {
  std::vector<float> times;
  Clip a, b;
  std::vector<MS::mat4> matrixOut;
  std::vector<PS::motor> motorOut;
  std::vector<glm::mat4> glmOut;
  Animations() {
    Rng r;
    for (int k = 0; k < kKeys; ++k) times.push_back(float(k) / kFps);
    for (Clip* c : {&a, &b})
      for (int i = 0; i < kNodes * kKeys; ++i) {
        const Quat q = randomQuat(r);
        c->q.push_back(V4(q.x, q.y, q.z, q.w));
        c->t.push_back(V3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)));
      }
    matrixOut.resize(kNodes), motorOut.resize(kNodes), glmOut.resize(kNodes);
  }
};

Animations& animations() {
  static Animations a;
  return a;
}

// Key interval and fraction for time `t` (binary search, clamped).
struct Key {
  int k;
  float f;
};
Key findKey(const std::vector<float>& times, float t) {
  t = std::clamp(t, times.front(), times.back());
  int k = int(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  k = std::clamp(k, 0, int(times.size()) - 2);
  return {k, (t - times[size_t(k)]) / (times[size_t(k) + 1] - times[size_t(k)])};
}

inline V4 nlerp(const V4& a, V4 b, float f) {
  if (PS::dot(a, b) < 0.0f) b = -b;
  return PS::normalize(a + (b - a) * f);
}

struct Sample {
  V3 t;
  V4 q;
};
inline Sample sample(const Clip& c, int node, const Key& key) {
  const size_t i = size_t(node) * kKeys + size_t(key.k);
  return {PS::mix(c.t[i], c.t[i + 1], key.f), nlerp(c.q[i], c.q[i + 1], key.f)};
}

inline PS::motor motorOf(PS& P, const Sample& s) {
  const PS::motor T(V4(1.0f, 0.0f, 0.0f, 0.0f), V4(s.t * -0.5f, 0.0f));
  return P.gp_tr(T, PS::motor(V4(s.q.w, -s.q.x, -s.q.y, -s.q.z), V4(0.0f)));
}

// Per iteration both clips advance by one 60 Hz frame (different keys every call).
template <class F> [[gnu::flatten]] void run(benchmark::State& state, F node) {
  Animations& an = animations();
  float clock = 0.0f;
  const float length = an.times.back();
  for (auto _ : state) {
    clock += 1.0f / 60.0f;
    if (clock > length) clock -= length;
    const Key ka = findKey(an.times, clock), kb = findKey(an.times, length - clock);
    const float w = 0.3f;
    for (int i = 0; i < kNodes; ++i) node(an, i, sample(an.a, i, ka), sample(an.b, i, kb), w);
    benchmark::ClobberMemory();
  }
  setThroughput(state, kNodes, 0, Size::InCache);
}

void animMatrix(benchmark::State& state) {
  run(state, [](Animations& an, int i, const Sample& a, const Sample& b, float w) {
    const V3 t = PS::mix(a.t, b.t, w);
    const V4 q = nlerp(a.q, b.q, w);
    const float x2 = q.x + q.x, y2 = q.y + q.y, z2 = q.z + q.z;
    const float xx = q.x * x2, yy = q.y * y2, zz = q.z * z2, xy = q.x * y2, xz = q.x * z2,
                yz = q.y * z2, wx = q.w * x2, wy = q.w * y2, wz = q.w * z2;
    an.matrixOut[size_t(i)] = MS::mat4(MS::vec4(1.0f - (yy + zz), xy + wz, xz - wy, 0.0f),
                                       MS::vec4(xy - wz, 1.0f - (xx + zz), yz + wx, 0.0f),
                                       MS::vec4(xz + wy, yz - wx, 1.0f - (xx + yy), 0.0f),
                                       MS::vec4(t, 1.0f));
  });
}

void animMotor(benchmark::State& state) {
  PS P;
  run(state, [&P](Animations& an, int i, const Sample& a, const Sample& b, float w) {
    const PS::motor ma = motorOf(P, a);
    PS::motor mb = motorOf(P, b);
    if (PS::dot(ma[0], mb[0]) < 0.0f) mb = -mb;
    an.motorOut[size_t(i)] = P.normalize_m(ma * (1.0f - w) + mb * w);
  });
}

void animGlm(benchmark::State& state) {
  run(state, [](Animations& an, int i, const Sample& a, const Sample& b, float w) {
    const glm::vec3 t = glm::mix(glm::vec3(a.t.x, a.t.y, a.t.z), glm::vec3(b.t.x, b.t.y, b.t.z), w);
    const glm::quat q = glm::slerp(glm::quat(a.q.w, a.q.x, a.q.y, a.q.z),
                                   glm::quat(b.q.w, b.q.x, b.q.y, b.q.z), w);
    glm::mat4 m = glm::mat4_cast(q);
    m[3] = glm::vec4(t, 1.0f);
    an.glmOut[size_t(i)] = m;
  });
}

}  // namespace

void registerAnimationBenchmarks() {
  registerKernel("anim_blend/matrix", animMatrix);
  registerKernel("anim_blend/motor", animMotor);
  registerKernel("anim_blend/glm", animGlm);
}

}  // namespace mb::bench
