// Compressed files through the command: inspect reports the decode of a Draco and a meshopt file (text
// and --json: compressed and decoded bytes), and render, compare and time refuse a file whose
// every primitive is skipped (exit 2, with the reason) instead of writing a blank image.
#include <gtest/gtest.h>

#include <fstream>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/compressed_gltf.h"

using namespace mb;
using namespace mb::cli_test;

namespace {

std::filesystem::path write(const std::filesystem::path& dir, const std::string& name, const std::vector<uint8_t>& b) {
  std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
  return dir / name;
}

TEST(CliCompressed, InspectReportsTheDecode) {
  const auto dir = scratchDir("compressed_inspect");
  auto glb = builtinSceneGlb("normal_torus");
  ASSERT_TRUE(glb) << glb.error();
  const auto draco = write(dir, "torus-draco.glb", compressed::dracoCompressed(*glb));
  const auto meshopt = write(dir, "torus-meshopt.glb", compressed::meshoptCompressed(*glb));
  // The sizes the loader measured, as the reference for the printed line.
  const Scene d = *loadGltfFile(draco.string()), m = *loadGltfFile(meshopt.string());
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "inspect " + quoted(draco) + " " + quoted(meshopt) + " --json " +
                           quoted(dir / "i.json"),
                       &out),
            0)
      << out;
  const std::string dracoLine = "  compression KHR_draco_mesh_compression 1 primitives, " +
                                std::to_string(d.compression.dracoCompressedBytes) + " compressed -> " +
                                std::to_string(d.compression.dracoDecodedBytes) + " decoded bytes\n";
  const std::string meshoptLine = "  compression meshopt " + std::to_string(m.compression.meshoptViews) + " bufferViews, " +
                                  std::to_string(m.compression.meshoptCompressedBytes) + " compressed -> " +
                                  std::to_string(m.compression.meshoptDecodedBytes) + " decoded bytes\n";
  EXPECT_NE(out.find(dracoLine), std::string::npos) << out;
  EXPECT_NE(out.find(meshoptLine), std::string::npos) << out;
  std::printf("%s", (dracoLine + meshoptLine).c_str());
  // normal_torus: one primitive of 4 decoded attributes (POSITION, NORMAL, TANGENT, TEXCOORD_0:
  // 3 + 3 + 4 + 2 floats per vertex) plus 32-bit indices.
  const Primitive& p = d.meshes[0].primitives[0];
  EXPECT_EQ(d.compression.dracoDecodedBytes, p.positions.size() * 12 * 4 + p.indices.size() * 4);
  const nlohmann::json j = readJson(dir / "i.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["files"][0]["compression"]["draco"]["primitives"], 1);
  EXPECT_EQ(j["files"][0]["compression"]["draco"]["decodedBytes"], d.compression.dracoDecodedBytes);
  EXPECT_EQ(j["files"][0]["compression"]["draco"]["compressedBytes"], d.compression.dracoCompressedBytes);
  EXPECT_EQ(j["files"][1]["compression"]["meshopt"]["bufferViews"], m.compression.meshoptViews);
  EXPECT_EQ(j["files"][1]["compression"]["meshopt"]["decodedBytes"], m.compression.meshoptDecodedBytes);
  EXPECT_EQ(j["files"][0]["notDrawn"], nullptr);
}

TEST(CliCompressed, NothingToDrawExitsTwoWithTheReason) {
  const auto dir = scratchDir("compressed_blank");
  hostile::Doc d;
  const int pos = d.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  d.mesh({{"attributes", {{"POSITION", pos}}}, {"mode", 1}});
  d.node({{"mesh", 0}});
  d.scene({0});
  d.finish();
  const auto lines = write(dir, "lines.glb", hostile::toGlb(d));
  const std::string why = "lines.glb: nothing to draw: only points/lines (1 skipped: 1 x mode 1 (lines) not supported)";
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "render " + quoted(lines) + " -o " + quoted(dir / "x.png"), &out), 2) << out;
  EXPECT_NE(out.find(why), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "compare " + quoted(lines) + " -o " + quoted(dir / "cmp"), &out), 2) << out;
  EXPECT_NE(out.find(why), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "time " + quoted(lines) + " --frames 1 --warmup 0", &out), 2) << out;
  EXPECT_NE(out.find(why), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "inspect " + quoted(lines), &out), 0) << out;
  EXPECT_NE(out.find("NOT DRAWN   only points/lines"), std::string::npos) << out;
}

}  // namespace
