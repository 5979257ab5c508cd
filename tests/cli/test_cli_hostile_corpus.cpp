// Mixed corpus run: a directory holding good files (the built-in scenes, the
// shared real-world corpus) and bad ones (the hostile catalogue and a truncation series) is
// given to `motorbench inspect DIR --json`. The run must finish with exit 0 and report every
// file exactly once: good ones loaded with statistics, bad ones with an error naming them.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/cli_test_support.h"
#include "tests/hostile/hostile_cases.h"

namespace {

namespace fs = std::filesystem;
using namespace mb::hostile;

void writeFile(const fs::path& p, const Bytes& b) {
  fs::create_directories(p.parent_path());
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
  ASSERT_TRUE(f.good()) << p;
}

// Runs a shell command; returns its exit status (-1 when it did not exit normally) and output.
int run(const std::string& cmd, std::string* output) {
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) output->append(buf, n);
  int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

enum class Want { Loads, Fails };

// The inspect JSON key of a LoadStats counter (its member name).
std::string counterName(int mb::LoadStats::*c) {
  using S = mb::LoadStats;
  const std::pair<int S::*, const char*> names[] = {
      {&S::flatNormalsGenerated, "flatNormalsGenerated"}, {&S::tangentsGenerated, "tangentsGenerated"},
      {&S::badNormalsReplaced, "badNormalsReplaced"},     {&S::badTangentsReplaced, "badTangentsReplaced"},
      {&S::weightsRenormalised, "weightsRenormalised"},   {&S::weightsZeroSum, "weightsZeroSum"},
      {&S::influencesTruncated, "influencesTruncated"},   {&S::nonFinitePositions, "nonFinitePositions"},
      {&S::skippedPrimitives, "skippedPrimitives"},       {&S::jointsOutOfRange, "jointsOutOfRange"},
      {&S::imagesNotDecoded, "imagesNotDecoded"},         {&S::accessorBoundsMismatch, "accessorBoundsMismatch"},
      {&S::keyframeTimesNotIncreasing, "keyframeTimesNotIncreasing"}, {&S::rotationKeysNormalised, "rotationKeysNormalised"},
      {&S::camerasRepaired, "camerasRepaired"},           {&S::binChunkUnaligned, "binChunkUnaligned"},
      {&S::basisuTexturesNotDecoded, "basisuTexturesNotDecoded"},
      {&S::camerasRepaired, "camerasRepaired"}, {&S::instanceRotationsNormalised, "instanceRotationsNormalised"},
      {&S::instancingDrawnOnce, "instancingDrawnOnce"}, {&S::dracoCountMismatch, "dracoCountMismatch"},
      {&S::jsonChunkUnpadded, "jsonChunkUnpadded"}, {&S::unusedTexturesWithoutImage, "unusedTexturesWithoutImage"},
      {&S::accessorsPastBufferView, "accessorsPastBufferView"}};
  for (const auto& [p, n] : names)
    if (p == c) return n;
  return "";
}

TEST(CliHostileCorpus, InspectReportsEveryFileAndFinishes) {
  const fs::path root = fs::temp_directory_path() / ("motorbench_hostile_corpus_" + std::to_string(::getpid()));
  const fs::path dir = root / "corpus";
  fs::remove_all(root);
  std::map<std::string, Want> want;  // path relative to dir -> expected outcome
  std::map<std::string, std::pair<std::string, int>> counters;  // fallback cases: counter, minimum

  // Good: built-in scenes and the shared real-world corpus.
  for (const auto& name : mb::builtinSceneNames()) {
    auto glb = mb::builtinSceneGlb(name);
    ASSERT_TRUE(glb.ok()) << glb.error();
    writeFile(dir / "good" / (name + ".glb"), *glb);
    want["good/" + name + ".glb"] = Want::Loads;
  }
  const fs::path shared = fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(shared, ec)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    fs::create_directories(dir / "good");
    fs::copy_file(e.path(), dir / "good" / e.path().filename(), fs::copy_options::overwrite_existing);
    want["good/" + e.path().filename().string()] = Want::Loads;
  }

