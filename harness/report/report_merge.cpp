#include "harness/report/report_merge.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "harness/options/shard.h"

#include "harness/document/report_document.h"
#include "harness/report/report_sources.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

int fail(const std::string& message) {
  std::fprintf(stderr, "motorbench merge: error: %s\n", message.c_str());
  return 2;
}

struct ShardRun {
  std::string dir;
  json report;
};

// The settings every shard must share (jobs, arguments and the shard's own index may differ).
json comparable(const json& settings) {
  json s = settings;
  for (const char* k : {"jobs", "arguments"}) s.erase(k);
  s["shard"].erase("index");
  return s;
}

}  // namespace

int mergeReports(const std::vector<std::string>& dirs, const Options& o) {
  if (dirs.empty()) return fail("no shard folders given");
  std::vector<ShardRun> runs;
  for (const std::string& d : dirs) {
    std::ifstream in(fs::path(d) / "report.json");
    if (!in) return fail(d + ": no report.json (not a motorbench report folder)");
    json j = json::parse(in, nullptr, false);
    if (j.is_discarded() || j.value("schema", "") != document::kReportSchema)
      return fail(d + "/report.json: not a " + std::string(document::kReportSchema) + " document");
    if (!j["settings"].contains("shard"))
      return fail(d + "/report.json: made without shard information (re-run it with --shard I/N)");
    runs.push_back({d, std::move(j)});
  }
  const json& first = runs.front().report;
  std::vector<options::ShardPart> parts;
  for (const ShardRun& r : runs) {
    const json& sh = r.report["settings"]["shard"];
    options::ShardPart p{r.dir, sh.value("index", 0), sh.value("count", 0), {}};
    for (const json& in : sh["inputs"]) p.inputs.push_back(in.value("spec", ""));
    parts.push_back(std::move(p));
  }
  if (std::string why = options::checkShardSet(parts); !why.empty()) return fail(why);
  for (const ShardRun& r : runs)
    if (comparable(r.report["settings"]) != comparable(first["settings"]))
      return fail(r.dir + " and " + runs.front().dir +
                  " were made with different settings (pipelines, image or timing size, frames)");
  const int count = first["settings"]["shard"].value("count", 0);

  // Scenes back in the order of the full input list; each one's images follow it.
  std::map<std::string, std::pair<json, std::string>> byId;
  for (const ShardRun& r : runs)
    for (const json& s : r.report["scenes"]) byId[s.value("id", "")] = {s, r.dir};
  std::error_code ec;
  fs::create_directories(o.outDir, ec);
  if (ec) return fail(o.outDir + ": cannot create folder: " + ec.message());
  std::vector<json> scenes;
  for (const json& in : first["settings"]["shard"]["inputs"]) {
    const std::string id = in.value("id", "");
    auto it = byId.find(id);
    if (it == byId.end()) return fail("scene " + id + " (" + in.value("spec", "") + ") is in no shard's report");
    scenes.push_back(it->second.first);
    const fs::path from = fs::path(it->second.second) / "images" / id, to = fs::path(o.outDir) / "images" / id;
    if (fs::exists(from, ec) && !(fs::exists(to, ec) && fs::equivalent(from, to, ec))) {
      fs::create_directories(to, ec);
      fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing, ec);
      if (ec) return fail(from.string() + " -> " + to.string() + ": " + ec.message());
    }
  }

  // Ops per vertex are the same for every shard (counted from the shader source); kernel ratios
  // come from the first shard that measured them.
  const ShardRun* kernelRun = &runs.front();
  for (const ShardRun& r : runs)
    if (r.report["kernels"].value("source", "") != "skipped") {
      kernelRun = &r;
      break;
    }
  const json& kernels = kernelRun->report["kernels"];
  if (kernels["file"].is_string() && fs::path(kernels["file"].get<std::string>()).is_relative())
    for (const std::string& name : {kernels["file"].get<std::string>(), std::string("bench.txt")})
      if (fs::exists(fs::path(kernelRun->dir) / name, ec))
        fs::copy_file(fs::path(kernelRun->dir) / name, fs::path(o.outDir) / name, fs::copy_options::overwrite_existing, ec);
  json settings = first["settings"];
  settings["shard"].erase("index");
  settings["shard"]["merged"] = dirs;
  json report = document::assembleReport(first["machine"], settings, std::move(scenes), first["opsPerVertex"], kernels);
  report["summary"]["statistics"] = statisticsByOrigin(report["scenes"]);  // built-ins apart from files
  // Alike in every shard that has them: the curved drift (measured by every shard with a curved
  // scene) and motorbench isa's file (--isa-json).
  for (const char* key : {"curved", "isa", "morph"})
    for (const ShardRun& r : runs)
      if (r.report.contains(key)) {
        report[key] = r.report[key];
        break;
      }
  std::fprintf(stderr, "merge: %d shard(s), %zu scene(s) -> %s\n", count, report["scenes"].size(), o.outDir.c_str());
  return writeReportFolder(std::move(report), o);
}

}  // namespace mb::report
