// A scene loaded from a file's bytes in a test: a load that fails fails the test, with the
// loader's message, and gives an empty scene.
#pragma once
#include <string>

#include <gtest/gtest.h>

#include "pipelines/scene/loader.h"
#include "tests/hostile/hostile_cases.h"

namespace mb::scene_test {

inline Scene load(const hostile::Bytes& bytes, const std::string& name) {
  auto s = loadGltfMemory(bytes, name);
  EXPECT_TRUE(s) << s.error();
  return s ? s.take() : Scene{};
}

}  // namespace mb::scene_test
