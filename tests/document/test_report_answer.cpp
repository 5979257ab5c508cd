// The answer block (harness/document/report_answer.h): its lines quote report.json's
// figures by name, and each verdict follows from those figures as the line's rule says.
#include <gtest/gtest.h>

#include <regex>

#include "harness/claims/claims_layout.h"
#include "harness/document/report_answer.h"
#include "harness/document/report_answer_figures.h"
#include "harness/document/report_figures.h"
#include "harness/document/report_format.h"
#include "harness/figures/figure.h"

namespace mb::document {
namespace {

using json = nlohmann::json;

figures::Figure fig(const std::string& name, double value, const std::string& unit, int n = 1,
                    std::optional<double> q1 = {}, std::optional<double> q3 = {}) {
  figures::Figure f;
  f.name = name, f.value = value, f.unit = unit, f.n = n, f.q1 = q1, f.q3 = q3;
  return f;
}

// Three scenes; matrix fetches 48 B per vertex, motor 36 (frames 100/200/400 vs 75/150/300
// bytes: 0.75 each); one frame each, motor's PSNR 60, 70 and identical.
json syntheticReport(bool realGpu) {
  json r = {{"settings", {{"pipelines", {"matrix", "motor"}}, {"baseline", "matrix"}}},
            {"machine", {{"gl", {{"renderer", realGpu ? "NVIDIA H100" : "llvmpipe"}, {"realGpu", realGpu}}}}},
            {"scenes", json::array()}, {"figures", json::object()}};
  const double matrixBytes[] = {100, 200, 400}, psnr[] = {60, 70, -1};
  for (int i = 0; i < 3; ++i) {
    json m = psnr[i] < 0 ? json{{"identical", true}, {"psnr", nullptr}} : json{{"identical", false}, {"psnr", psnr[i]}};
    r["scenes"].push_back(
        {{"id", "s" + std::to_string(i)}, {"space", "Euclidean"},
         {"pipelines", {{"matrix", {{"vertexFetch", {{"bytesFetchedPerFrame", matrixBytes[i]}, {"bytesFetchedPerVertex", 48}}}}},
                        {"motor", {{"vertexFetch", {{"bytesFetchedPerFrame", 0.75 * matrixBytes[i]}, {"bytesFetchedPerVertex", 36}}}}}}},
         {"frames", json::array({{{"metrics", {{"motor", m}}}}})}});
  }
  figures::put(r["figures"], fig("bytes_per_vertex.matrix", 48, "bytes"));
  figures::put(r["figures"], fig("bytes_per_vertex.motor", 36, "bytes"));
  figures::put(r["figures"], fig("ops_per_vertex.rigid.counted.matrix", 85, "ops"));
  figures::put(r["figures"], fig("ops_per_vertex.rigid.counted.motor", 89, "ops"));
  figures::put(r["figures"], fig("ops_per_vertex.to_clip.counted.matrix", 113, "ops"));
  figures::put(r["figures"], fig("ops_per_vertex.to_clip.counted.motor", 132, "ops"));
  figures::put(r["figures"], fig("frame_time.motor_over_matrix", 0.9, "x", 3, 0.85, 0.95));
  r["isa"] = {{"families", {{{"id", "tahiti"}}, {{"id", "gfx1100"}}}},
              {"shaders", {{{"stage", "vertex"}, {"pipeline", "matrix"}, {"familyId", "tahiti"}, {"labels", {"rigid"}}, {"instructions", 115}},
                           {{"stage", "vertex"}, {"pipeline", "motor"}, {"familyId", "tahiti"}, {"labels", {"rigid"}}, {"instructions", 125}},
                           {{"stage", "vertex"}, {"pipeline", "matrix"}, {"familyId", "gfx1100"}, {"labels", {"rigid"}}, {"instructions", 153}},
                           {{"stage", "vertex"}, {"pipeline", "motor"}, {"familyId", "gfx1100"}, {"labels", {"rigid"}}, {"instructions", 150}}}}};
  addAnswerFigures(r);
  return r;
}

const AnswerLine& line(const std::vector<AnswerLine>& lines, const std::string& evidence) {
  for (const AnswerLine& l : lines)
    if (l.evidence.find(evidence) == 0) return l;
  static AnswerLine none;
  ADD_FAILURE() << "no line " << evidence;
  return none;
}

TEST(ReportAnswer, FiguresComputedFromTheScenes) {
  const json r = syntheticReport(false);
  const auto ratio = figures::figureNamed(r, "vertex_fetch.bytes_per_frame_over_baseline.motor");
  ASSERT_TRUE(ratio);
  EXPECT_DOUBLE_EQ(ratio->value, 0.75);  // 75/100, 150/200, 300/400
  EXPECT_EQ(ratio->n, 3);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "vertex_fetch.bytes_per_vertex.motor")->value, 36);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "isa.instructions.rigid.gfx1100.motor")->value, 150);
  // Worst PSNR over the frames that differ (60 of 60, 70); the identical frame counted apart.
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "image.worst_psnr.motor")->value, 60);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "image.identical_frames.motor")->value, 1);
  EXPECT_EQ(figures::figureNamed(r, "image.identical_frames.motor")->n, 3);
  EXPECT_EQ(r["pipelineFamilies"]["motor"], "motor");
  EXPECT_EQ(r["pipelineFamilies"]["matrix"], "matrix");
}

