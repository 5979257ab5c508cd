// Skinned test files built from the built-in skinned_tube (tests/cli): written to a folder, as
// the commands read them.
#pragma once
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/compressed_gltf.h"

namespace mbtest {

// skinned_tube with its mesh and skin drawn by a second node too: the motor-blend reference
// cannot stand for the method (PreSkinnedScene: a skinned mesh drawn by more than one node).
inline std::filesystem::path twiceDrawnTube(const std::filesystem::path& dir) {
  auto glb = mb::builtinSceneGlb("skinned_tube");
  EXPECT_TRUE(glb) << glb.error();
  mb::compressed::Glb g = mb::compressed::splitGlb(*glb);
  for (size_t n = 0; n < g.json["nodes"].size(); ++n)
    if (g.json["nodes"][n].contains("skin")) {
      nlohmann::json twin = {{"mesh", g.json["nodes"][n]["mesh"]}, {"skin", g.json["nodes"][n]["skin"]}};
      g.json["nodes"].push_back(twin);
      g.json["scenes"][0]["nodes"].push_back(g.json["nodes"].size() - 1);
      break;
    }
  const mb::compressed::Bytes bytes = mb::compressed::joinGlb(g);
  const std::filesystem::path file = dir / "tube_twice.glb";
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return file;
}

}  // namespace mbtest
