#include "pipelines/scene/transform.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "pipelines/scene/similarity_tolerance.h"

namespace mb {

glm::mat4 trsMatrix(const TRS& trs) {
  glm::mat3 r = glm::mat3_cast(trs.rotation);
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c) m[c] = glm::vec4(r[c] * trs.scale[c], 0.0f);
  m[3] = glm::vec4(trs.translation, 1.0f);
  return m;
}

bool decomposeMatrix(const glm::mat4& m, TRS* out) {
  constexpr float kTol = 1e-4f;
  bool exact = std::fabs(m[0][3]) < kTol && std::fabs(m[1][3]) < kTol &&
               std::fabs(m[2][3]) < kTol && std::fabs(m[3][3] - 1.0f) < kTol;
  out->translation = glm::vec3(m[3]);
  glm::vec3 col[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
  glm::vec3 scale(glm::length(col[0]), glm::length(col[1]), glm::length(col[2]));
  if (!(scale.x > 0.0f && scale.y > 0.0f && scale.z > 0.0f)) {
    out->rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    out->scale = scale;
    return false;
  }
  // Shear: columns not mutually orthogonal.
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::fabs(glm::dot(col[i], col[j])) > float(kSimilarityTolerance) * scale[i] * scale[j]) exact = false;
  if (glm::determinant(glm::mat3(col[0], col[1], col[2])) < 0.0f) scale.x = -scale.x;
  // Gram-Schmidt so the rotation is proper even when the input is slightly sheared.
  glm::vec3 x = col[0] / scale.x;
  glm::vec3 yRaw = col[1] - x * glm::dot(x, col[1]);
  if (!(glm::length(yRaw) > 1e-6f * scale.y)) {  // parallel axes: no rotation recoverable
    out->rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    out->scale = scale;
    return false;
  }
  glm::vec3 y = glm::normalize(yRaw);
  glm::vec3 z = glm::cross(x, y);
  out->rotation = glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
  out->scale = scale;
  return exact;
}

}  // namespace mb
