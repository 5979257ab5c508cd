// Procedural textures for the built-in scenes.
#include <cmath>

#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

std::vector<uint8_t> bumpNormalMap(int size, int periodsU, int periodsV, float strength) {
  const float kTwoPi = 6.28318530718f;
  std::vector<uint8_t> out(size_t(size) * size_t(size) * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float u = (x + 0.5f) / float(size), v = (y + 0.5f) / float(size);
      // h = sin(2 pi pu u) sin(2 pi pv v); the normal is (-dh/du, -dh/dv, 1) scaled.
      float su = std::sin(kTwoPi * periodsU * u), cu = std::cos(kTwoPi * periodsU * u);
      float sv = std::sin(kTwoPi * periodsV * v), cv = std::cos(kTwoPi * periodsV * v);
      glm::vec3 n = glm::normalize(glm::vec3(-strength * periodsU * cu * sv, -strength * periodsV * su * cv, 1.0f));
      uint8_t* p = &out[(size_t(y) * size_t(size) + size_t(x)) * 4];
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround((n[c] * 0.5f + 0.5f) * 255.0f));
      p[3] = 255;
    }
  return out;
}

std::vector<uint8_t> markedChecker(int size, int cells, glm::u8vec3 a, glm::u8vec3 b) {
  std::vector<uint8_t> out(size_t(size) * size_t(size) * 4);
  int cell = size / cells;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      glm::u8vec3 c = ((x / cell + y / cell) % 2) ? b : a;
      int lx = x % cell, ly = y % cell;  // "L" in cell (0,0): vertical bar + foot
      bool mark = x < cell && y < cell && ((lx > cell / 5 && lx < cell * 2 / 5 && ly > cell / 5 && ly < cell * 4 / 5) ||
                                           (ly > cell * 3 / 5 && ly < cell * 4 / 5 && lx > cell / 5 && lx < cell * 4 / 5));
      if (mark) c = glm::u8vec3(220, 30, 30);
      uint8_t* p = &out[(size_t(y) * size_t(size) + size_t(x)) * 4];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = 255;
    }
  return out;
}

}  // namespace mb
