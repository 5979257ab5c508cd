// `motorbench merge DIR... -o OUT [--no-plots] [--python P]`: puts the outputs of sharded runs
// (`--shard I/N` on report, check or inspect) back together. What is merged follows the inputs:
// report folders (report.json) -> one report folder; check folders (check.json) -> one
// check.json + summary; inspect JSON files (--json) -> one inspect JSON. A missing or duplicated
// shard is an error (exit 2), never a silent partial merge.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "harness/check/check_merge.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/options/args.h"
#include "harness/options/shard.h"
#include "harness/report/corpus_stats.h"
#include "harness/report/report_merge.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/scene_stats.h"

namespace mb {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// Inspect --json files of shards -> one inspect JSON with the aggregate over every file, as one
// run would write it. Exit 1 when some file failed to load (as inspect), 2 when the merge failed.
int mergeInspectRuns(const std::vector<std::string>& inputs, const std::string& out) {
  auto fail = [](const std::string& message) { return commandError("merge", message); };
  std::vector<options::ShardPart> parts;
  std::map<std::string, json> byFile;
  for (const std::string& path : inputs) {
    std::ifstream in(path);
    json j = in ? json::parse(in, nullptr, false) : json();
    if (j.is_discarded() || !j.is_object() || !j.contains("files") || !j.contains("aggregate"))
      return fail(path + ": not a motorbench inspect --json file");
    if (!j["shard"].is_object()) return fail(path + ": made without shard information (re-run with --shard I/N)");
    parts.push_back({path, j["shard"].value("index", 0), j["shard"].value("count", 0),
                     j["shard"].value("inputs", std::vector<std::string>{})});
    for (const json& f : j["files"]) byFile[f.value("input", f.value("file", ""))] = f;
  }
  if (std::string why = options::checkShardSet(parts); !why.empty()) return fail(why);
  json files = json::array();
  int failed = 0;
  for (const std::string& file : parts[0].inputs) {
    auto it = byFile.find(file);
    if (it == byFile.end()) return fail(file + " is in no shard's file list");
    failed += !it->second.value("loaded", false);
    files.push_back(it->second);
  }
  json aggregate = aggregateFileJson(files);
  report::addCorpusAggregates(files, aggregate);  // as inspect adds them
  json merged = {{"files", files}, {"aggregate", aggregate},
                 {"shard", {{"count", parts[0].count}, {"inputs", parts[0].inputs}, {"merged", inputs}}},
                 {"figures", report::scaleFigures(files)}};
  if (!writeTextFile(out, merged.dump(2, ' ', false, json::error_handler_t::replace) + "\n"))
    return fail(out + ": cannot write the merged JSON file");
  std::printf("merge: %d shard(s), %zu file(s), %d failed -> %s\n", parts[0].count, files.size(), failed, out.c_str());
  return failed ? 1 : 0;
}

int runMerge(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("merge", message); };
  const options::Args args(argv, {{"o", "output", "python"}, {"no-plots"}, {}});
  if (!args.error().empty()) return fail(args.error());
  const std::vector<std::string>& inputs = args.positional();
  const std::string out = args.get("o", args.get("output", ""));
  if (inputs.empty() || out.empty()) return fail("expected shard outputs and -o OUT");
  std::error_code ec;
  for (const std::string& in : inputs)
    if (!fs::exists(in, ec)) return fail(in + ": not found (give the shard outputs: report or check folders, or inspect --json files)");
  auto all = [&](auto pred) {
    for (const std::string& in : inputs)
      if (!pred(fs::path(in))) return false;
    return true;
  };
  if (all([&](const fs::path& p) { return fs::exists(p / "report.json", ec); })) {
    if (Status ok = prepareOutputFolder("-o", out, "the merged report: report.json, report.md, report.html, images/"); !ok)
      return fail(ok.error());
    report::Options o;
    o.outDir = out;
    o.plots = !args.has("no-plots");
    o.python = args.get("python", "");
    return report::mergeReports(inputs, o);
  }
  if (all([&](const fs::path& p) { return fs::exists(p / "check.json", ec); })) {
    if (Status ok = prepareOutputFolder("-o", out, "the merged check.json and summary"); !ok) return fail(ok.error());
    return check::mergeCheckRuns(inputs, out);
  }
  if (all([&](const fs::path& p) { return fs::is_regular_file(p, ec) && p.extension() == ".json"; })) {
    if (Status ok = prepareOutputFile("-o", out); !ok)
      return fail(ok.error() + " (merging inspect --json files writes one JSON file)");
    return mergeInspectRuns(inputs, out);
  }
  return fail("every input must be a report folder (report.json), a check folder (check.json) or an "
              "inspect --json file, all of one kind");
}

}  // namespace
}  // namespace mb

MB_COMMAND(merge, "merge", "DIR|FILE... -o OUT [--no-plots] [--python P]",
           "combine the outputs of --shard I/N runs of report, check or inspect into one",
           mb::runMerge);
MB_COMMAND_HELP(merge, "merge",
               "  DIR|FILE...        the shard outputs: report folders, check folders, or inspect --json files\n"
               "  -o, --output OUT   a report or check folder, or one inspect JSON file (missing folders are created)\n"
               "  --no-plots         no plots for a merged report;  --python P  the python with matplotlib\n",
                "motorbench merge out/shards/1 out/shards/2 out/shards/3 -o out/merged", false);
