// `report` exits 1 when a scene failed and shows each failure's reason
// in report.md and report.html (not "failed" and "-"); a worker that dies is named with the step
// it was on; frames whose drawn pixels fail compare's check are marked, with compare's reason
// for the same frame; skinned frames are judged against their own skinning method's reference,
// and a frame that cannot be is counted with its reason.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "harness/render/image_metrics.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/png_pixels.h"
#include "tests/support/skin_test_files.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::readText;
using mb::cli_test::runMb;

std::string htmlEscaped(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

using mb::cli_test::nonBackground;

// A corrupt .glb beside skinned_tube and tube_twice (skinned_tube with its mesh drawn by a second
// node), matrix vs motor, whose candy_wrapper frames draw shapes of different size where linear
// blend skinning collapses the ring. skinned_tube's frames are judged against motor's own method's
// reference and pass; tube_twice's cannot be (its mesh cannot be pre-skinned for the motor blend):
// counted as not judged with the reason, and judged against matrix, the strict reading, which
// marks the frames apart FAILED, with compare's reason for the same frame.
TEST(CliReportFailures, FailedSceneExitsOneWithItsReasonAndFramesAreMarked) {
  const fs::path dir = mb::cli_test::scratchDir("report_failures");
  const fs::path bad = dir / "broken.glb";
  std::ofstream(bad, std::ios::binary) << "glTF, then not a GLB header at all";
  const fs::path twice = mbtest::twiceDrawnTube(dir);
  const fs::path out = dir / "out";
  const auto r = runMb("report " + quoted(bad) + " skinned_tube " + quoted(twice) + " --anim candy_wrapper "
                       "--pipelines matrix,motor --size 96x72 --frames 0 --no-bench --no-isa --no-plots -o " + quoted(out));
  EXPECT_EQ(r.rc, 1) << r.out;
  const json rep = readJson(out / "report.json");
  ASSERT_FALSE(rep.is_discarded()) << r.out;
  ASSERT_EQ(rep["scenes"].size(), 3u);
  const json& broken = rep["scenes"][0];
  ASSERT_EQ(broken["status"], "failed");
  ASSERT_TRUE(broken["error"].is_string());
  const std::string why = broken["error"];
  EXPECT_TRUE(contains(why, "broken.glb")) << why;
  // The reason reaches stderr, the failure list and the scenes table of both documents.
  const std::string id = broken["id"];
  EXPECT_TRUE(contains(r.out, "1 scene(s) not measured fully (exit 1)")) << r.out;
  EXPECT_TRUE(contains(r.out, "report:   " + id + " (failed): " + why + "\n")) << r.out;
  const std::string md = readText(out / "report.md"), html = readText(out / "report.html");
  EXPECT_TRUE(contains(md, id + " (failed): " + why)) << md.substr(0, 3000);
  EXPECT_TRUE(contains(md, "| failed: " + why)) << "the scenes table row shows the reason";
  EXPECT_TRUE(contains(html, htmlEscaped(id + " (failed): " + why))) << html.substr(0, 3000);
  EXPECT_FALSE(contains(md, "worker exit status")) << md.substr(0, 3000);

  // Both tubes were measured: their frames carry the drawn-pixel check, recomputed here from the
  // PNGs the report wrote and the counts of the reference that judged them.
  int apart = 0, failedFrames = 0;
  std::string failedTime, failedReason;
  for (size_t s = 1; s < 3; ++s) {
    const json& tube = rep["scenes"][s];
    ASSERT_EQ(tube["status"], "ok") << tube.dump(1).substr(0, 2000);
    const bool own = s == 1;  // skinned_tube: its own method's reference; tube_twice: none
    for (const json& f : tube["frames"]) {
      const int64_t a = nonBackground(out / f["images"]["matrix"].get<std::string>());
      const int64_t b = nonBackground(out / f["images"]["motor"].get<std::string>());
      ASSERT_EQ(f["drawnPixels"]["matrix"], a);
      const json& c = f["drawnCheck"]["motor"];
      const json& j = f["skinJudgement"]["motor"];
      ASSERT_TRUE(c.is_object() && j.is_object()) << f.dump(1);
      EXPECT_EQ(j["vsMatrix"]["drawnPixels"], b);
      EXPECT_EQ(j["vsMatrix"]["referenceDrawnPixels"], a);
      const bool fromMatrix = std::llabs(a - b) > 0.01 * double(std::max(a, b));
      apart += fromMatrix;
      if (own) {
        EXPECT_EQ(c["against"], "motor-blend reference");
        const int64_t ref = j["vsReference"]["referenceDrawnPixels"];
        EXPECT_EQ(c["failed"], std::llabs(ref - b) > 0.01 * double(std::max(ref, b))) << ref << " vs " << b;
        EXPECT_EQ(c["failed"], false) << "motor left its own method's reference: " << c.dump();
        EXPECT_EQ(c["skinningMethodNote"], true);
        continue;
      }
      EXPECT_EQ(j["judged"], false);
      EXPECT_EQ(j["why"], "a skinned mesh drawn by more than one node");
      EXPECT_EQ(c["against"], "matrix");
      EXPECT_EQ(c["failed"], fromMatrix) << a << " vs " << b;
      if (!fromMatrix) continue;
      ++failedFrames;
      failedReason = c["reason"];
      char t[32];
      std::snprintf(t, sizeof t, "%.9g", f["time"].get<double>());
      failedTime = t;
      EXPECT_TRUE(contains(failedReason, "(matrix " + std::to_string(a) + ", motor " + std::to_string(b) + ": "))
          << failedReason;
      // The per-scene metrics table: the frame's row for motor ends with its drawn-pixel check.
      EXPECT_TRUE(contains(md, " | FAILED: " + failedReason + " |")) << failedReason;
    }
  }
  ASSERT_GT(apart, 2) << "candy_wrapper no longer draws shapes of different size from matrix";
  ASSERT_GT(failedFrames, 0);
  // The frames not judged are counted, with their reason, and the marks are in the summary.
  const json& images = rep["summary"]["images"]["motor"];
  EXPECT_EQ(images["notJudgedFrames"], 3);
  EXPECT_EQ(images["judgedAgainst"], json({{"motor-blend reference", 3}}));
  EXPECT_EQ(images["drawnCheckFailed"], failedFrames);
  ASSERT_EQ(images["notJudged"].size(), 3u);
  EXPECT_TRUE(contains(images["notJudged"][0].get<std::string>(),
                       ": not judged against the motor-blend reference: a skinned mesh drawn by more than one node"));
  EXPECT_EQ(rep["figures"]["image.frames_not_judged.motor"]["value"], 3);
  EXPECT_TRUE(contains(md, "\">3 frames</span> not judged (first: tube_twice t=0: not judged against the motor-blend "
                          "reference: a skinned mesh drawn by more than one node)")) << "the answer row says so";
  // compare on the same frame fails with the same reason, with no threshold given.
  const auto cmp = runMb("compare " + quoted(twice) + " --anim candy_wrapper --pipelines matrix,motor --time " +
                         failedTime + " --size 96x72 -o " + quoted(dir / "cmp"));
  EXPECT_EQ(cmp.rc, 1) << cmp.out;
  EXPECT_TRUE(contains(cmp.out, "-> FAIL (" + failedReason)) << cmp.out;
  fs::remove_all(dir);
}

// A worker killed (here by --timeout, 3 s into skinned_tube's 9 pipelines x (3 images + a
// 24-frame loop) at 800x600, far more than 3 s of work) is named with the step it was on, not
// only with how it ended.
TEST(CliReportFailures, DeadWorkerIsNamedWithItsLastStep) {
  const fs::path dir = mb::cli_test::scratchDir("report_dead_worker");
  const auto r = runMb("report skinned_tube --timeout 3 --size 800x600 --frames 0 --no-bench --no-isa --no-plots -o " + quoted(dir));
  EXPECT_EQ(r.rc, 1) << r.out;
  const json rep = readJson(dir / "report.json");
  ASSERT_FALSE(rep.is_discarded()) << r.out;
  const json& s = rep["scenes"][0];
  ASSERT_EQ(s["status"], "failed") << "the scene finished within 3 s: " << s.dump(1).substr(0, 1000);
  const std::string why = s["error"];
  EXPECT_EQ(why.rfind("worker timed out after 3 s while ", 0), 0u) << why;
  // The step is the worker's last progress line, which the run printed too.
  const std::string step = why.substr(std::string("worker timed out after 3 s while ").size(),
                                      why.find(" (its message") - std::string("worker timed out after 3 s while ").size());
  EXPECT_TRUE(contains(r.out, "skinned_tube: " + step + "\n")) << step << "\n" << r.out;
  EXPECT_TRUE(contains(readText(dir / "report.md"), why)) << why;
  fs::remove_all(dir);
}

}  // namespace