TEST(ReportAnswer, EveryLineQuotesItsFiguresAsReportJsonHasThem) {
  const json r = syntheticReport(false);
  const std::vector<AnswerLine> lines = answerLines(r);
  ASSERT_EQ(lines.size(), 5u);
  for (const AnswerLine& l : lines) {
    EXPECT_FALSE(l.anchor.empty()) << l.evidence;
    for (const std::string& name : l.figures) {
      const auto f = figures::figureNamed(r, name);
      if (!f || !std::isfinite(f->value) || name.rfind("isa.", 0) == 0 || name.rfind("image.identical", 0) == 0) continue;
      EXPECT_NE(l.text.find(figures::valueText(*f)), std::string::npos) << l.evidence << ": " << name << " = "
                                                                         << figures::valueText(*f) << " not in: " << l.text;
    }
  }
  // The ISA line quotes the scope ladder's cell: 150/153 = 0.98 (gfx1100) .. 125/115 = 1.09 (tahiti).
  EXPECT_NE(line(lines, "AMD ISA").text.find("2 families"), std::string::npos) << line(lines, "AMD ISA").text;
  EXPECT_NE(line(lines, "AMD ISA").text.find("instructions 0.98..1.09x as cheap"), std::string::npos)
      << line(lines, "AMD ISA").text;
  // The ops line: to world 89/85 = 1.05 (the paper's scope), to clip 132/113 = 1.17.
  EXPECT_NE(line(lines, "ops").text.find("to world (the paper's scope) counted 89 ops / 85 ops 1.05x as cheap"),
            std::string::npos) << line(lines, "ops").text;
  EXPECT_NE(line(lines, "ops").text.find("132 ops / 113 ops 1.17x dearer"), std::string::npos) << line(lines, "ops").text;
  EXPECT_NE(line(lines, "image").text.find("1 of 3 frames identical"), std::string::npos);
}

// A skinned scene whose pipelines blend joints by different methods: each frame judged against
// motor's own method's reference (skinJudgement, referenceMetrics), not set aside. Its frames:
// 30 dB from matrix but 55 dB from the motor-blend reference; one whose reference could not be
// made (counted, with its reason); and a scene of a report made before such judgements (counted).
TEST(ReportAnswer, SkinnedFramesAreJudgedByTheirOwnMethodAndCounted) {
  json r = syntheticReport(false);
  const json skinnedScene = {{"space", "Euclidean"}, {"vertexMix", {{"skinned", 100}}},
                             {"pipelines", {{"matrix", {{"skinBlend", "linear blend skinning"}}},
                                            {"motor", {{"skinBlend", "motor blending"}}}}}};
  const json vsMatrix = {{"identical", false}, {"psnr", 30}, {"flip", {{"mean", 0.2}}}};
  json tube = skinnedScene;
  tube["id"] = "tube";
  tube["frames"] = {
      {{"time", 0}, {"metrics", {{"motor", vsMatrix}}},
       {"skinJudgement", {{"motor", {{"reference", "motor-blend reference"}, {"judged", true}}}}},
       {"referenceMetrics", {{"motor", {{"identical", false}, {"psnr", 55}, {"flip", {{"mean", 0.01}}}}}}}},
      {{"time", 1}, {"metrics", {{"motor", vsMatrix}}},
       {"skinJudgement", {{"motor", {{"reference", "motor-blend reference"}, {"judged", false},
                                     {"why", "a skinned mesh drawn by more than one node"}}}}}}};
  json old = skinnedScene;
  old["id"] = "old";
  old["frames"] = {{{"time", 0}, {"metrics", {{"motor", vsMatrix}}}}};
  r["scenes"].push_back(tube);
  r["scenes"].push_back(old);
  r["summary"]["images"]["motor"]["notJudged"] = {"tube t=1: not judged against the motor-blend reference: a skinned "
                                                  "mesh drawn by more than one node"};
  addAnswerFigures(r);
  // Worst PSNR 55 (the reference's), not 30 (matrix's); 4 frames judged: three rigid, one skinned.
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "image.worst_psnr.motor")->value, 55);
  EXPECT_EQ(figures::figureNamed(r, "image.identical_frames.motor")->n, 4);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "image.skinned_frames_own_reference.motor")->value, 1);
  const auto notJudged = figures::figureNamed(r, "image.frames_not_judged.motor");
  EXPECT_DOUBLE_EQ(notJudged->value, 2);
  EXPECT_EQ(notJudged->n, 6);
  EXPECT_NE(notJudged->definition.find("not judged against the motor-blend reference: a skinned mesh drawn by more "
                                       "than one node"), std::string::npos) << notJudged->definition;
  EXPECT_NE(notJudged->definition.find("made before skinned frames were judged so"), std::string::npos);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "image.flip_mean_worst.motor")->value, 0.01);
  const AnswerLine image = line(answerLines(r), "image");
  EXPECT_NE(image.text.find("1 of 4 frames identical (of them 1 frames skinned, against the motor-blend reference: "
                            "motor's own skinning method, not matrix's)"), std::string::npos) << image.text;
  EXPECT_NE(image.text.find("; 2 frames not judged (first: tube t=1: not judged against the motor-blend reference: a "
                            "skinned mesh drawn by more than one node)"), std::string::npos) << image.text;
  EXPECT_EQ(image.verdict, "equivalent (every differing frame >= 50 dB); 2 frames not judged");
  // Only skinned frames, none judged: said so, not "not compared".
  json none = {{"settings", {{"pipelines", {"matrix", "motor"}}}}, {"scenes", json::array({old})}};
  addAnswerFigures(none);
  EXPECT_EQ(line(answerLines(none), "image").verdict, "not judged (1 frames not judged)");
}

