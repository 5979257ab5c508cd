#include "harness/check/corpus_tables.h"

#include <algorithm>
#include <cmath>

namespace mb::check {
namespace {

std::string cell(const ojson& v) { return valueText(v); }

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

// {file: why} of the files whose status is one of `statuses`.
ojson reasons(const std::vector<ojson>& files, std::initializer_list<const char*> statuses) {
  ojson out = ojson::object();
  for (const ojson& f : files)
    for (const char* s : statuses)
      if (f["status"] == s) out[f["file"].get<std::string>()] = f["error"];
  return out;
}

int64_t countStatus(const std::vector<ojson>& files, std::initializer_list<const char*> statuses) {
  int64_t n = 0;
  for (const ojson& f : files)
    for (const char* s : statuses) n += f["status"] == s;
  return n;
}

std::vector<std::string> pipelineTable(const ojson& per, const RuleSet& set) {
  std::vector<std::string> out = {
      "| pipeline | rows | drawn | errors | worst rigid PSNR (file) | rigid < " + printed("%g", set.minPsnr) +
          " dB (outside ties) | compact outside bound (outside ties) | frames passed on ties | skinned > " +
          printed("%g", 100 * set.maxDrawnDiff) + " % from matrix (from own method) | seconds |",
      "|---|---|---|---|---|---|---|---|---|---|"};
  for (const auto& [name, p] : per.items()) {
    const std::string worst =
        p["worstRigidPsnr"].is_null() ? "-" : psnrText(p["worstRigidPsnr"]) + " (" + cell(p["worstRigidFile"]) + ")";
    const std::string comp = set.isCompact(name) ? cell(p["compactFilesOutsideEnvelope"]) + " (" +
                                                       cell(p["compactFilesOutsideEnvelopeNotTies"]) + ")"
                                                 : "-";
    const std::string rig = cell(p["rigidFilesBelow50dB"]) + " (" + cell(p["rigidFilesFailing"]) + ")";
    const std::string tie = set.isFullPrecision(name) || set.isCompact(name)
                                ? std::to_string(p["rigidTieFrames"].get<int64_t>() + p["compactTieFrames"].get<int64_t>())
                                : "-";
    out.push_back("| " + name + " | " + cell(p["rows"]) + " | " + cell(p["drawn"]) + " | " + cell(p["errors"]) + " | " +
                  worst + " | " + rig + " | " + comp + " | " + tie + " | " + cell(p["skinnedFilesOver1Percent"]) + " (" +
                  cell(p["skinnedFilesOver1PercentOfReference"]) + ") | " + printed("%.1f", p["seconds"].get<double>()) +
                  " |");
  }
  return out;
}

std::vector<std::string> fallbackTable(const ojson& per) {
  std::string head = "| counter |", rule = "|---|";
  for (const auto& [name, p] : per.items()) head += " " + name + " |", rule += "---|";
  std::vector<std::string> out = {
      "", "Fallbacks (per file the largest value over its frames, summed over files; files taking it):", "", head, rule};
  for (const std::string& key : fallbackCounters()) {
    std::string line = "| " + key + " |";
    for (const auto& [name, p] : per.items()) {
      const ojson& f = p["fallbacks"][key];
      line += " " + (truthy(f["total"]) ? cell(f["total"]) + " (" + cell(f["files"]) + ")" : std::string("0")) + " |";
    }
    out.push_back(line);
  }
  return out;
}

// One file's cell for `name`: its worst rigid PSNR against matrix, or (skinned files) its largest
// drawn-pixel difference from matrix; a row that failed or drew nothing in bold.
std::string fileCell(const ojson& f, const ojson* r, const std::string& name) {
  if (!r) return "-";
  if ((*r)["status"] != "ok" || !truthy(member(*r, "drawn")))
    return "**" + ((*r)["status"] != "ok" ? cell((*r)["status"]) : std::string("not drawn")) + "**";
  if (member(f, "kind") == "skinned") {
    const ojson d = member(*r, "worstSkinnedDrawnDiff");
    return d.is_null() || name == "matrix" ? "-" : printed("%.1f %%", 100 * d.get<double>());
  }
  return name == "matrix" ? "-" : psnrText(member(*r, "worstRigidPsnr"));
}

std::vector<std::string> fileTable(const std::vector<ojson>& files, const ojson& per) {
  std::string head = "| file | status | kind | bound px |", rule = "|---|---|---|---|";
  for (const auto& [name, p] : per.items()) head += " " + name + " |", rule += "---|";
  std::vector<std::string> out = {
      "", "## Files", "",
      "Bound: the 16-byte pipelines' position error in pixels at this size (rigid files; int16 in each "
      "primitive's bounding cube: half extent / 32767 world units, projected at the nearest depth). The 16-byte "
      "pipelines are judged on it in the geometry view (base colour alone, no light); their lit images' PSNR "
      "against matrix is the cost of their quantised frame (and motor_cf's interpolated rotor).",
      "", head, rule};
  for (const ojson& f : files) {
    std::string line = "| " + f["file"].get<std::string>() + " | " + f["status"].get<std::string>() +
                       (f["status"] == "ok" ? "" : ": " + cell(f["error"])) + " | " + cell(member(f, "kind", "-")) + " | " +
                       (member(f, "boundPixels").is_null() ? "-" : printed("%.2g", f["boundPixels"].get<double>())) + " |";
    for (const auto& [name, p] : per.items()) {
      const ojson* row = nullptr;
      for (const ojson& r : f["rows"])
        if (r["pipeline"] == name) row = &r;
      line += " " + fileCell(f, row, name) + " |";
    }
    out.push_back(line);
  }
  out.push_back("");
  out.push_back("Cells: rigid files the worst PSNR (dB) against matrix over their frames; skinned files the largest "
                "drawn-pixel difference from matrix.");
  return out;
}

}  // namespace

std::vector<std::string> pipelinesOfRows(const std::vector<ojson>& files) {
  std::vector<std::string> out;
  for (const ojson& f : files)
    for (const ojson& r : f["rows"])
      if (!has(out, r["pipeline"].get<std::string>())) out.push_back(r["pipeline"].get<std::string>());
  return out;
}

ojson summaryOf(const RunFacts& facts, const std::vector<ojson>& files, const ojson& per, const RuleSet& set) {
  int64_t rigidTies = 0, compactTies = 0, errors = 0, rigid = 0, skinned = 0, rows = 0;
  double workerSeconds = 0;
  ojson gl = nullptr, loader = ojson::object();
  for (const auto& [name, p] : per.items())
    rigidTies += p["rigidTieFrames"].get<int64_t>(), compactTies += p["compactTieFrames"].get<int64_t>();
  for (const ojson& f : files) {
    workerSeconds += f["seconds"].get<double>();
    if (gl.is_null() && truthy(member(f, "gl"))) gl = f["gl"];
    for (const ojson& r : f["rows"]) errors += r["status"] == "error";
    rigid += member(f, "kind") == "rigid";
    skinned += member(f, "kind") == "skinned";
    rows += int64_t(f["rows"].size());
    const ojson fallbacks = member(f, "loaderFallbacks", ojson::object());
    for (const auto& [key, value] : fallbacks.items()) {
      if (!loader.contains(key)) loader[key] = {{"total", 0}, {"files", 0}};
      loader[key]["total"] = loader[key]["total"].get<int64_t>() + value.get<int64_t>();
      loader[key]["files"] = loader[key]["files"].get<int64_t>() + 1;
    }
  }
  return {{"folder", facts.folder},
          {"files", files.size()},
          {"size", facts.size},
          {"jobs", facts.jobs},
          {"wallSeconds", std::round(facts.wallSeconds * 10) / 10},
          {"workerSeconds", std::round(workerSeconds * 10) / 10},
          {"gl", gl},
          {"ok", countStatus(files, {"ok"})},
          {"noData", countStatus(files, {"no-data"})},
          {"loadFailed", countStatus(files, {"load-failed"})},
          {"crashed", countStatus(files, {"crashed", "worker-error"})},
          {"pipelineErrors", errors},
          {"rigidFiles", rigid},
          {"skinnedFiles", skinned},
          {"rows", rows},
          {"loaderFallbacks", loader},
          {"framesPassedOnTies", {{"rigid", rigidTies}, {"compact", compactTies}}},
          {"notDrawable", reasons(files, {"no-data"})},
          {"loadFailures", reasons(files, {"load-failed"})},
          {"crashes", reasons(files, {"crashed", "worker-error"})},
          {"thresholds", {{"minPsnr", set.minPsnr}, {"maxDrawnDiff", set.maxDrawnDiff},
                          {"pipelines", set.pipelines.empty() ? ojson("every one of the file's space") : ojson(set.pipelines)}}}};
}

ojson checkDocument(const ojson& summary, const ojson& per, const Verdicts& v, const std::vector<ojson>& files) {
  ojson rules = ojson::array(), counted = ojson::array(), fileList = ojson::array(), rows = ojson::array();
  for (const Rule& r : v.rules)
    rules.push_back({{"rule", r.name}, {"pass", r.pass()}, {"failures", r.failures}, {"passedOnTies", r.passedMarked}});
  for (const auto& [mark, line] : v.counted) counted.push_back({{"mark", mark}, {"frame", line}});
  for (const ojson& f : files) {
    ojson copy = f;
    copy.erase("rows");
    fileList.push_back(copy);
    for (ojson r : f["rows"]) {
      r.erase("perFrame");  // the per-frame verdicts' figures: in memory only
      rows.push_back(std::move(r));
    }
  }
  return {{"summary", summary}, {"pipelines", per}, {"rules", rules}, {"countedOmissions", counted},
          {"files", fileList}, {"rows", rows}};
}

std::string markdown(const ojson& s, const std::vector<ojson>& files, const ojson& per, const Verdicts& v,
                     const RuleSet& set) {
  std::vector<std::string> out = {
      "# corpus-check: " + cell(s["folder"]), "",
      cell(s["files"]) + " files, " + cell(s["size"]) + ", " + cell(s["jobs"]) + " jobs, " +
          printed("%.0f", s["wallSeconds"].get<double>()) + " s wall (" + printed("%.0f", s["workerSeconds"].get<double>()) +
          " s in workers); drawn on " + (truthy(s["gl"]) ? cell(s["gl"]) : std::string("no context")),
      "",
      "| files | ok | no data | load failed | crashed | pipeline errors | rigid | skinned |",
      "|---|---|---|---|---|---|---|---|",
      "| " + cell(s["files"]) + " | " + cell(s["ok"]) + " | " + cell(s["noData"]) + " | " + cell(s["loadFailed"]) + " | " +
          cell(s["crashed"]) + " | " + cell(s["pipelineErrors"]) + " | " + cell(s["rigidFiles"]) + " | " +
          cell(s["skinnedFiles"]) + " |",
      "",
      "Frames passed on ties (every pixel that fails the rule undetermined by the transform): " +
          cell(s["framesPassedOnTies"]["rigid"]) + " rigid (full precision), " + cell(s["framesPassedOnTies"]["compact"]) +
          " compact.",
      ""};
  for (const auto& [what, key] : {std::pair{"No data (not failures)", "notDrawable"}, std::pair{"Load failures", "loadFailures"},
                                  std::pair{"Crashes", "crashes"}}) {
    if (s[key].empty()) continue;
    out.push_back(std::string(what) + ":");
    out.push_back("");
    for (const auto& [file, why] : s[key].items()) out.push_back("- " + file + ": " + cell(why));
    out.push_back("");
  }
  for (std::string& line : pipelineTable(per, set)) out.push_back(std::move(line));
  for (std::string& line : fallbackTable(per)) out.push_back(std::move(line));
  std::string loader;
  for (const auto& [key, v] : s["loaderFallbacks"].items())
    loader += (loader.empty() ? "" : ", ") + key + " " + cell(v["total"]) + " (" + cell(v["files"]) + ")";
  out.push_back("");
  out.push_back("Loader fallbacks (total; files): " + (loader.empty() ? std::string("none") : loader));
  out.push_back("");
  out.push_back("## Rules");
  out.push_back("");
  for (std::string& line : ruleLines(v, set)) out.push_back(std::move(line));
  for (std::string& line : fileTable(files, per)) out.push_back(std::move(line));
  std::string text;
  for (const std::string& line : out) text += line + "\n";
  return text;
}

}  // namespace mb::check
