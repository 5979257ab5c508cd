#include "harness/render/rounding_magnitude.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "pipelines/scene/transform.h"

namespace mb {
namespace {

double maxNorm(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

// sqrt of the largest eigenvalue of A^T A, closed form for a symmetric 3x3 (the trigonometric
// solution of its characteristic cubic).
double largestSingularValue(const glm::dmat3& a) {
  const glm::dmat3 s = glm::transpose(a) * a;
  const double p1 = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
  const double q = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  if (p1 == 0.0) return std::sqrt(std::max({s[0][0], s[1][1], s[2][2]}));
  const double p2 = (s[0][0] - q) * (s[0][0] - q) + (s[1][1] - q) * (s[1][1] - q) + (s[2][2] - q) * (s[2][2] - q) + 2 * p1;
  const double p = std::sqrt(p2 / 6.0);
  const glm::dmat3 b = (1.0 / p) * (s - q * glm::dmat3(1.0));
  const double r = std::clamp(glm::determinant(b) / 2.0, -1.0, 1.0);
  return std::sqrt(std::max(0.0, q + 2.0 * p * std::cos(std::acos(r) / 3.0)));
}

std::vector<double> roundingMagnitudes(const Scene& scene, const std::vector<AnimState>& poses,
                                       const std::vector<View>& views) {
  std::vector<size_t> first;  // index of each mesh's first primitive
  std::vector<double> magnitude;
  for (const Mesh& mesh : scene.meshes) {
    first.push_back(magnitude.size());
    for (const Primitive& p : mesh.primitives) {
      double m = 0;
      for (const glm::vec3& v : p.positions) m = std::max(m, maxNorm(glm::dvec3(v)));
      magnitude.push_back(m);
    }
  }
  const std::vector<int> order = nodesInDrawOrder(scene);
  for (size_t k = 0; k < poses.size() && k < views.size(); ++k) {
    const std::vector<glm::mat4> world = worldMatrices(scene, samplePose(scene, poses[k]));
    const glm::dmat4 toView = glm::inverse(glm::dmat4(trsMatrix(TRS{views[k].eye, views[k].orientation, glm::vec3(1.0f)})));
    for (int n : order) {
      const Node& node = scene.nodes[size_t(n)];
      if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size() || size_t(n) >= world.size()) continue;
      std::vector<glm::dmat4> draws;
      if (node.instances.empty()) draws.push_back(glm::dmat4(world[size_t(n)]));
      for (const TRS& i : node.instances) draws.push_back(glm::dmat4(world[size_t(n)]) * glm::dmat4(trsMatrix(i)));
      const std::vector<Primitive>& prims = scene.meshes[size_t(node.mesh)].primitives;
      for (size_t q = 0; q < prims.size(); ++q) {
        double& m = magnitude[first[size_t(node.mesh)] + q];
        for (const glm::dmat4& d : draws) {
          const double sigma = largestSingularValue(glm::dmat3(d));
          if (!(sigma > 0) || !std::isfinite(sigma)) continue;
          const glm::dmat4 dv = toView * d;
          double largest = 0;
          for (const glm::vec3& p : prims[q].positions) {
            const glm::dvec4 h(glm::dvec3(p), 1.0);
            largest = std::max({largest, maxNorm(glm::dvec3(d * h)), maxNorm(glm::dvec3(dv * h))});
          }
          if (std::isfinite(largest)) m = std::max(m, largest / sigma);
        }
      }
    }
  }
  return magnitude;
}

}  // namespace mb
