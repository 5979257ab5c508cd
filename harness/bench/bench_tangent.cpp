// load_frames: the load-time work on each vertex's normal + tangent (kVertices vertices, as
// read from a file: not exactly unit or orthogonal). Matrix: none beyond interleaving, the
// Sample Viewer uploads normal and tangent as they are (a copy). Motor: the motor pipeline's
// conversion to a tangent rotor (pipelines/motor/companion.h encodeTangentRotor: Gram-Schmidt,
// rotor of the frame, handedness in the scalar's sign, the 1/32767 clamp). glm: the same
// conversion with GLM's quat_cast.
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"
#include "pipelines/motor/companion.h"

namespace mb::bench {
namespace {

constexpr size_t kVertices = 16384;

struct Frame {
  glm::vec3 n;
  glm::vec4 t;
};

struct Data {
  std::vector<Frame> in;
  std::vector<Frame> copied;
  std::vector<glm::vec4> rotors;
  Data() : copied(kVertices), rotors(kVertices) {
    Rng r;
    for (size_t i = 0; i < kVertices; ++i) {
      float c0[3], c1[3], c2[3];
      quatColumns(randomQuat(r), c0, c1, c2);
      const float e = 0.01f;
      in.push_back({glm::vec3(c2[0] + r.uniform(-e, e), c2[1], c2[2]),
                    glm::vec4(c0[0], c0[1] + r.uniform(-e, e), c0[2], r.index(2) ? 1.0f : -1.0f)});
    }
  }
};

Data& data() {
  static Data d;
  return d;
}

[[gnu::flatten]] void loadMatrix(benchmark::State& state) {
  Data& d = data();
  for (auto _ : state) {
    for (size_t i = 0; i < kVertices; ++i) d.copied[i] = d.in[i];
    benchmark::DoNotOptimize(d.copied.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kVertices, kVertices * 2 * sizeof(Frame), Size::InCache);
}

[[gnu::flatten]] void loadMotor(benchmark::State& state) {
  Data& d = data();
  for (auto _ : state) {
    for (size_t i = 0; i < kVertices; ++i)
      d.rotors[i] = companion::encodeTangentRotor(d.in[i].n, glm::vec3(d.in[i].t), d.in[i].t.w).rotor;
    benchmark::DoNotOptimize(d.rotors.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kVertices, kVertices * (sizeof(Frame) + sizeof(glm::vec4)), Size::InCache);
}

[[gnu::flatten]] void loadGlm(benchmark::State& state) {
  Data& d = data();
  for (auto _ : state) {
    for (size_t i = 0; i < kVertices; ++i) {
      const glm::vec3 n = glm::normalize(d.in[i].n);
      const glm::vec3 t = glm::normalize(glm::vec3(d.in[i].t) - n * glm::dot(n, glm::vec3(d.in[i].t)));
      const glm::quat q = glm::quat_cast(glm::mat3(t, glm::cross(n, t), n));
      glm::vec4 r(q.w, -q.x, -q.y, -q.z);
      if (std::signbit(r.x) != (d.in[i].t.w < 0.0f)) r = -r;
      if (std::abs(r.x) < companion::kMinTangentScalar) r.x = std::copysign(companion::kMinTangentScalar, r.x);
      d.rotors[i] = r;
    }
    benchmark::DoNotOptimize(d.rotors.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kVertices, kVertices * (sizeof(Frame) + sizeof(glm::vec4)), Size::InCache);
}

}  // namespace

void registerTangentBenchmarks() {
  registerKernel("load_frames/matrix", loadMatrix);
  registerKernel("load_frames/motor", loadMotor);
  registerKernel("load_frames/glm", loadGlm);
}

}  // namespace mb::bench
