// What `check --rules` writes: the summary, corpus-check.json (summary, per-pipeline totals, the
// rules, the counted omissions, the files and their rows) and corpus-check.md (summary, pipeline,
// fallback and per-file tables, the rule lines).
#pragma once
#include <string>
#include <vector>

#include "harness/check/corpus_verdicts.h"

namespace mb::check {

// How the run was made, for the summary.
struct RunFacts {
  std::string folder;  // the inputs as given ("a, b"; more than two: "N paths under COMMON")
  std::string size;    // "128x128"
  int jobs = 1;
  double wallSeconds = 0;
};

// The pipelines in the order the rows first name them.
std::vector<std::string> pipelinesOfRows(const std::vector<ojson>& files);

ojson summaryOf(const RunFacts& facts, const std::vector<ojson>& files, const ojson& per, const RuleSet& set);

ojson checkDocument(const ojson& summary, const ojson& per, const Verdicts& v, const std::vector<ojson>& files);

std::string markdown(const ojson& summary, const std::vector<ojson>& files, const ojson& per, const Verdicts& v,
                     const RuleSet& set);

}  // namespace mb::check
