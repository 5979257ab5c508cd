// `motorbench claims [--results DIR] [--report F] [--ops F] [--morph F] [--accuracy F]
//   [--scene-graphs F] [--corpus-report F] [--corpus-accuracy F] [-o FILE] [--json FILE]`:
// every declared claim (harness/claims/claim_table.h) judged on the figures of a run's JSON
// files. It measures nothing: no GL, no scene, no count, no timing. A missing file makes the
// rows that read it "not measurable here", with the command that writes it.
#include <cstdio>
#include <filesystem>

#include "harness/claims/claim_table.h"
#include "harness/claims/claims_layout.h"
#include "harness/claims/evaluate.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/document/report_answer.h"
#include "harness/document/report_format.h"
#include "harness/document/scope_ladder.h"
#include "harness/options/args.h"
#include "harness/render/frame_options.h"

namespace mb {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

int fail(const std::string& message) { return commandError("claims", message); }

// The option that overrides each source's file, and the command that writes it.
struct SourceOption {
  const char* source;
  const char* option;
  const char* makes;
};
const SourceOption kSources[] = {
    {"report", "report", "motorbench report -o DIR (with --bench-json and --isa-json)"},
    {"ops", "ops", "motorbench ops --json DIR/ops.json"},
    {"morph", "morph", "motorbench morph --json DIR/morph.json"},
    {"accuracy", "accuracy", "motorbench accuracy --json DIR/accuracy.json"},
    {"graphs", "scene-graphs", "motorbench inspect ../shared/corpus-graph --json DIR/corpus-graph.json"},
    {"corpus", "corpus-report", "motorbench report ../shared/corpus -o DIR/corpus"},
    {"corpus_accuracy", "corpus-accuracy", "motorbench accuracy --skinned-files ../shared/corpus --json DIR/corpus/accuracy.json"},
};

int runClaims(const std::vector<std::string>& argv) {
  const options::Args args(argv, {{"o", "output", "json", "results", "report", "ops", "morph", "accuracy", "scene-graphs",
                          "corpus-report", "corpus-accuracy"},
                         {},
                         {}});
  if (!args.error().empty()) return fail(args.error());
  if (!args.positional().empty()) return fail("unexpected argument '" + args.positional()[0] + "'");
  for (const char* key : {"json", "o", "output"})
    if (auto path = args.get(key))
      if (Status ok = prepareOutputFile(std::string(key) == "o" ? "-o" : std::string("--") + key, *path); !ok)
        return fail(ok.error());
  std::map<std::string, std::string> layout = claims::resultsLayout(args.get("results", "results"));
  for (const SourceOption& s : kSources)
    if (auto path = args.get(s.option)) layout[s.source] = *path;
  claims::FigureSet figures = claims::loadFigureSet(layout);
  const json& report = figures.report;
  if (!report.is_object())
    return fail(layout["report"] + ": no report.json (claims reads a run's figures; make them with " +
                std::string(kSources[0].makes) + ", or all of them with scripts/reproduce.sh)");
  json sources = json::object();
  for (const SourceOption& s : kSources) {
    const auto miss = figures.missing.find(s.source);
    sources[s.source] = miss == figures.missing.end() ? json(layout[s.source])
                                                      : json(miss->second + "; made by " + s.makes);
    if (miss != figures.missing.end()) figures.missing[s.source] = miss->second + "; made by " + s.makes;
  }
  const std::vector<claims::Claim> all = claims::evaluateAll(claims::claimTable(), figures);
  json j = claims::claimsJson(all, report.value("machine", json()), sources);
  j["scopeLadder"] = document::ladderJson(document::scopeLadder(report));
  j["answer"] = document::answerJson(report);
  const std::string mdPath = args.get("o", args.get("output", ""));
  const fs::path reportMd = fs::path(layout["report"]).parent_path() / "report.md";
  const fs::path mdDir = mdPath.empty() ? fs::current_path() : fs::absolute(mdPath).parent_path();
  document::Document doc = claims::claimsDocument(j);
  doc = document::withAnswerFirst(doc, report, fs::absolute(reportMd).lexically_relative(mdDir).generic_string());
  if (auto path = args.get("json"))
    if (Status ok = writeTextFile(*path, document::dumpJson(j, 2) + "\n"); !ok) return fail(ok.error());
  const std::string md = document::toMarkdown(doc);
  if (mdPath.empty()) std::fputs(md.c_str(), stdout);
  else if (Status ok = writeTextFile(mdPath, md); !ok) return fail(ok.error());
  auto tally = [](const json& c) {
    return c["reproduced"].dump() + " reproduced, " + c["differs"].dump() + " differ, " + c["inconclusive"].dump() +
           " inconclusive, " + c["not measurable here"].dump() + " not measurable";
  };
  std::fprintf(stderr, "claims: %zu rows; the paper's claims: %s; our own rows: %s, %s baselines\n", all.size(),
               tally(j["paperCounts"]).c_str(), tally(j["ownCounts"]).c_str(), j["ownCounts"]["baseline"].dump().c_str());
  for (const auto& [source, why] : figures.missing) std::fprintf(stderr, "claims: no %s figures: %s\n", source.c_str(), why.c_str());
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(claims, "claims",
           "[--results DIR] [--report F] [--ops F] [--morph F] [--accuracy F] [--scene-graphs F] [--corpus-report F] "
           "[--corpus-accuracy F] [-o FILE] [--json FILE]",
           "every claim of the paper (and our own rows) judged on a run's figures: rule, evidence, verdict (Markdown/JSON)",
           mb::runClaims);
MB_COMMAND_HELP(claims, "claims",
               "  --results DIR      the run's folder as scripts/reproduce.sh writes it (default results): report.json,\n"
               "                     ops.json, morph.json, accuracy.json, corpus-graph.json, corpus/report.json,\n"
               "                     corpus/accuracy.json; each can be given on its own:\n"
               "  --report F  --ops F  --morph F  --accuracy F  --scene-graphs F  --corpus-report F  --corpus-accuracy F\n"
               "  -o FILE            claims.md (default: stdout);  --json FILE  claims.json\n"
               "claims measures nothing: each row reads named figures and applies its declared rule. A missing\n"
               "file makes its rows \"not measurable here\"; stderr names the command that writes it.\n",
               "motorbench claims --results results -o results/claims.md --json results/claims.json", false);