  // Bad (and extreme-but-valid): the hostile catalogue, with its sidecar files.
  for (const Case& c : allCases()) {
    if (!c.pendingFix.empty()) continue;  // would crash or hang the run until the loader is fixed
    writeFile(dir / "hostile" / c.file, c.bytes);
    for (const auto& [name, bytes] : c.sidecars) writeFile(dir / "hostile" / name, bytes);
    want["hostile/" + c.file] = c.outcome == Outcome::Error ? Want::Fails : Want::Loads;
    if (c.outcome == Outcome::Fallback && c.counter && c.atLeast > 0) counters["hostile/" + c.file] = {counterName(c.counter), c.atLeast};
  }
  // Misaligned accessors may load (read correctly) or fail: not asserted either way.
  want.erase("hostile/misaligned_accessor_offset.glb");
  // A truncation series (every 4th cut), in a nested folder.
  auto cuts = truncations("rich", toGlb(richDoc()));
  for (size_t i = 0; i < cuts.size(); i += 4) {
    if (cuts[i].file.find("_fixed") != std::string::npos) continue;  // may legitimately load
    writeFile(dir / "truncated" / "deeper" / cuts[i].file, cuts[i].bytes);
    want["truncated/deeper/" + cuts[i].file] = Want::Fails;
  }

  const fs::path json = root / "inspect.json";
  std::string out;
  const int rc = run("timeout 600 " + quoted(MB_MOTORBENCH_EXE) + " inspect " + quoted(dir.string()) + " --json " +
                         quoted(json.string()),
                     &out);
  // inspect exits 1 when any input failed (the bad files here), after reporting all.
  if (rc != 1) {
    // The error (if any) is what the command wrote last to stderr, among the per-file lines.
    std::string errors;
    for (size_t at = out.find("motorbench"); at != std::string::npos; at = out.find("motorbench", at + 1))
      errors += out.substr(at, out.find('\n', at) - at) + "\n";
    FAIL() << "motorbench inspect exited " << rc << "; its messages:\n" << errors;
  }

  const nlohmann::json report = mb::cli_test::readJson(json);
  ASSERT_FALSE(report.is_discarded()) << "no --json report";
  std::map<std::string, int> seen;
  int good = 0, bad = 0;
  for (const auto& f : report["files"]) {
    const std::string path = f["file"];
    const std::string rel = fs::relative(path, dir).generic_string();
    ++seen[rel];
    // Every reported file also appears in the human-readable output.
    EXPECT_NE(out.find(path), std::string::npos) << rel << " missing from the printed report";
    auto w = want.find(rel);
    if (w == want.end()) continue;
    if (w->second == Want::Loads) {
      EXPECT_TRUE(f["loaded"].get<bool>()) << rel << ": expected to load, got: " << f.value("error", "");
      if (f["loaded"].get<bool>()) {
        EXPECT_TRUE(f.contains("geometry") && f["geometry"].contains("vertices") && f.contains("fallbacks"))
            << rel << ": loaded without statistics";
        if (auto k = counters.find(rel); k != counters.end()) {
          EXPECT_GE(f["fallbacks"].value(k->second.first, 0), k->second.second)
              << rel << ": fallback " << k->second.first << " not reported";
        }
        ++good;
      }
    } else {
      EXPECT_FALSE(f["loaded"].get<bool>()) << rel << ": expected an error";
      if (!f["loaded"].get<bool>()) {
        const std::string err = f.value("error", "");
        EXPECT_NE(err.find(fs::path(path).filename().string()), std::string::npos) << rel << ": error does not name the file: " << err;
        EXPECT_NE(out.find("FAILED"), std::string::npos);
        ++bad;
      }
    }
  }
  for (const auto& [rel, w] : want) EXPECT_EQ(seen[rel], 1) << rel << " reported " << seen[rel] << " times";
  EXPECT_EQ(report["aggregate"]["files"].get<size_t>(), report["files"].size());
  std::printf("[ corpus   ] %zu files reported: %d good with statistics, %d bad with their error\n", report["files"].size(), good,
              bad);
  if (!HasFailure()) fs::remove_all(root);
}

}  // namespace
