// `motorbench report` end to end: the report on a small built-in scene writes report.json with
// the keys documented in README.md (section Report), its images exist and are referenced by
// relative paths, a bad file in the arguments is recorded with its error while the run goes on,
// a missing Python is reported, and bad usage (a missing --bench-json file included) is refused
// before the run. Never asserts measured timings or ratios, only that they are there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/cli_test_support.h"
#include "pipelines/pipeline.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::contains;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::readText;
using mb::cli_test::runCommand;
using mb::cli_test::runMb;

// Runs the report on a file that is not JSON, then textured_box; the run goes on past the bad file.
void runWithBadFileFirst(const fs::path& dir, const fs::path& out, std::string& log) {
  const fs::path bad = dir / "broken.gltf";
  std::ofstream(bad) << "{ this is not json";
  // The bad file first: the good scene after it must still be measured.
  const int rc = runCommand(motorbench() + "report " + quoted(bad) + " textured_box -o " + quoted(out) +
                                " --no-bench --no-isa --frames 3 --size 64x48 --jobs 2",
                            &log);
  // Written in full, but a scene failed: exit 1, as inspect.
  ASSERT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("[2/2] textured_box: rendering motor t=0"), std::string::npos) << log;
}

// report.json: the documented top-level and machine keys, every pipeline, both scenes.
void checkReportKeys(const json& r, const std::string& log) {
  ASSERT_FALSE(r.is_discarded()) << log;
  for (const char* key : {"schema", "tool", "machine", "settings", "summary", "scenes", "opsPerVertex", "kernels",
                          "plots", "files"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(r["schema"], "motorbench-report/1");
  for (const char* key : {"cpu", "logicalCores", "gl", "lpNumThreads"}) EXPECT_TRUE(r["machine"].contains(key)) << key;
  EXPECT_EQ(r["settings"]["pipelines"], json(mb::pipelineNames()));  // every registered one, matrix first
  EXPECT_EQ(r["settings"]["width"], 64);
  ASSERT_EQ(r["scenes"].size(), 2u);
}

// The bad file: failed, its error names it.
void checkBrokenScene(const json& broken) {
  EXPECT_EQ(broken["status"], "failed");
  ASSERT_TRUE(broken["error"].is_string());
  EXPECT_NE(broken["error"].get<std::string>().find("broken.gltf"), std::string::npos) << broken["error"];
}

// textured_box: loaded, with its sections; each frame's images and diff exist at relative paths, with metrics.
void checkBoxFrames(const json& box, const fs::path& out) {
  EXPECT_EQ(box["id"], "textured_box");
  EXPECT_EQ(box["status"], "ok") << box.dump(1);
  for (const char* key : {"stats", "vertexMix", "times", "frames", "pipelines", "timing", "opsPerVertex"})
    EXPECT_TRUE(box.contains(key)) << key;
  ASSERT_FALSE(box["frames"].empty());
  for (const json& f : box["frames"]) {
    for (const char* p : {"matrix", "motor"}) {
      ASSERT_TRUE(f["images"][p].is_string()) << f.dump();
      const std::string rel = f["images"][p];
      EXPECT_FALSE(fs::path(rel).is_absolute()) << rel;
      EXPECT_TRUE(fs::is_regular_file(out / rel)) << rel;
    }
    ASSERT_TRUE(f["diffs"]["motor"].is_string());
    EXPECT_TRUE(fs::is_regular_file(out / f["diffs"]["motor"].get<std::string>()));
    for (const char* key : {"rmse", "psnr", "identical", "maxError", "fractionOver1"})
      EXPECT_TRUE(f["metrics"]["motor"].contains(key)) << key;
  }
}

// Memory as uploaded: 12 vs 9 floats per vertex on this normal-mapped box; fallbacks, conversion, timing and ops.
void checkBoxPipelines(const json& box) {
  const json& mm = box["pipelines"]["matrix"]["memory"];
  const json& qm = box["pipelines"]["motor"]["memory"];
  for (const char* key : {"bytesPerVertex", "floatsPerVertex", "floatsPerTransform", "floatsPerJoint", "vertexBytes"})
    EXPECT_TRUE(mm.contains(key) && qm.contains(key)) << key;
  EXPECT_EQ(mm["floatsPerVertex"], 12.0);
  EXPECT_EQ(qm["floatsPerVertex"], 9.0);
  EXPECT_TRUE(box["pipelines"]["motor"].contains("fallbacks"));
  EXPECT_TRUE(box["pipelines"]["motor"]["conversionMs"]["median"].is_number());
  EXPECT_TRUE(box["timing"]["ratio_motor_matrix"].is_number()) << box["timing"].dump();
  EXPECT_TRUE(box["opsPerVertex"]["motor"]["counted"]["mul"].is_number());
  EXPECT_EQ(box["stats"]["geometry"]["vertices"], 24);
}

// Kernels skipped (--no-isa); one scene failed, one ok.
void checkKernelsAndSummary(const json& r) {
  EXPECT_EQ(r["kernels"]["source"], "skipped");
  EXPECT_TRUE(r["kernels"]["error"].is_string());
  EXPECT_EQ(r["summary"]["failed"], 1);
  EXPECT_EQ(r["summary"]["ok"], 1);
}

// The documents: relative image paths, the failure named.
void checkDocuments(const json& r, const fs::path& out) {
  for (const char* doc : {"report.md", "report.html"}) {
    const std::string text = readText(out / doc);
    EXPECT_NE(text.find("images/textured_box/t0_motor.png"), std::string::npos) << doc;
    EXPECT_EQ(text.find(out.string()), std::string::npos) << doc << " holds an absolute path";
    EXPECT_NE(text.find("broken.gltf"), std::string::npos) << doc;
    // A summary median says how many scenes it covers (one scene loaded here), and
    // the glossary explains every counter and the heat maps' colours.
    EXPECT_NE(text.find("36 over 1 scene"), std::string::npos) << doc << ": bytes per vertex without its scene count";
    EXPECT_NE(text.find("Glossary"), std::string::npos) << doc;
    EXPECT_NE(text.find("zeroScalarFrames"), std::string::npos) << doc;
    EXPECT_NE(text.find("Diff heat maps:"), std::string::npos) << doc;
  }
  EXPECT_TRUE(r["glossary"]["PipelineStats"].contains("zeroScalarFrames")) << r["glossary"].dump();
}

// The ops step (a minute or more) reports progress up to its last item; every frame
// records the pixels each pipeline drew (the box covers part of the image, never all of it).
void checkProgressAndDrawnPixels(const json& box, const std::string& log) {
  EXPECT_TRUE(std::regex_search(log, std::regex("report: counting ops per vertex: ([0-9]+)/\\1 kernels and shader variants")))
      << log;
  for (const json& f : box["frames"])
    for (const std::string& p : mb::pipelineNames()) {
      ASSERT_TRUE(f["drawnPixels"][p].is_number_integer()) << f.dump();
      EXPECT_GT(f["drawnPixels"][p].get<int64_t>(), 0) << p;
      EXPECT_LT(f["drawnPixels"][p].get<int64_t>(), 64 * 48) << p;
    }
}

// image_error is grouped, one bar per compared pipeline on the scene, each at its
// own x, read from the data plots/index.json records (when matplotlib is there).
void checkImageErrorBars(const json& r, const fs::path& out) {
  if (r["plots"]["available"] == true) {
    const json index = readJson(out / "plots" / "index.json");
    ASSERT_FALSE(index.is_discarded());
    json bars;
    for (const json& f : index["files"])
      if (f["name"] == "image_error") bars = f["bars"];
    ASSERT_TRUE(bars.is_array()) << index.dump(1);
    std::set<std::string> series;
    std::set<double> xs;
    for (const json& b : bars)
      if (b["panel"] == "psnr" && b["label"] == "textured_box") series.insert(b["series"].get<std::string>()), xs.insert(b["x"].get<double>());
    std::vector<std::string> compared = mb::pipelineNames();
    compared.erase(compared.begin());  // the baseline
    EXPECT_EQ(series, std::set<std::string>(compared.begin(), compared.end())) << bars.dump();
    EXPECT_EQ(xs.size(), compared.size()) << bars.dump();
  }
}

TEST(CliReport, SmallSceneWithBadFileWritesDocumentedReport) {
  const fs::path dir = mb::cli_test::scratchDir("report");
  const fs::path out = dir / "out";
  std::string log;
  ASSERT_NO_FATAL_FAILURE(runWithBadFileFirst(dir, out, log));
  const json r = readJson(out / "report.json");
  ASSERT_NO_FATAL_FAILURE(checkReportKeys(r, log));
  ASSERT_NO_FATAL_FAILURE(checkBrokenScene(r["scenes"][0]));
  const json& box = r["scenes"][1];
  ASSERT_NO_FATAL_FAILURE(checkBoxFrames(box, out));
  checkBoxPipelines(box);
  checkKernelsAndSummary(r);
  checkDocuments(r, out);
  ASSERT_NO_FATAL_FAILURE(checkProgressAndDrawnPixels(box, log));
  ASSERT_NO_FATAL_FAILURE(checkImageErrorBars(r, out));
  EXPECT_EQ(r["diffLegend"]["stops"].size(), 7u);
  fs::remove_all(dir);
}

TEST(CliReport, MissingPythonIsReportedAndTheRunGoesOn) {
  const fs::path dir = mb::cli_test::scratchDir("report_nopython");
  std::string log;
  const int rc = runCommand(motorbench() + "report textured_box -o " + quoted(dir) +
                                " --no-bench --no-isa --frames 0 --size 32x24 --python /nonexistent/python3",
                            &log);
  ASSERT_EQ(rc, 0) << log;
  const json r = readJson(dir / "report.json");
  ASSERT_FALSE(r.is_discarded());
  EXPECT_FALSE(r["plots"]["available"].get<bool>());
  ASSERT_TRUE(r["plots"]["error"].is_string());
  EXPECT_NE(readText(dir / "report.md").find("No plots"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir / "report.html"));
  fs::remove_all(dir);
}

TEST(CliReport, RejectsBadUsage) {
  std::string log;
  EXPECT_EQ(runCommand(motorbench() + "report textured_box", &log), 2) << log;  // no -o
  EXPECT_EQ(runCommand(motorbench() + "report -o /tmp/x --jobs 0", &log), 2) << log;
  EXPECT_EQ(runCommand(motorbench() + "report -o /tmp/x --pipelines nosuch", &log), 2) << log;
  EXPECT_EQ(runCommand(motorbench() + "report -o /tmp/x --bogus 1", &log), 2) << log;
}

// A missing --bench-json file is refused before the run starts.
TEST(CliMessages, ReportBenchJsonMissingFailsBeforeTheRun) {
  const fs::path dir = mb::cli_test::scratchDir("messages_benchjson");
  const auto r = runMb("report normal_torus -o " + quoted(dir / "r") + " --bench-json " + quoted(dir / "missing.json"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--bench-json " + (dir / "missing.json").string() + ": no such file")) << r.out;
  EXPECT_FALSE(contains(r.out, "[1/1]")) << "the run started:\n" << r.out;
  EXPECT_FALSE(fs::exists(dir / "r" / "report.json"));
  fs::remove_all(dir);
}

}  // namespace
