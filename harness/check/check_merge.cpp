#include "harness/check/check_merge.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "harness/check/check_report.h"
#include "harness/options/shard.h"

namespace mb::check {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

int fail(const std::string& message) {
  std::fprintf(stderr, "motorbench merge: error: %s\n", message.c_str());
  return 2;
}

CheckItem::Outcome outcomeFromName(const std::string& name) {
  for (auto o : {CheckItem::Outcome::Pass, CheckItem::Outcome::Warn, CheckItem::Outcome::Fail, CheckItem::Outcome::Changed})
    if (name == outcomeName(o)) return o;
  return CheckItem::Outcome::Error;
}

// The inverse of render_frame.h's toJson(ImageMetrics) (psnr null = identical = +inf).
ImageMetrics metricsFromJson(const json& m) {
  ImageMetrics r;
  r.rmse = m.value("rmse", 0.0);
  if (m["psnr"].is_number()) r.psnr = m["psnr"].get<double>();
  r.meanError = m.value("meanError", 0.0);
  r.maxError = m.value("maxError", 0.0);
  r.maxX = m["maxErrorPixel"].value("x", 0);
  r.maxY = m["maxErrorPixel"].value("y", 0);
  r.maxChannel = m["maxErrorPixel"].value("channel", 0);
  r.fractionOver1 = m.value("fractionOver1", 0.0);
  r.fractionOver2 = m.value("fractionOver2", 0.0);
  r.fractionOver4 = m.value("fractionOver4", 0.0);
  return r;
}

CheckItem itemFromJson(const json& e) {
  CheckItem it;
  it.file = e.value("file", ""), it.scene = e.value("scene", ""), it.pipeline = e.value("pipeline", "");
  it.pose = e.value("pose", ""), it.level = e.value("level", ""), it.reason = e.value("reason", "");
  it.source = e.value("source", "");
  it.outcome = outcomeFromName(e.value("outcome", ""));
  it.compared = e.contains("metrics");
  if (it.compared) it.metrics = metricsFromJson(e["metrics"]);
  if (it.compared) it.flip = flipFromJson(e["metrics"].value("flip", json()));
  it.expected = e.value("expected", ""), it.actual = e.value("actual", ""), it.diff = e.value("diff", "");
  it.flipMap = e.value("flipMap", "");
  return it;
}

}  // namespace

int mergeCheckRuns(const std::vector<std::string>& dirs, const std::string& outDir) {
  std::vector<json> runs;
  std::vector<options::ShardPart> parts;
  for (const std::string& d : dirs) {
    std::ifstream in(fs::path(d) / "check.json");
    json j = in ? json::parse(in, nullptr, false) : json();
    if (j.is_discarded() || !j.is_object() || !j.contains("images"))
      return fail(d + "/check.json: not a motorbench check result");
    if (!j["shard"].is_object()) return fail(d + "/check.json: made without shard information (re-run with --shard I/N)");
    parts.push_back({d, j["shard"].value("index", 0), j["shard"].value("count", 0),
                     j["shard"].value("inputs", std::vector<std::string>{})});
    runs.push_back(std::move(j));
  }
  if (std::string why = options::checkShardSet(parts); !why.empty()) return fail(why);
  for (size_t i = 1; i < runs.size(); ++i)
    if (runs[i]["golden"] != runs[0]["golden"])
      return fail(dirs[i] + " and " + dirs[0] + " checked different golden folders");

  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) return fail(outDir + ": cannot create folder: " + ec.message());
  CheckRun run;
  run.goldenDir = runs[0].value("golden", "");
  run.shaderDir = runs[0].value("shaders", "");
  run.glRenderer = runs[0]["gl"].value("renderer", "");
  run.glVersion = runs[0]["gl"].value("version", "");
  run.shard = {{"count", parts[0].count}, {"inputs", parts[0].inputs}, {"merged", dirs}};
  // Items scene by scene in the order of the full list; each shard's images come along.
  std::map<std::string, std::vector<std::pair<json, std::string>>> byScene;
  for (size_t i = 0; i < runs.size(); ++i) {
    for (const json& e : runs[i]["images"]) byScene[e.value("scene", "")].push_back({e, dirs[i]});
    for (const json& c : runs[i].value("changedFiles", json::array()))
      run.changed.push_back({c.value("scene", ""), c.value("path", ""), c.value("recordedSha256", ""),
                             c.value("sha256", ""), c.value("images", 0)});
    for (const json& n : runs[i]["notes"])
      if (std::find(run.notes.begin(), run.notes.end(), n.get<std::string>()) == run.notes.end())
        run.notes.push_back(n.get<std::string>());
  }
  for (const std::string& scene : parts[0].inputs)
    for (const auto& [e, dir] : byScene[scene]) {
      run.items.push_back(itemFromJson(e));
      const CheckItem& it = run.items.back();
      for (const std::string* f : {&it.expected, &it.actual, &it.diff, &it.flipMap})
        if (!f->empty()) fs::copy_file(fs::path(dir) / *f, fs::path(outDir) / *f, fs::copy_options::overwrite_existing, ec);
    }
  if (Status s = writeCheckReport(outDir, run); !s) return fail(s.error());
  // check's summary line ("check: N images: ...") with merge's shard count in front.
  std::string line = summaryLine(run);
  line = line.substr(line.find(':') + 2);
  std::printf("merge: %d shard(s): %s -> %s\n", parts[0].count, line.c_str(),
              (fs::path(outDir) / "summary.html").string().c_str());
  return exitCode(run);
}

}  // namespace mb::check
