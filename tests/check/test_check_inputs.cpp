// What `check FILE|DIR|SCENE...` plans for a user's files (harness/check/check_inputs.h,
// golden.h): scene names from the path relative to the folder argument, folders sorted, a
// collision refused naming both files, and the poses of a file (rest and its first animation at
// 35 % and 70 %; an animation without duration posed once).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "harness/check/check_inputs.h"
#include "harness/check/golden.h"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  fs::path p = fs::temp_directory_path() / ("motorbench_check_inputs_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

void touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "{}";
}

TEST(CheckInputs, FolderFilesAreNamedByTheirPathInsideTheFolderSorted) {
  const fs::path root = scratch("folder");
  touch(root / "assets" / "z.glb");
  touch(root / "assets" / "props" / "Fox.GLB");
  touch(root / "assets" / "a b.gltf");
  touch(root / "assets" / "notes.txt");
  touch(root / "single.gltf");
  auto in = mb::check::checkInputs({(root / "assets").string(), (root / "single.gltf").string(), "normal_torus"});
  ASSERT_TRUE(in) << in.error();
  ASSERT_EQ(in->size(), 5u);
  const std::vector<std::pair<std::string, std::string>> want = {
      {"a b.gltf", "a_b_gltf"}, {"props/Fox.GLB", "props_Fox_GLB"}, {"z.glb", "z_glb"},
      {"single.gltf", "single_gltf"}, {"normal_torus", "normal_torus"}};
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ((*in)[i].shown, want[i].first) << i;
    EXPECT_EQ((*in)[i].scene, want[i].second) << i;
    EXPECT_EQ((*in)[i].file, i < 4) << i;
  }
  EXPECT_EQ((*in)[1].spec, (root / "assets" / "props" / "Fox.GLB").string());
  fs::remove_all(root);
}

TEST(CheckInputs, CollidingNamesAndBadArgumentsAreRefusedByName) {
  const fs::path root = scratch("collide");
  touch(root / "a" / "x.glb");
  touch(root / "a" / "x_glb.glb");
  touch(root / "b" / "x.glb");
  touch(root / "b" / "x.txt");
  fs::create_directories(root / "empty");
  auto in = mb::check::checkInputs({(root / "a" / "x.glb").string(), (root / "b" / "x.glb").string()});
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().find("would share the golden name 'x_glb'"), std::string::npos) << in.error();
  EXPECT_NE(in.error().find((root / "b" / "x.glb").string()), std::string::npos) << in.error();
  EXPECT_TRUE(mb::check::checkInputs({(root / "a").string()}));  // x_glb vs x_glb_glb: distinct
  in = mb::check::checkInputs({(root / "b" / "x.txt").string()});
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().find("not a .gltf or .glb file"), std::string::npos) << in.error();
  in = mb::check::checkInputs({(root / "empty").string()});
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().find("holds no .gltf or .glb files"), std::string::npos) << in.error();
  in = mb::check::checkInputs({(root / "nope.glb").string()});
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().find("no such file or folder"), std::string::npos) << in.error();
  fs::remove_all(root);
}

TEST(CheckInputs, AFileIsPosedAtRestAndTwiceInItsFirstAnimation) {
  mb::Scene scene;
  scene.animations.resize(2);
  scene.animations[0].name = "Walk cycle";
  scene.animations[0].duration = 2.0f;
  scene.animations[1].name = "Run";
  scene.animations[1].duration = 1.0f;
  auto poses = mb::check::posesFor(scene, mb::check::kMaxFileAnimations);
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses[0].name, "rest");
  EXPECT_EQ(poses[0].anim.anim, -1);
  EXPECT_EQ(poses[1].name, "Walk_cycle-t0.700");
  EXPECT_FLOAT_EQ(poses[1].anim.time, 0.7f);
  EXPECT_EQ(poses[2].name, "Walk_cycle-t1.400");
  EXPECT_EQ(mb::check::posesFor(scene).size(), 5u);  // a built-in: every animation
  scene.animations[0].duration = 0.0f;                 // both times 0: one pose
  poses = mb::check::posesFor(scene, mb::check::kMaxFileAnimations);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[1].name, "Walk_cycle-t0.000");
}

}  // namespace
