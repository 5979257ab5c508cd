// The answer block (issue 36, harness/document/report_answer.h): its lines quote report.json's
// figures by name, and each verdict follows from those figures as the line's rule says.
#include <gtest/gtest.h>

#include "harness/document/report_answer.h"
#include "harness/document/report_answer_figures.h"
#include "harness/figures/figure.h"

namespace mb::report {
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
  EXPECT_NE(line(lines, "AMD ISA").text.find("tahiti 125/115, gfx1100 150/153"), std::string::npos);
  EXPECT_NE(line(lines, "image").text.find("1 of 3 frames identical"), std::string::npos);
}

TEST(ReportAnswer, VerdictsFollowTheFigures) {
  const std::vector<AnswerLine> cpu = answerLines(syntheticReport(false));
  EXPECT_EQ(line(cpu, "bytes").verdict, "motor side cheaper: it fetches fewer bytes");
  EXPECT_EQ(line(cpu, "ops").verdict, "matrix side cheaper: it runs fewer arithmetic ops");  // 113 < 132
  EXPECT_EQ(line(cpu, "AMD ISA").verdict, "motor fewer on 1, more on 1 of 2 families");
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

}  // namespace
}  // namespace mb::report
