// The corpus rules of `check --rules` (harness/check/corpus_rows.h, corpus_verdicts.h,
// corpus_junit.h) on synthetic survey documents: the rigid and 16-byte rules judged outside the tie
// pixels, counted omissions listed and not judged, skinned frames against their own skinning
// method's reference, the totals, the per-frame JUnit cases, and the option errors. The figures
// and texts are the ones hand-derived from each made-up frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "harness/check/corpus_junit.h"
#include "harness/check/corpus_rules.h"
#include "harness/check/corpus_verdicts.h"

namespace {

using mb::check::ojson;

const mb::check::RuleSet& ruleSet() {
  static const mb::check::RuleSet set = mb::check::defaultRuleSet();
  return set;
}

mb::check::WorkerRecord record(const ojson& doc) {
  mb::check::WorkerRecord rec;
  rec.exit = 0;
  rec.doc = doc;
  rec.seconds = 1.0;
  return rec;
}

ojson tieSet(int pixels, int renders) {
  ojson set = ojson::array();
  for (int i = 0; i < pixels; ++i) set.push_back(i);
  return {{"pixels", pixels}, {"renders", renders}, {"set", set}};
}

// The file result of a made-up one-frame rigid survey: matrix plus motor's and matrix_c's frames
// when given (each merged over {"drawnPixels": 5000}); ties < 0: the survey gave no tie data.
ojson syntheticResult(const ojson& motor, const ojson& matrixC = nullptr, int ties = 16, int int16Ties = 9) {
  ojson frame = {{"animation", nullptr},
                 {"time", 0.0},
                 {"kind", "rigid"},
                 {"positionBound", {{"worldUnits", 1e-5}, {"pixels", 0.01}, {"envelopeRadius", 1}, {"shadeTolerance", 4}}}};
  if (ties >= 0) frame["ties"] = tieSet(ties, 2);
  if (int16Ties >= 0) frame["int16Ties"] = tieSet(int16Ties, 5);
  ojson pipelines = {{"matrix", {{"error", nullptr}, {"frames", {{{"drawnPixels", 5000}}}}, {"fallbacks", ojson::object()},
                                 {"seconds", 0.1}}}};
  for (const auto& [name, f] : {std::pair<const char*, const ojson*>{"motor", &motor}, {"matrix_c", &matrixC}}) {
    if (f->is_null()) continue;
    ojson merged = {{"drawnPixels", 5000}};
    merged.update(*f);
    pipelines[name] = {{"error", nullptr}, {"frames", {merged}}, {"fallbacks", ojson::object()}, {"seconds", 0.1}};
  }
  ojson order = ojson::array();
  for (const auto& [name, p] : pipelines.items()) order.push_back(name);
  const ojson doc = {{"status", "ok"}, {"baseline", "matrix"}, {"pipelineOrder", order}, {"frames", {frame}},
                     {"pipelines", pipelines}, {"scene", ojson::object()}, {"loaderFallbacks", ojson::object()}};
  return mb::check::fileResult("x.glb", record(doc), "", ruleSet());
}

mb::check::Rule ruleStarting(const mb::check::Verdicts& v, const std::string& start) {
  for (const mb::check::Rule& r : v.rules)
    if (r.name.rfind(start, 0) == 0) return r;
  throw std::runtime_error("no rule " + start);
}

std::string allLines(const mb::check::Verdicts& v) {
  std::string text;
  for (const std::string& l : mb::check::ruleLines(v, ruleSet())) text += l + "\n";
  return text;
}

TEST(CorpusRulesTies, AFrameWhoseFailingPixelsAreAllTiesPassesWithTheMark) {
  // A court's case: 42.4 dB, 16 differing pixels, every one a tie.
  const ojson res = syntheticResult({{"identical", false}, {"psnr", 42.4}, {"differingPixels", 16}, {"differingNotTies", 0},
                                     {"identicalNotTies", true}, {"psnrNotTies", nullptr}});
  const mb::check::Verdicts v = mb::check::evaluate({res}, ruleSet());
  const mb::check::Rule rigid = ruleStarting(v, "rigid frames of motor");
  EXPECT_TRUE(rigid.failures.empty());
  ASSERT_EQ(rigid.passedMarked.size(), 1u);
  EXPECT_NE(rigid.passedMarked[0].find("x.glb [motor] rest: 42.40 dB; identical dB outside the 16 tie pixels"), std::string::npos)
      << rigid.passedMarked[0];
  const std::string lines = allLines(v);
  EXPECT_NE(lines.find("PASS: rigid frames of motor"), std::string::npos);
  EXPECT_NE(lines.find("(1 frames pass on ties)"), std::string::npos);
  EXPECT_NE(lines.find("PASS (ties: undetermined by the transform): x.glb [motor] rest"), std::string::npos);
  const ojson per = mb::check::totals({res}, {"matrix", "motor"}, ruleSet());
  EXPECT_EQ(per["motor"]["rigidTieFrames"], 1);
  EXPECT_EQ(per["motor"]["rigidFilesFailing"], 0);
  EXPECT_EQ(per["motor"]["rigidFilesBelow50dB"], 1);  // the raw figure stays visible
}

TEST(CorpusRulesTies, RoundingOutsideTheTiesThatTheBoundAllowsStillPasses) {
  // motor on a court also differs by one byte in 8 non-tie pixels: 66 dB outside the ties.
  const ojson res = syntheticResult({{"identical", false}, {"psnr", 42.4}, {"differingPixels", 37}, {"differingNotTies", 8},
                                     {"identicalNotTies", false}, {"psnrNotTies", 66.0}});
  const mb::check::Rule rigid = ruleStarting(mb::check::evaluate({res}, ruleSet()), "rigid frames of motor");
  EXPECT_TRUE(rigid.failures.empty());
  ASSERT_EQ(rigid.passedMarked.size(), 1u);
  EXPECT_NE(rigid.passedMarked[0].find("66.0 dB outside the 16 tie pixels (37 px differ, 8 of them not ties)"), std::string::npos)
      << rigid.passedMarked[0];
}

TEST(CorpusRulesTies, AFrameWithAFailingPixelOutsideTheTieSetStillFails) {
  const ojson res = syntheticResult({{"identical", false}, {"psnr", 42.0}, {"differingPixels", 17}, {"differingNotTies", 1},
                                     {"identicalNotTies", false}, {"psnrNotTies", 43.5}});
  const mb::check::Verdicts v = mb::check::evaluate({res}, ruleSet());
  const mb::check::Rule rigid = ruleStarting(v, "rigid frames of motor");
  EXPECT_TRUE(rigid.passedMarked.empty());
  EXPECT_EQ(rigid.failures, std::vector<std::string>{"x.glb [motor]: 42.00 dB, 43.5 dB outside the tie pixels"});
  EXPECT_NE(allLines(v).find("FAIL: rigid frames of motor"), std::string::npos);
  EXPECT_FALSE(v.pass());
  EXPECT_EQ(mb::check::totals({res}, {"motor"}, ruleSet())["motor"]["rigidFilesFailing"], 1);
}

TEST(CorpusRulesTies, ASurveyWithoutTieDataIsJudgedOnEveryPixel) {
  const ojson res = syntheticResult({{"identical", false}, {"psnr", 42.0}}, nullptr, -1);
  const mb::check::Rule rigid = ruleStarting(mb::check::evaluate({res}, ruleSet()), "rigid frames of motor");
  EXPECT_EQ(rigid.failures.size(), 1u);
  EXPECT_TRUE(rigid.passedMarked.empty());
}

TEST(CorpusRulesTies, ACountedMorphOmissionIsListedNotJudged) {
  // motor draws a morphed node in its base shape and counts it (morphNotDrawnNodes): no image
  // rule judges that frame; it is listed apart with its count and PSNR.
  const ojson res = syntheticResult({{"identical", false}, {"psnr", 22.0}, {"fallbacks", {{"morphNotDrawnNodes", 1}}}});
  const mb::check::Verdicts v = mb::check::evaluate({res}, ruleSet());
  EXPECT_TRUE(ruleStarting(v, "rigid frames of motor").failures.empty());
  ASSERT_EQ(v.counted.size(), 1u);
  EXPECT_EQ(v.counted[0].first, "counted omission: motor does not morph");
  EXPECT_EQ(v.counted[0].second, "x.glb [motor] rest: 1 morphed node(s) drawn in their base shape, 22.0 dB against matrix");
  EXPECT_NE(allLines(v).find("- COUNTED: frames judged by no image rule: a feature the pipeline counts as not drawn (1)\n"),
            std::string::npos);
  // The same frame without the count is a failure.
  const ojson plain = syntheticResult({{"identical", false}, {"psnr", 22.0}});
  EXPECT_EQ(ruleStarting(mb::check::evaluate({plain}, ruleSet()), "rigid frames of motor").failures.size(), 1u);
}

TEST(CorpusRulesTies, TheSixteenByteRuleBothWays) {
  const ojson ok = syntheticResult(nullptr, {{"identical", false}, {"psnr", 45.0}, {"outsideEnvelope", 2}, {"envelopeExcess", 90},
                                             {"outsideEnvelopeNotTies", 0}, {"envelopeExcessNotTies", 3}});
  const mb::check::Rule pass = ruleStarting(mb::check::evaluate({ok}, ruleSet()), "rigid frames of matrix_c");
  EXPECT_TRUE(pass.failures.empty());
  EXPECT_EQ(pass.passedMarked, std::vector<std::string>{"x.glb [matrix_c] rest: 2 px outside the envelope, every one of them "
                                                        "an int16-cell tie pixel (9 in the frame)"});
  EXPECT_EQ(mb::check::totals({ok}, {"matrix_c"}, ruleSet())["matrix_c"]["compactTieFrames"], 1);
  const ojson bad = syntheticResult(nullptr, {{"identical", false}, {"psnr", 45.0}, {"outsideEnvelope", 3}, {"envelopeExcess", 90},
                                              {"outsideEnvelopeNotTies", 1}, {"envelopeExcessNotTies", 40}});
  const mb::check::Rule fail = ruleStarting(mb::check::evaluate({bad}, ruleSet()), "rigid frames of matrix_c");
  EXPECT_TRUE(fail.passedMarked.empty());
  ASSERT_EQ(fail.failures.size(), 1u);
  EXPECT_NE(fail.failures[0].find("3 px outside the envelope (1 not tie pixels)"), std::string::npos) << fail.failures[0];
}

// A one-frame skinned survey: matrix and motor, motor's frame 40 dB from matrix and 90 dB from
// the motor-blend reference, with the drawn-pixel counts given.
ojson skinnedResult(int motorDrawn, int referenceDrawn, int matrixDrawn = 1000) {
  const ojson frame = {{"animation", 0}, {"time", 0.5}, {"kind", "skinned"}, {"motorBlendReference", {{"drawnPixels", referenceDrawn}}}};
  const ojson pipelines = {
      {"matrix", {{"error", nullptr}, {"frames", {{{"drawnPixels", matrixDrawn}}}}, {"fallbacks", ojson::object()}, {"seconds", 0.1}}},
      {"motor",
       {{"error", nullptr},
        {"frames", {{{"drawnPixels", motorDrawn}, {"psnr", 40.0}, {"motorBlend", {{"identical", false}, {"psnr", 90.0}}}}}},
        {"fallbacks", ojson::object()},
        {"seconds", 0.1}}}};
  const ojson doc = {{"status", "ok"}, {"baseline", "matrix"}, {"pipelineOrder", {"matrix", "motor"}}, {"frames", {frame}},
                     {"pipelines", pipelines}, {"scene", ojson::object()}, {"loaderFallbacks", ojson::object()},
                     {"motorBlendReference", {{"available", true}, {"why", nullptr}}}};
  return mb::check::fileResult("s.glb", record(doc), "", ruleSet());
}

TEST(CorpusRulesSkinned, MotorJudgedAgainstTheMotorBlend) {
  // 2 % from matrix but on its own method's reference: passes, listed as a method difference.
  const mb::check::Rule ok = ruleStarting(mb::check::evaluate({skinnedResult(1020, 1020)}, ruleSet()), "skinned frames");
  EXPECT_TRUE(ok.failures.empty());
  ASSERT_EQ(ok.passedMarked.size(), 1u);
  EXPECT_NE(ok.passedMarked[0].find("s.glb [motor]: t=0.5 2.0 % apart from matrix; from its own method's reference t=0.5 0.0 %, "
                                    "90.0 dB"),
            std::string::npos)
      << ok.passedMarked[0];
  // Within 1 % of matrix but 2 % from its own reference: a failure naming the reference.
  const mb::check::Rule bad = ruleStarting(mb::check::evaluate({skinnedResult(1000, 1020)}, ruleSet()), "skinned frames");
  ASSERT_EQ(bad.failures.size(), 1u);
  EXPECT_NE(bad.failures[0].find("apart from motor blend (GLM dual quaternions, drawn by matrix) by t=0.5 2.0 %"), std::string::npos)
      << bad.failures[0];
  // --max-drawn-diff 0.001: 0.10 % from the reference passes, 0.20 % fails; 2 % from matrix decides nothing.
  mb::check::RuleSet tight = ruleSet();
  tight.maxDrawnDiff = 0.001;
  EXPECT_TRUE(ruleStarting(mb::check::evaluate({skinnedResult(1020, 1021)}, tight), "skinned frames").failures.empty());
  EXPECT_EQ(ruleStarting(mb::check::evaluate({skinnedResult(1020, 1022)}, tight), "skinned frames").failures.size(), 1u);
}

TEST(CorpusRulesJunit, OneCasePerFileFramePipelineWithTheRuleThatFailed) {
  const ojson failing = syntheticResult({{"identical", false}, {"psnr", 42.0}, {"differingPixels", 17}, {"differingNotTies", 1},
                                         {"identicalNotTies", false}, {"psnrNotTies", 43.5}});
  const std::vector<mb::check::JunitCase> cases = mb::check::junitCases({failing, skinnedResult(1000, 1020)}, ruleSet());
  ASSERT_EQ(cases.size(), 4u);  // x.glb and s.glb, one frame each, matrix and motor
  EXPECT_EQ(cases[0].classname, "check.rules.x.glb");
  EXPECT_EQ(cases[0].name, "rest.matrix");
  EXPECT_EQ(cases[0].kind, mb::check::JunitCase::Kind::Pass);
  EXPECT_EQ(cases[1].name, "rest.motor");
  EXPECT_EQ(cases[1].kind, mb::check::JunitCase::Kind::Fail);
  EXPECT_EQ(cases[1].message, "rigid frames vs matrix >= 50 dB: 42.00 dB, 43.5 dB outside the tie pixels");
  EXPECT_EQ(cases[3].name, "t=0.5.motor");
  EXPECT_EQ(cases[3].kind, mb::check::JunitCase::Kind::Fail);
  EXPECT_NE(cases[3].message.find("2.0 % apart from motor blend"), std::string::npos) << cases[3].message;
  // The frames that pass on ties are passes.
  const ojson ties = syntheticResult({{"identical", false}, {"psnr", 42.4}, {"differingPixels", 16}, {"differingNotTies", 0},
                                      {"identicalNotTies", true}, {"psnrNotTies", nullptr}});
  EXPECT_EQ(mb::check::junitCases({ties}, ruleSet())[1].kind, mb::check::JunitCase::Kind::Pass);
}

TEST(CorpusRulesOptions, BadInputsExitTwoBeforeAnyWorker) {
  EXPECT_EQ(mb::check::runCheckRules({"--rules"}), 2);
  EXPECT_EQ(mb::check::runCheckRules({"--rules", "/nonexistent/corpus"}), 2);
  const std::string here = MB_SOURCE_DIR "/tests/check";
  EXPECT_EQ(mb::check::runCheckRules({"--rules", here, "--max-drawn-diff", "1"}), 2);  // 1 would be 100 %
  EXPECT_EQ(mb::check::runCheckRules({"--rules", here, "--pipelines", "Motor"}), 2);
  EXPECT_EQ(mb::check::runCheckRules({"--rules", here, "--min-psnr", "-3"}), 2);
  EXPECT_EQ(mb::check::runCheckRules({"--rules", here, "--out", "/proc/nope"}), 2);
  const std::string out = (std::filesystem::temp_directory_path() / "check-rules-options-test").string();
  EXPECT_EQ(mb::check::runCheckRules({"--rules", here, "--out", out}), 2);  // no .gltf/.glb under tests/check
  std::filesystem::remove_all(out);
  const mb::check::RuleSet only = mb::check::defaultRuleSet({"motor", "motor_c"});
  EXPECT_EQ(only.fullPrecision, std::vector<std::string>{"motor"});
  EXPECT_EQ(only.compact, std::vector<std::string>{"motor_c"});
  EXPECT_EQ(only.motorBlend, (std::vector<std::string>{"motor", "motor_c"}));
  EXPECT_EQ(ruleSet().fullPrecision, (std::vector<std::string>{"motor", "affine", "qtangent", "motor_q", "hybrid"}));
  EXPECT_EQ(ruleSet().compact, (std::vector<std::string>{"matrix_c", "motor_c", "motor_cf"}));
  EXPECT_EQ(ruleSet().motorBlend, (std::vector<std::string>{"motor", "motor_q", "motor_c", "motor_cf"}));
}

}  // namespace