TEST(ReportAnswer, VerdictsFollowTheFigures) {
  const std::vector<AnswerLine> cpu = answerLines(syntheticReport(false));
  EXPECT_EQ(line(cpu, "bytes").verdict, "motor side cheaper: it fetches fewer bytes");
  // Each scope judged by the one rule (motor / matrix <= 1.1): to world 89/85 passes, to clip 132/113 not.
  EXPECT_EQ(line(cpu, "ops").verdict, "to world as cheap, to clip dearer");
  // 125/115 and 150/153 both within 1.1; no throughput estimate in this report.
  EXPECT_EQ(line(cpu, "AMD ISA").verdict, "instructions as cheap, throughput estimate -");
  EXPECT_EQ(line(cpu, "time").verdict, "inconclusive: a CPU rasterizer cannot discriminate");
  EXPECT_EQ(line(cpu, "image").verdict, "equivalent (every differing frame >= 50 dB)");
  // On a GPU the spread decides: IQR 0.85..0.95 lies below 1.
  json gpu = syntheticReport(true);
  EXPECT_EQ(line(answerLines(gpu), "time").verdict, "motor side faster");
  figures::put(gpu["figures"], fig("frame_time.motor_over_matrix", 0.99, "x", 3, 0.95, 1.02));
  EXPECT_EQ(line(answerLines(gpu), "time").verdict, "no difference beyond the spread");
  figures::put(gpu["figures"], fig("image.worst_psnr.motor", 41, "dB", 2));
  EXPECT_EQ(line(answerLines(gpu), "image").verdict, "differs: worst 41 dB");
}

TEST(ReportAnswer, MissingEvidenceIsSaidNotInvented) {
  json r = {{"settings", {{"pipelines", {"matrix", "motor"}}}}};
  addAnswerFigures(r);
  const std::vector<AnswerLine> lines = answerLines(r);
  EXPECT_EQ(line(lines, "bytes").verdict, "not measured");
  EXPECT_EQ(line(lines, "AMD ISA").verdict, "not measured");
  EXPECT_EQ(line(lines, "image").verdict, "not compared");
}

// The rows of a Markdown document's answer table (between "## The answer" and the next heading):
// evidence | figures | verdict, the evidence's link dropped (claims.md links into report.md).
std::vector<std::string> answerRows(const std::string& md) {
  const size_t start = md.find("## The answer");
  EXPECT_NE(start, std::string::npos) << md.substr(0, 300);
  if (start == std::string::npos) return {};
  const size_t end = md.find("\n## ", start + 1);
  const std::string block = md.substr(start, end == std::string::npos ? std::string::npos : end - start);
  std::vector<std::string> rows;
  const std::regex row("\\| \\[([^\\]]*)\\]\\([^)]*\\) \\|([^\\n]*)");
  for (auto it = std::sregex_iterator(block.begin(), block.end(), row); it != std::sregex_iterator(); ++it)
    rows.push_back((*it)[1].str() + " |" + (*it)[2].str());
  return rows;
}

// report.md's answer block as reportDocument lays it out (first, as in report_layout.cpp).
std::string reportAnswerMd(const json& r) {
  Document d;
  answerSection(d, r);
  return toMarkdown(d);
}

