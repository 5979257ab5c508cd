// Tangent rotors of the motor pipeline's vertices (pipelines/motor/motor_vertices.h) decode,
// through the shader's own code (motor_transform.glsl via the C++ shim), to the authored
// normal, tangent and handedness: on the textured_box (axis-aligned frames, several of them
// 180-degree turns of the basis frame whose rotor scalar part is exactly 0) and on every
// axis-aligned frame with both handedness values.
#include <gtest/gtest.h>

#include "pipelines/motor/motor_kernels.h"
#include "pipelines/motor/motor_vertices.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

struct Decoded {
  glm::vec3 normal, tangent;
  float w;
};

// Runs the rigid vertex kernel with the identity motor on vertex `v` of an interleaved stream.
Decoded decode(const std::vector<float>& data, size_t v) {
  const float* f = &data[v * motor::kFloatsPerVertex];
  const MK::mat3x4 r = mk().motorRigidVertex(Motor(1.0f), 1.0f, MK::vec3(f[0], f[1], f[2]),
                                             MK::vec4(f[3], f[4], f[5], f[6]));
  return {glm::normalize(glm::vec3(r[1].x, r[1].y, r[1].z)),
          glm::normalize(glm::vec3(r[2].x, r[2].y, r[2].z)), r[2].w};
}

void expectFrame(const Decoded& d, const glm::vec3& n, const glm::vec4& t, const std::string& what) {
  EXPECT_LT(glm::length(d.normal - glm::normalize(n)), 2e-4f) << what;
  EXPECT_LT(glm::length(d.tangent - glm::normalize(glm::vec3(t))), 2e-4f) << what;
  EXPECT_EQ(d.w, t.w < 0.0f ? -1.0f : 1.0f) << what;
}

}  // namespace

TEST(MotorFrames, TexturedBoxFramesDecodeToTheAuthoredFrames) {
  auto scene = loadScene("textured_box");
  ASSERT_TRUE(scene) << scene.error();
  int zeroScalar = 0;
  for (const Mesh& mesh : scene->meshes)
    for (const Primitive& p : mesh.primitives) {
      ASSERT_EQ(p.tangents.size(), p.positions.size());
      const motor::VertexStream s = motor::interleaveVertices(p);
      ASSERT_EQ(s.data.size(), p.positions.size() * motor::kFloatsPerVertex);
      zeroScalar += s.zeroScalarFrames;
      for (size_t v = 0; v < p.positions.size(); ++v) {
        expectFrame(decode(s.data, v), p.normals[v], p.tangents[v], "vertex " + std::to_string(v));
        EXPECT_EQ(s.data[v * 9 + 7], p.uv0[v].x);
        EXPECT_EQ(s.data[v * 9 + 8], p.uv0[v].y);
      }
    }
  // The box has faces whose frame is a half turn of the basis frame: the case the reference
  // implementation gets wrong. They must be present for this test to mean something.
  EXPECT_GT(zeroScalar, 0);
}

TEST(MotorFrames, EveryAxisAlignedFrameWithBothHandedness) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  Primitive p;
  for (const glm::vec3& n : axes)
    for (const glm::vec3& t : axes) {
      if (glm::dot(n, t) != 0.0f) continue;
      for (float w : {1.0f, -1.0f}) {
        p.positions.push_back(glm::vec3(0.0f));
        p.normals.push_back(n);
        p.tangents.emplace_back(t, w);
      }
    }
  ASSERT_EQ(p.positions.size(), 48u);
  const motor::VertexStream s = motor::interleaveVertices(p);
  EXPECT_GT(s.zeroScalarFrames, 0);
  for (size_t v = 0; v < p.positions.size(); ++v)
    expectFrame(decode(s.data, v), p.normals[v], p.tangents[v], "frame " + std::to_string(v));
}

TEST(MotorFrames, MissingTangentGetsThePerpendicularTheMatrixPipelineUses) {
  Primitive p;
  p.positions = {glm::vec3(0.0f), glm::vec3(1.0f)};
  p.normals = {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0)};
  const motor::VertexStream s = motor::interleaveVertices(p);
  // normalize(cross(n, |n.x| < 0.9 ? x : y)), w = +1; missing uv0 -> (0, 0).
  expectFrame(decode(s.data, 0), p.normals[0], glm::vec4(0, 1, 0, 1), "n = z");
  expectFrame(decode(s.data, 1), p.normals[1], glm::vec4(0, 0, 1, 1), "n = x");
  EXPECT_EQ(s.data[7], 0.0f);
  EXPECT_EQ(s.data[8], 0.0f);
}
