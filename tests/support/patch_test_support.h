// Shared by the Bezier patch tests: the project's teapot control points and an independent
// double-precision reference evaluation (de Casteljau, not the Bernstein code under test).
#pragma once
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/builtin/bpt_reader.h"
#include "shaders/shim/patch.h"

namespace mbtest {

inline std::string teapotPath() { return std::string(MB_SOURCE_DIR) + "/pipelines/scene/data/teapot.bpt"; }

inline std::vector<glm::vec3> teapotPoints() {
  std::ifstream in(teapotPath(), std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  auto points = mb::parseBpt(s.str(), "teapot.bpt");
  EXPECT_TRUE(points.ok()) << points.error();
  return points ? points.take() : std::vector<glm::vec3>{};
}

// de Casteljau on one cubic.
inline glm::dvec3 casteljau(std::array<glm::dvec3, 4> p, double t) {
  for (int level = 3; level > 0; --level)
    for (int i = 0; i < level; ++i) p[size_t(i)] = (1.0 - t) * p[size_t(i)] + t * p[size_t(i) + 1];
  return p[0];
}

// Reference P(u, v) of patch `patch` (rows along u first, then across the rows in v).
inline glm::dvec3 referencePoint(const std::vector<glm::vec3>& pts, size_t patch, double u, double v) {
  std::array<glm::dvec3, 4> rows;
  for (int r = 0; r < 4; ++r) {
    std::array<glm::dvec3, 4> row;
    for (int c = 0; c < 4; ++c) row[size_t(c)] = glm::dvec3(pts[16 * patch + size_t(4 * r + c)]);
    rows[size_t(r)] = casteljau(row, u);
  }
  return casteljau(rows, v);
}

// The shader function's arguments for `patch`, in scalar type S.
template <class S>
std::array<typename mb::PatchShaders<S>::mat4x3, 4> patchRows(const std::vector<glm::vec3>& pts, size_t patch) {
  std::array<typename mb::PatchShaders<S>::mat4x3, 4> rows;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) rows[size_t(r)][c][k] = S(pts[16 * patch + size_t(4 * r + c)][k]);
  return rows;
}

template <class S>
typename mb::PatchShaders<S>::mat3 evaluate(const std::vector<glm::vec3>& pts, size_t patch, double u, double v) {
  auto r = patchRows<S>(pts, patch);
  mb::PatchShaders<S> shaders;
  return shaders.bezierPatch(r[0], r[1], r[2], r[3], typename mb::PatchShaders<S>::vec2(S(u), S(v)));
}

}  // namespace mbtest
