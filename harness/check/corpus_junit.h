// `check --rules --junit FILE`: the rules' verdicts as JUnit XML (junit.h), one test case per
// file x pipeline x frame ("check.rules.<file>", "<frame>.<pipeline>", e.g. "rest.motor"), a
// failure naming the rule and the figure that broke it; a file that did not load, a crashed
// worker and a pipeline error are errors, a file without anything to draw and a frame no image
// rule judges (a counted omission) are skipped.
#pragma once
#include <string>
#include <vector>

#include "harness/check/corpus_rows.h"
#include "harness/check/junit.h"

namespace mb::check {

std::vector<JunitCase> junitCases(const std::vector<ojson>& files, const RuleSet& set);

Status writeRulesJunit(const std::string& path, const std::vector<ojson>& files, const RuleSet& set);

}  // namespace mb::check
