// Files tinygltf 2.7 refuses without a message get the reason from the loader's own reading
// of the glTF 2.0 schema's required properties, naming the object.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipelines/scene/loader.h"
#include "pipelines/scene/repair/preflight.h"

namespace mb {
namespace {

std::vector<uint8_t> bytesOf(const std::string& s) { return {s.begin(), s.end()}; }

const char* kPrerelease =
    R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"name":"root"}],"skins":[{"jointNames":["root"]}]})";

TEST(LoaderRefusal, PrereleaseSkinSaysSo) {
  auto scene = loadGltfMemory(bytesOf(kPrerelease), "old.gltf", "");
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error(), "old.gltf: skin 0 has 'jointNames' but no 'joints': glTF 2.0 pre-release file");
}

TEST(LoaderRefusal, SkinWithoutJointsNamesTheProperty) {
  auto scene = loadGltfMemory(bytesOf(R"({"asset":{"version":"2.0"},"skins":[{"name":"s"},{}]})"), "s.gltf", "");
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error(), "s.gltf: skin 0 has no 'joints' (required by glTF 2.0)");
}

TEST(LoaderRefusal, ExplainsEachRequiredPropertyInSchemaOrder) {
  EXPECT_EQ(explainRefusal(bytesOf(R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"type":"VEC3"}]})")),
            "accessor 0 has no 'count' (required by glTF 2.0)");
  EXPECT_EQ(explainRefusal(bytesOf(R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{}},{}]}]})")),
            "mesh 0 primitive 1 has no 'attributes' (required by glTF 2.0)");
  EXPECT_EQ(explainRefusal(bytesOf(R"({"asset":{"version":"2.0"},"animations":[{"channels":[{"sampler":0}],"samplers":[]}]})")),
            "animation 0 channel 0 has no 'target' (required by glTF 2.0)");
  EXPECT_EQ(explainRefusal(bytesOf(R"({"asset":{"version":"2.0"},"cameras":[3]})")), "camera 0 is not an object");
  EXPECT_EQ(explainRefusal(bytesOf(R"({"asset":{"version":"2.0"},"skins":[{"joints":[0]}]})")), "");
  EXPECT_EQ(explainRefusal(bytesOf("not json")), "");
}

}  // namespace
}  // namespace mb
