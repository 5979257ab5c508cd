#include "pipelines/scene/curved_space.h"

#include <cmath>

namespace mb {

int kappaOf(Space space) {
  return space == Space::Spherical ? 1 : (space == Space::Hyperbolic ? -1 : 0);
}

const char* spaceName(Space space) {
  switch (space) {
    case Space::Spherical: return "spherical (S3)";
    case Space::Hyperbolic: return "hyperbolic (H3)";
    default: return "Euclidean";
  }
}

glm::dmat4 elementaryMatrix(int kappa, int i, int j, double angle) {
  glm::dmat4 m(1.0);  // m[column][row]
  if (j < 3) {        // e_i turns towards e_j
    const double c = std::cos(angle), s = std::sin(angle);
    m[i][i] = c, m[j][j] = c, m[i][j] = s, m[j][i] = -s;
  } else if (kappa > 0) {  // the origin e_w turns towards e_i
    const double c = std::cos(angle), s = std::sin(angle);
    m[i][i] = c, m[3][3] = c, m[3][i] = s, m[i][3] = -s;
  } else if (kappa < 0) {  // boost: the origin moves to (sinh, cosh) along e_i
    const double c = std::cosh(angle), s = std::sinh(angle);
    m[i][i] = c, m[3][3] = c, m[3][i] = s, m[i][3] = s;
  } else {  // Euclidean translation
    m[3][i] = angle;
  }
  return m;
}

glm::dmat4 cameraToWorld(const CurvedScene& scene, double t) {
  glm::dmat4 m(1.0);
  const int k = kappaOf(scene.space);
  for (const CurvedMove& mv : scene.camera) m = m * elementaryMatrix(k, mv.i, mv.j, mv.angle0 + mv.rate * t);
  return m;
}

}  // namespace mb