// claims.md opens with the same answer lines as report.md, made from the same report.json
// (claims reads the figures; it measures none of them), each figure marked by its name.
// tests/document/test_documents_agree.py checks the same on results/ (real report.json).
TEST(ReportAnswer, ClaimsOpenWithTheReportsAnswerLines) {
  const json r = syntheticReport(false);
  const std::string reportMd = reportAnswerMd(r);
  const json machine = {{"cpu", "a CPU"}, {"logicalCores", 2}, {"os", "Linux"}, {"date", "today"}};
  const json claimsJson = claims::claimsJson({}, machine, json::object());
  const std::string claimsMd = toMarkdown(withAnswerFirst(claims::claimsDocument(claimsJson), r, "report.md"));
  const std::vector<std::string> fromReport = answerRows(reportMd), fromClaims = answerRows(claimsMd);
  ASSERT_EQ(fromReport.size(), 5u) << reportMd.substr(0, 2000);
  EXPECT_EQ(fromClaims, fromReport);
  EXPECT_LT(claimsMd.find("## The answer"), claimsMd.find("## Verdicts"));  // first in claims.md
  EXPECT_NE(claimsMd.find("](report.md#gpu-evidence)"), std::string::npos);  // links into report.md
  // Every figure a line prints is marked with its name, its value as report.json has it.
  EXPECT_NE(fromReport[0].find("<span title=\"bytes_per_vertex.motor\">36 bytes</span>"), std::string::npos) << fromReport[0];
  EXPECT_NE(fromReport[3].find("<span title=\"frame_time.motor_over_matrix\">0.9x</span>"), std::string::npos) << fromReport[3];
  EXPECT_EQ(withoutFigureMarks(figureMark("a.b", "1 B") + " and " + figureMark("c", "2")), "1 B and 2");
  // A changed figure changes both documents' line alike.
  json changed = r;
  figures::put(changed["figures"], fig("frame_time.motor_over_matrix", 1.2, "x", 3, 1.1, 1.3));
  const std::vector<std::string> after = answerRows(toMarkdown(withAnswerFirst(claims::claimsDocument(claimsJson), changed, "report.md")));
  EXPECT_NE(after, fromReport);
  EXPECT_EQ(after, answerRows(reportAnswerMd(changed)));
}

}  // namespace
}  // namespace mb::document

namespace mb::document {
namespace {

// reportFigures' fallback.* figures of `scenes` into r's figures.
void addFallbackFigures(json& r, const std::vector<json>& scenes) {
  const json all = reportFigures(r["machine"], r["settings"], scenes, json::object(), json::object());
  for (const auto& [name, f] : all.items())
    if (name.rfind("fallback.", 0) == 0) r["figures"][name] = f;
}

// The exact fallback's figures (fallback.<what>.<p>: each scene's most in any frame, summed over
// the scenes) and the time line that quotes them: two of three scenes drew with it.
TEST(ReportAnswer, TheTimeLineSaysHowMuchTheMotorDrewWithItsExactFallback) {
  json r = syntheticReport(false);
  const json fallbacks[] = {{{"linearFallbackDraws", 2}, {"skinFallbackDraws", 1}, {"skinFallbackJoints", 20}, {"fallbackVertices", 500}},
                            {{"linearFallbackDraws", 0}, {"skinFallbackDraws", 3}, {"skinFallbackJoints", 30}, {"fallbackVertices", 700}},
                            {{"linearFallbackDraws", 0}, {"skinFallbackDraws", 0}, {"skinFallbackJoints", 0}, {"fallbackVertices", 0}}};
  std::vector<json> scenes;
  for (int i = 0; i < 3; ++i) {
    r["scenes"][i]["pipelines"]["motor"]["fallbacks"] = fallbacks[i];
    scenes.push_back(r["scenes"][i]);
  }
  addFallbackFigures(r, scenes);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "fallback.scenes.motor")->value, 2);
  EXPECT_EQ(figures::figureNamed(r, "fallback.scenes.motor")->n, 3);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "fallback.draws.motor")->value, 6);     // 2 + 1 + 3
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "fallback.joints.motor")->value, 50);
  EXPECT_DOUBLE_EQ(figures::figureNamed(r, "fallback.vertices.motor")->value, 1200);
  const std::string text = line(answerLines(r), "time").text;
  EXPECT_NE(text.find("motor drew with its exact fallback in 2 scenes of 3: 6 draws, 50 joints, 1200 vertices"),
            std::string::npos) << text;

  for (int i = 0; i < 3; ++i) r["scenes"][i]["pipelines"]["motor"]["fallbacks"] = fallbacks[2];
  scenes.assign(r["scenes"].begin(), r["scenes"].end());
  addFallbackFigures(r, scenes);
  EXPECT_NE(line(answerLines(r), "time").text.find("motor took no exact fallback (0 scenes)"), std::string::npos);
}

}  // namespace
}  // namespace mb::document
