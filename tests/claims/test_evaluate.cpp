// The one evaluator (harness/claims/evaluate.h) on figure sets built here, against verdicts
// worked out by hand from the rule kinds claim_table.h declares: the paper's columns (equal,
// differing with the signed difference, an unstated column absent), ours or the printed
// listing, an undefined expansion, thresholds on one and several kinds of evidence (all pass:
// reproduced, none: differs, some: inconclusive), the evidence left out and named (missing,
// not measured, disturbed, too few samples, a CPU rasterizer's frame time), nothing left, and a
// baseline.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "harness/claims/evaluate.h"
#include "harness/figures/figure.h"

namespace {

using json = nlohmann::json;
namespace claims = mb::claims;
namespace figures = mb::figures;
using claims::Evidence;
using claims::RuleKind;
using claims::Verdict;

figures::Figure fig(const std::string& name, double value, const std::string& unit = "ops", int n = 1,
                    const std::string& device = "op-counting scalar") {
  figures::Figure f;
  f.name = name;
  f.value = value;
  f.unit = unit;
  f.n = n;
  f.device = device;
  f.statistic = "by hand";
  return f;
}

// {source: [figures]} as FigureSet reads it from each run's "figures" object.
claims::FigureSet setOf(const std::map<std::string, std::vector<figures::Figure>>& sources) {
  claims::FigureSet set;
  for (const auto& [source, list] : sources) {
    set.figures[source] = json::object();
    for (const figures::Figure& f : list) figures::put(set.figures[source], f);
  }
  return set;
}

// The five columns of a counted kernel under `prefix`; a NaN column is left unwritten.
std::vector<figures::Figure> columns(const std::string& prefix, double mul, double add, double div = 0, double sqrt = 0,
                                     double other = 0) {
  std::vector<figures::Figure> out;
  const std::pair<const char*, double> cols[] = {{"mul", mul}, {"add", add}, {"div", div}, {"sqrt", sqrt}, {"other", other}};
  for (const auto& [c, v] : cols)
    if (!std::isnan(v)) out.push_back(fig(prefix + "." + c, v));
  return out;
}

claims::ClaimRow row(RuleKind kind, std::vector<Evidence> evidence, double limit = 0, json paperValue = json()) {
  claims::ClaimRow r{.id = "r", .section = "s", .statement = "a statement", .origin = "paper"};
  r.scope = {"operator", "none", "synthetic"};
  r.paperValue = std::move(paperValue);
  r.evidence = std::move(evidence);
  r.rule = {kind, limit};
  return r;
}

const json kPaper4840 = {{"mul", 48}, {"add", 40}};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---- the paper's columns

TEST(Evaluate, PaperColumnsEqualIsReproduced) {
  const auto set = setOf({{"ops", columns("kernel.gp_mm", 48, 40)}});
  const claims::Claim c = claims::evaluate(row(RuleKind::PaperColumns, {{"counted", "ops:kernel.gp_mm", ""}}, 0, kPaper4840), set);
  EXPECT_EQ(c.verdict, Verdict::Reproduced) << c.verdictText;
  EXPECT_EQ(c.verdictText, "reproduced");
  EXPECT_EQ(c.measured, "counted 48 mul, 40 add");
  EXPECT_EQ(c.measuredValue["counted"]["mul"], 48.0);
  const json& e = c.declared["evidence"][0];
  EXPECT_EQ(e["passes"], true);
  EXPECT_EQ(e["figures"].size(), 5u);  // the five columns, each named
  EXPECT_EQ(e["figures"][0]["reference"], "ops:kernel.gp_mm.mul");
  EXPECT_EQ(c.declared["rule"]["kind"], "paper_columns");
}

TEST(Evaluate, PaperColumnsDifferPrintsTheSignedDifference) {
  // 49 - 48 = +1 mul, 38 - 40 = -2 add; the unstated div (1) is printed but not judged.
  const auto set = setOf({{"ops", columns("kernel.k", 49, 38, 1)}});
  const claims::Claim c = claims::evaluate(row(RuleKind::PaperColumns, {{"counted", "ops:kernel.k", ""}}, 0, kPaper4840), set);
  EXPECT_EQ(c.verdict, Verdict::Differs);
  EXPECT_EQ(c.verdictText, "differs: counted 49 mul, 38 add + 1 div (+1 mul, -2 add)");
}

TEST(Evaluate, AnUnstatedColumnMayBeAbsentAStatedOneMayNot) {
  const auto set = setOf({{"ops", columns("kernel.k", 48, 40, NAN, NAN, NAN)}});  // mul and add only
  EXPECT_EQ(claims::evaluate(row(RuleKind::PaperColumns, {{"counted", "ops:kernel.k", ""}}, 0, kPaper4840), set).verdict,
            Verdict::Reproduced);
  const json withDiv = {{"mul", 48}, {"add", 40}, {"div", 1}};
  const claims::Claim c = claims::evaluate(row(RuleKind::PaperColumns, {{"counted", "ops:kernel.k", ""}}, 0, withDiv), set);
  EXPECT_EQ(c.verdict, Verdict::NotMeasurable);
  EXPECT_TRUE(has(c.verdictText, "no figure ops:kernel.k.div")) << c.verdictText;
}

TEST(Evaluate, OursOrThePrintedListing) {
  const json paper = {{"mul", 14}, {"add", 5}};
  const std::vector<Evidence> ev = {{"ours", "ops:kernel.log_m", ""}, {"listing", "ops:listing.log_m", ""}};
  auto judge = [&](double oursAdd, double listingAdd) {
    auto cols = columns("kernel.log_m", 14, oursAdd);
    for (const auto& f : columns("listing.log_m", 14, listingAdd)) cols.push_back(f);
    return claims::evaluate(row(RuleKind::PaperColumnsOrListing, ev, 0, paper), setOf({{"ops", cols}}));
  };
  const claims::Claim ours = judge(5, 6), listing = judge(6, 5), neither = judge(6, 7);
  EXPECT_EQ(ours.verdict, Verdict::Reproduced);
  EXPECT_EQ(ours.verdictText, "reproduced by ours");
  EXPECT_EQ(listing.verdict, Verdict::Reproduced);
  EXPECT_EQ(listing.verdictText, "reproduced by the paper's printed listing; ours 14 mul, 6 add (+1 add)");
  EXPECT_EQ(neither.verdict, Verdict::Differs);
  EXPECT_EQ(neither.verdictText, "differs: ours 14 mul, 6 add (+1 add); listing 14 mul, 7 add (+2 add)");
}

TEST(Evaluate, AnUndefinedExpansionIsInconclusiveWhenItDiffers) {
  const json paper = {{"mul", 33}, {"add", 29}};
  const std::vector<Evidence> ev = {{"counted", "ops:kernel.sw_mp_naive", ""}};
  const claims::Claim differs = claims::evaluate(row(RuleKind::PaperColumnsUndefined, ev, 0, paper),
                                                 setOf({{"ops", columns("kernel.sw_mp_naive", 36, 33)}}));
  EXPECT_EQ(differs.verdict, Verdict::Inconclusive);
  EXPECT_EQ(differs.verdictText, "inconclusive: counted 36 mul, 33 add (+3 mul, +4 add)");
  EXPECT_EQ(claims::evaluate(row(RuleKind::PaperColumnsUndefined, ev, 0, paper),
                             setOf({{"ops", columns("kernel.sw_mp_naive", 33, 29)}}))
                .verdict,
            Verdict::Reproduced);
}

// ---- thresholds

TEST(Evaluate, AtMostOnOneRatio) {
  const auto set = setOf({{"report", {fig("a.motor", 89), fig("a.matrix", 85), fig("b.motor", 132), fig("b.matrix", 113)}}});
  const claims::Claim pass = claims::evaluate(row(RuleKind::AtMost, {{"to world", "report:a.motor", "report:a.matrix"}}, 1.1), set);
  EXPECT_EQ(pass.verdict, Verdict::Reproduced) << pass.verdictText;
  EXPECT_EQ(pass.measured, "to world 1.05x (89 ops / 85 ops)");  // 89 / 85 = 1.047
  EXPECT_DOUBLE_EQ(pass.declared["evidence"][0]["read"].get<double>(), 89.0 / 85.0);
  const claims::Claim fail = claims::evaluate(row(RuleKind::AtMost, {{"to clip", "report:b.motor", "report:b.matrix"}}, 1.1), set);
  EXPECT_EQ(fail.verdict, Verdict::Differs);  // 132 / 113 = 1.168
  EXPECT_EQ(fail.verdictText, "differs: to clip 1.17x (132 ops / 113 ops) under the rule (each ratio <= 1.1)");
  // The bound itself passes.
  const auto at = setOf({{"report", {fig("r", 1.1, "x")}}});
  EXPECT_EQ(claims::evaluate(row(RuleKind::AtMost, {{"r", "report:r", ""}}, 1.1), at).verdict, Verdict::Reproduced);
}

TEST(Evaluate, SeveralKindsAllNoneOrSomePass) {
  const auto set = setOf({{"report", {fig("low", 0.8, "x"), fig("low2", 0.9, "x"), fig("high", 1.3, "x"), fig("high2", 1.2, "x")}}});
  auto judge = [&](RuleKind k, const char* a, const char* b) {
    return claims::evaluate(row(k, {{"A", std::string("report:") + a, ""}, {"B", std::string("report:") + b, ""}}, 1.0), set);
  };
  const claims::Claim all = judge(RuleKind::AtMost, "low", "low2"), none = judge(RuleKind::AtMost, "high", "high2"),
                      some = judge(RuleKind::AtMost, "low", "high");
  EXPECT_EQ(all.verdict, Verdict::Reproduced);
  EXPECT_TRUE(has(all.verdictText, "every kind passes A 0.8x, B 0.9x")) << all.verdictText;
  EXPECT_EQ(none.verdict, Verdict::Differs);
  EXPECT_EQ(some.verdict, Verdict::Inconclusive);
  EXPECT_TRUE(has(some.verdictText, "passes A 0.8x; fails B 1.3x")) << some.verdictText;
  EXPECT_EQ(some.declared["evidence"][0]["passes"], true);
  EXPECT_EQ(some.declared["evidence"][1]["passes"], false);
  // AtLeast is the mirror: 1.3 and 1.2 >= 1 reproduce, 0.8 and 0.9 differ, a mix is inconclusive.
  EXPECT_EQ(judge(RuleKind::AtLeast, "high", "high2").verdict, Verdict::Reproduced);
  EXPECT_EQ(judge(RuleKind::AtLeast, "low", "low2").verdict, Verdict::Differs);
  EXPECT_EQ(judge(RuleKind::AtLeast, "high", "low").verdict, Verdict::Inconclusive);
  EXPECT_EQ(judge(RuleKind::AtLeast, "high", "low").declared["rule"]["kind"], "at_least");
}

// ---- evidence left out, and named

TEST(Evaluate, AMissingFigureIsLeftOutAndTheRestJudged) {
  claims::FigureSet set = setOf({{"report", {fig("low", 0.8, "x")}}});
  set.missing["ops"] = "ops.json: not found; made by motorbench ops --json DIR/ops.json";
  const claims::Claim c = claims::evaluate(
      row(RuleKind::AtMost, {{"A", "report:low", ""}, {"B", "report:nope", ""}, {"C", "ops:kernel.x.total", ""}}, 1.0), set);
  EXPECT_EQ(c.verdict, Verdict::Reproduced) << c.verdictText;  // A alone is judged
  EXPECT_TRUE(has(c.verdictText, "left out: B: no figure report:nope; C: no figure ops:kernel.x.total "
                                 "(ops.json: not found; made by motorbench ops --json DIR/ops.json)"))
      << c.verdictText;
  EXPECT_EQ(c.declared["evidence"][1]["read"], json());
  EXPECT_EQ(c.declared["evidence"][1]["passes"], json());
  EXPECT_EQ(c.measured, "A 0.8x");
}

TEST(Evaluate, NotMeasuredDisturbedTooFewAndCpuRasterizerAreLeftOut) {
  figures::Figure nan = fig("nan", NAN, "x");
  nan.why = "no GPU";
  figures::Figure disturbed = fig("disturbed", 0.5, "x");
  disturbed.disturbed = {{"disturbed", true}, {"reason", "CPU time 40 % of real time"}};
  const figures::Figure few = fig("few", 0.5, "x", 4), enough = fig("enough", 0.5, "x", 5),
                        cpu = fig("cpu", 0.5, "x", 8, "CPU rasterizer (llvmpipe)"), gpu = fig("gpu", 1.5, "x", 8, "GPU (AMD)");
  const auto set = setOf({{"report", {nan, disturbed, few, enough, cpu, gpu}}});
  auto leftOut = [&](const std::string& name) {
    claims::ClaimRow r = row(RuleKind::AtMost, {{"one", "report:" + name, ""}}, 1.0);
    r.rule.minN = 5;
    r.rule.gpuTimed = true;
    const claims::Claim c = claims::evaluate(r, set);
    const json& why = c.declared["evidence"][0]["leftOut"];
    return std::make_pair(c.verdict, why.is_string() ? why.get<std::string>() : std::string());
  };
  EXPECT_EQ(leftOut("nan"), std::make_pair(Verdict::NotMeasurable, std::string("report:nan not measured: no GPU")));
  EXPECT_EQ(leftOut("disturbed"),
            std::make_pair(Verdict::NotMeasurable, std::string("report:disturbed disturbed (CPU time 40 % of real time)")));
  EXPECT_EQ(leftOut("few"),
            std::make_pair(Verdict::NotMeasurable, std::string("report:few: n = 4 < 5, too few to carry a verdict")));
  EXPECT_EQ(leftOut("enough"), std::make_pair(Verdict::Reproduced, std::string()));  // n = minN carries one
  EXPECT_EQ(leftOut("cpu"), std::make_pair(Verdict::NotMeasurable,
                                           std::string("report:cpu was timed on a CPU rasterizer, which cannot stand for a GPU")));
  EXPECT_EQ(leftOut("gpu"), std::make_pair(Verdict::Differs, std::string()));  // 1.5 > 1: judged, and it fails
  // The same figure without the GPU rule is judged wherever it was timed.
  EXPECT_EQ(claims::evaluate(row(RuleKind::AtMost, {{"one", "report:cpu", ""}}, 1.0), set).verdict, Verdict::Reproduced);
  // The rule applies to the denominator too.
  claims::ClaimRow ratio = row(RuleKind::AtMost, {{"gpu / cpu", "report:gpu", "report:cpu"}}, 10);
  ratio.rule.gpuTimed = true;
  EXPECT_EQ(claims::evaluate(ratio, set).verdict, Verdict::NotMeasurable);
}

TEST(Evaluate, NothingLeftIsNotMeasurableWithEveryReasonNamed) {
  const auto set = setOf({{"report", {fig("zero", 0, "ops"), fig("one", 1, "ops")}}});
  const claims::Claim c =
      claims::evaluate(row(RuleKind::AtMost, {{"A", "report:gone", ""}, {"B", "report:one", "report:zero"}}, 1.0), set);
  EXPECT_EQ(c.verdict, Verdict::NotMeasurable);
  EXPECT_EQ(c.verdictText, "not measurable here: A: no figure report:gone; B: report:zero is 0");
  EXPECT_EQ(c.measured, "-");
  EXPECT_TRUE(c.measuredValue.is_null());
  EXPECT_EQ(claims::evaluate(row(RuleKind::AtMost, {}, 1.0), set).verdictText, "not measurable here: no evidence declared");
}

TEST(Evaluate, ABaselinePrintsItsFiguresWithoutAVerdict) {
  const auto set = setOf({{"ops", {fig("variant.matrix.total", 113), fig("variant.motor.total", 132)}}});
  const claims::Claim c = claims::evaluate(
      row(RuleKind::Baseline, {{"matrix", "ops:variant.matrix.total", ""},
                               {"motor / matrix", "ops:variant.motor.total", "ops:variant.matrix.total"},
                               {"absent", "ops:variant.none.total", ""}}),
      set);
  EXPECT_EQ(c.verdict, Verdict::Baseline);
  EXPECT_EQ(c.verdictText, "baseline (left out: absent: no figure ops:variant.none.total)");
  EXPECT_EQ(c.measured, "matrix 113 ops; motor / matrix 1.17x (132 ops / 113 ops)");
  EXPECT_EQ(c.declared["evidence"][0]["passes"], json());  // no rule to pass
  EXPECT_DOUBLE_EQ(c.declared["evidence"][1]["read"].get<double>(), 132.0 / 113.0);
  EXPECT_EQ(claims::evaluate(row(RuleKind::Baseline, {{"absent", "ops:none", ""}}), set).verdict, Verdict::NotMeasurable);
}

}  // namespace
