// The corpus rules over the file results of corpus_rows.h: each rule with one line per failing
// file x pipeline and the frames that pass it only on ties (or, skinned frames, only by their own
// method's reference), the PASS/FAIL lines, and the per-pipeline totals of corpus-check.json.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "harness/check/corpus_rows.h"

namespace mb::check {

struct Rule {
  std::string name;
  std::vector<std::string> failures;      // one line per failing file x pipeline
  std::vector<std::string> passedMarked;  // frames that pass only on ties / by their method's reference
  bool skinned = false;                   // the skinned rule (its marked passes: the method's difference)
  bool pass() const { return failures.empty(); }
};

struct Verdicts {
  std::vector<Rule> rules;  // in order: crashes, loads, drawn, rigid, 16-byte, skinned
  // Frames judged by no image rule (a feature the pipeline counts as not drawn): (mark, line).
  std::string countedName;
  std::vector<std::pair<std::string, std::string>> counted;
  bool pass() const;
};

Verdicts evaluate(const std::vector<ojson>& files, const RuleSet& set);

// The rules as PASS/FAIL lines (a Markdown list): failures, then frames passed on ties, marked;
// then the COUNTED list.
std::vector<std::string> ruleLines(const Verdicts& v, const RuleSet& set);

// Per pipeline: rows, drawn, errors, the worst rigid PSNR and its file, files over each bound,
// frames passed on ties, the fallback counters' totals and files, seconds.
ojson totals(const std::vector<ojson>& files, const std::vector<std::string>& pipelines, const RuleSet& set);

// The fallback counters the totals sum (survey's per-pipeline maxima over frames).
const std::vector<std::string>& fallbackCounters();

}  // namespace mb::check
