// The answer by kind of content (report_kind_figures.h, report_answer_kinds.h): per-kind figures
// from scenes' contentKinds and vertexFetch.byKind, weighted by drawn vertices and by the
// variant each primitive draws with; the lines quote them with each kind's share, and the
// headline names the kinds where motor is cheaper and where it is not. Hand-chosen numbers.
#include <gtest/gtest.h>

#include "harness/document/report_answer.h"
#include "harness/document/report_answer_figures.h"
#include "harness/document/report_format.h"
#include "harness/figures/figure.h"
#include "harness/report/content_kinds.h"
#include "pipelines/scene/loader.h"

namespace mb::document {
namespace {

using json = nlohmann::json;

json fetch(double fetched, double vertices, const char* material, const char* deformation) {
  const json k = {{"bytesFetchedPerFrame", fetched}, {"uniqueVertexBytesPerFrame", fetched},
                  {"verticesReferencedPerFrame", vertices}};
  return {{"bytesFetchedPerFrame", fetched}, {"uniqueVertexBytesPerFrame", fetched},
          {"verticesReferencedPerFrame", vertices}, {"byKind", {{material, k}, {deformation, k}}}};
}

json frameWith(double psnr) {
  const json m = psnr < 0 ? json{{"identical", true}, {"psnr", nullptr}} : json{{"identical", false}, {"psnr", psnr}};
  return json::array({{{"metrics", {{"motor", m}}}}});
}

// File a: 200 normal-mapped rigid vertices, 1 primitive, matrix 48 B, motor 36 B, timed 0.9.
// File b: 300 skinned vertices without a normal map, 3 primitives, matrix 32 B, motor 36 B,
// timed 1.2, motor's skin fallback on 30 of them. Built-in c: 50 normal-mapped rigid, 48/36 B.
json kindsReport() {
  json r = {{"settings", {{"pipelines", {"matrix", "motor"}}, {"baseline", "matrix"}}},
            {"machine", {{"gl", {{"renderer", "NVIDIA H200"}, {"realGpu", true}}}}},
            {"figures", json::object()}};
  r["scenes"] = json::array();
  r["scenes"].push_back(
      {{"id", "a"}, {"origin", "file"}, {"space", "Euclidean"},
       {"contentKinds", {{"cells", {{{"normalMapped", true}, {"deformation", "rigid"}, {"instanced", false},
                                     {"vertices", 200}, {"primitives", 1}}}}}},
       {"vertexMix", {{"rigid", 200}, {"skinned", 0}, {"scaledFallback", 0}}},
       {"timing", {{"paired_ratio_motor_matrix", 0.9}}},
       {"pipelines", {{"matrix", {{"vertexFetch", fetch(9600, 200, "normalMapped", "rigid")}}},
                      {"motor", {{"vertexFetch", fetch(7200, 200, "normalMapped", "rigid")}}}}},
       {"frames", frameWith(60)}});
  r["scenes"].push_back(
      {{"id", "b"}, {"origin", "file"}, {"space", "Euclidean"},
       {"contentKinds", {{"cells", {{{"normalMapped", false}, {"deformation", "skinned"}, {"instanced", false},
                                     {"vertices", 300}, {"primitives", 3}}}}}},
       {"vertexMix", {{"rigid", 0}, {"skinned", 300}, {"scaledFallback", 0}}},
       {"opsPerVertex", {{"motor", {{"fallbackVertices", {{"rigid", 0}, {"skinned", 30}}}}}}},
       {"timing", {{"paired_ratio_motor_matrix", 1.2}}},
       {"pipelines", {{"matrix", {{"vertexFetch", fetch(9600, 300, "notNormalMapped", "skinned")}}},
                      {"motor", {{"vertexFetch", fetch(10800, 300, "notNormalMapped", "skinned")}}}}},
       {"frames", frameWith(-1)}});
  r["scenes"].push_back(
      {{"id", "c"}, {"origin", "built-in"}, {"space", "Euclidean"},
       {"contentKinds", {{"cells", {{{"normalMapped", true}, {"deformation", "rigid"}, {"instanced", false},
                                     {"vertices", 50}, {"primitives", 1}}}}}},
       {"vertexMix", {{"rigid", 50}, {"skinned", 0}, {"scaledFallback", 0}}},
       {"pipelines", {{"matrix", {{"vertexFetch", fetch(2400, 50, "normalMapped", "rigid")}}},
                      {"motor", {{"vertexFetch", fetch(1800, 50, "normalMapped", "rigid")}}}}},
       {"frames", frameWith(70)}});
  auto variant = [](const char* p, const char* label, double mul) {
    return json{{"pipeline", p}, {"label", label}, {"counted", {{"mul", mul}, {"add", 0}}}, {"spirv", {{"mul", mul + 1}}}};
  };
  r["opsPerVertex"] = {{"variants", {variant("matrix", "rigid", 100), variant("matrix", "rigid, no tangent", 90),
                                     variant("matrix", "skinned", 200), variant("matrix", "skinned, no tangent", 180),
                                     variant("motor", "rigid", 110), variant("motor", "skinned", 120),
                                     variant("motor", "skinned, linear fallback", 220)}}};
  auto row = [](const char* p, const char* label, int n) {
    return json{{"stage", "vertex"}, {"pipeline", p}, {"familyId", "tahiti"}, {"labels", {label}}, {"instructions", n}};
  };
  r["isa"] = {{"families", {{{"id", "tahiti"}}}},
              {"shaders", {row("matrix", "rigid", 115), row("motor", "rigid", 125), row("matrix", "skinned", 200),
                           row("motor", "skinned", 150)}}};
  addAnswerFigures(r);
  return r;
}

double value(const json& r, const std::string& name) {
  const auto f = figures::figureNamed(r, name);
  EXPECT_TRUE(f) << name;
  return f ? f->value : -1;
}

TEST(ReportKinds, SharesAndBytesPerKindFromTheScenes) {
  const json r = kindsReport();
  EXPECT_DOUBLE_EQ(value(r, "kind.vertices.all"), 500);  // the files only: the built-in scene apart
  EXPECT_DOUBLE_EQ(value(r, "kind.vertices.built_in"), 50);
  EXPECT_DOUBLE_EQ(value(r, "kind.share_vertices.normal_mapped"), 40);
  EXPECT_DOUBLE_EQ(value(r, "kind.share_vertices.skinned"), 60);
  EXPECT_DOUBLE_EQ(value(r, "kind.share_primitives.not_normal_mapped"), 75);  // 3 of 4
  EXPECT_FALSE(figures::figureNamed(r, "kind.share_vertices.morph") &&
               figures::figureNamed(r, "kind.share_vertices.morph")->value > 0);
  EXPECT_DOUBLE_EQ(value(r, "kind.fetched_over_baseline.all.motor"), 18000.0 / 19200);
  EXPECT_DOUBLE_EQ(value(r, "kind.fetched_over_baseline.normal_mapped.motor"), 0.75);
  EXPECT_DOUBLE_EQ(value(r, "kind.fetched_over_baseline.not_normal_mapped.motor"), 1.125);
  EXPECT_DOUBLE_EQ(value(r, "kind.fetched_over_baseline.built_in.motor"), 0.75);
  EXPECT_DOUBLE_EQ(value(r, "kind.fetched_bytes_per_vertex.all.matrix"), 38.4);  // 19200 / 500
  EXPECT_DOUBLE_EQ(value(r, "kind.uploaded_bytes_per_vertex.skinned.motor"), 36);
}

TEST(ReportKinds, OpsAndIsaByTheVariantEachVertexDraws) {
  const json r = kindsReport();
  // matrix: 200 x rigid 100 + 300 x "skinned, no tangent" 180; motor: 200 x 110 + 300 x (0.9 x 120 + 0.1 x 220).
  EXPECT_DOUBLE_EQ(value(r, "kind.ops_counted.all.matrix"), 148);
  EXPECT_DOUBLE_EQ(value(r, "kind.ops_counted.all.motor"), 122);
  EXPECT_DOUBLE_EQ(value(r, "kind.ops_counted.skinned.motor"), 130);
  EXPECT_DOUBLE_EQ(value(r, "kind.ops_counted.normal_mapped.matrix"), 100);
  EXPECT_DOUBLE_EQ(value(r, "kind.ops_spirv.not_normal_mapped.matrix"), 181);
  // ISA: no no-tangent or fallback shader compiled, so the base variants: (200 x 115 + 300 x 200) / 500.
  EXPECT_DOUBLE_EQ(value(r, "kind.isa_instructions.all.tahiti.matrix"), 166);
  EXPECT_DOUBLE_EQ(value(r, "kind.isa_instructions.all.tahiti.motor"), 140);
  EXPECT_DOUBLE_EQ(value(r, "kind.frame_time.all"), 1.05);  // median of 0.9 and 1.2
  EXPECT_DOUBLE_EQ(value(r, "kind.frame_time.skinned"), 1.2);
  EXPECT_FALSE(figures::figureNamed(r, "kind.frame_time.built_in").has_value() &&
               std::isfinite(figures::figureNamed(r, "kind.frame_time.built_in")->value));
  EXPECT_DOUBLE_EQ(value(r, "kind.image_worst_psnr.normal_mapped.motor"), 60);
  EXPECT_DOUBLE_EQ(value(r, "kind.image_identical_frames.skinned.motor"), 1);
}

const AnswerLine& lineOf(const std::vector<AnswerLine>& lines, const std::string& evidence) {
  for (const AnswerLine& l : lines)
    if (l.evidence.rfind(evidence, 0) == 0) return l;
  static AnswerLine none;
  ADD_FAILURE() << evidence;
  return none;
}

// "<kind [shares]>: <figures>" of line `l`, as the kinds table prints it (marks dropped).
std::string kindRow(const AnswerLine& l, const std::string& kind) {
  for (const KindAnswer& k : l.kinds)
    if (k.kind == kind) return withoutFigureMarks(k.head) + ": " + k.text;
  return "";
}

TEST(ReportKinds, LinesQuoteEachKindWithItsShareAndTheHeadlineNamesTheSides) {
  const json r = kindsReport();
  const std::vector<AnswerLine> lines = answerLines(r);
  const AnswerLine& bytes = lineOf(lines, "bytes");
  EXPECT_EQ(kindRow(bytes, "normal_mapped").rfind("normal-mapped [40 % of vertices, 25 % of primitives]: fetched per "
                                                  "vertex matrix 48 bytes, motor 36 bytes, per frame motor / matrix 0.75x",
                                                  0),
            0u)
      << kindRow(bytes, "normal_mapped");
  EXPECT_EQ(kindRow(bytes, "built_in").rfind("built-in scenes (controlled cases) [50 vertices, 1 primitives]", 0), 0u);
  EXPECT_EQ(kindRow(bytes, "morph"), "");  // a kind the content does not draw
  EXPECT_EQ(bytes.kinds.size(), 6u);      // all, normal-mapped, not, skinned, rigid, built-in
  for (const AnswerLine& l : lines)
    for (const std::string& name : l.figures)  // the kinds' figures; the lines' own are ReportAnswer's
      if (name.rfind("kind.", 0) == 0) {
        EXPECT_TRUE(r["figures"].contains(name)) << l.evidence << ": " << name;
      }
  EXPECT_NE(std::find(bytes.figures.begin(), bytes.figures.end(), "kind.fetched_over_baseline.skinned.motor"),
            bytes.figures.end());
  EXPECT_EQ(bytes.verdict.rfind("motor side cheaper: fewer bytes fetched, weighted by drawn vertices (by kind: above", 0), 0u)
      << bytes.verdict;
  EXPECT_NE(bytes.verdict.find("built-in scenes: motor side cheaper"), std::string::npos) << bytes.verdict;
  const AnswerLine& ops = lineOf(lines, "ops");
  EXPECT_EQ(kindRow(ops, "skinned").rfind("skinned [60 % of vertices, 75 % of primitives]: counted matrix 180 ops, "
                                          "motor 130 ops", 0),
            0u)
      << kindRow(ops, "skinned");
  // 122 / 148 on the files; on the built-in scene 110 / 100; the rigid vertex alone as before.
  EXPECT_EQ(ops.verdict, "motor side cheaper: fewer arithmetic ops, weighted by drawn vertices (by kind: above; "
                         "built-in scenes: matrix side cheaper; rigid vertex alone: not counted)");
  EXPECT_EQ(kindRow(lineOf(lines, "time"), "skinned"),
            "skinned [60 % of vertices, 75 % of primitives]: frame motor / matrix 1.2x over 1 scene(s)");
  EXPECT_EQ(kindRow(lineOf(lines, "time"), "built_in"), "built-in scenes (controlled cases) [50 vertices, 1 primitives]: not measured");
  EXPECT_EQ(kindRow(lineOf(lines, "image"), "normal_mapped"),
            "normal-mapped [40 % of vertices, 25 % of primitives]: worst PSNR 60 dB, 0 of 1 frames identical");
  const json answer = answerJson(r);
  EXPECT_EQ(answer["headline"],
            "The content decides the verdict (drawn vertices: normal-mapped 40 %, not normal-mapped 60 %, skinned 60 %, "
            "rigid 40 %): motor fetches fewer bytes on normal-mapped, rigid, more on not normal-mapped, skinned (built-in "
            "scenes: fewer); runs fewer arithmetic ops on not normal-mapped, skinned, more on normal-mapped, rigid "
            "(built-in scenes: more); compiles to fewer ISA instructions on not normal-mapped, skinned, more on "
            "normal-mapped, rigid (built-in scenes: more).");
  const json& kinds = answer["lines"][0]["kinds"];
  ASSERT_TRUE(kinds.is_array());
  EXPECT_EQ(kinds[1]["kind"], "normal_mapped");
  EXPECT_DOUBLE_EQ(kinds[1]["shareVertices"].get<double>(), 40);
  EXPECT_DOUBLE_EQ(kinds[1]["ratio"].get<double>(), 0.75);
}

TEST(ReportKinds, TheAnswerSectionHasTheHeadlineAndARowPerKind) {
  const json r = kindsReport();
  Document d;
  answerSection(d, r);
  const Block* table = nullptr;
  bool headline = false;
  for (const Block& b : d.blocks) {
    if (b.anchor == "answer-kinds") table = &b;
    headline |= b.anchor == "answer-headline";
  }
  EXPECT_TRUE(headline);
  ASSERT_TRUE(table);
  ASSERT_EQ(table->rows.size(), 6u);  // all, normal-mapped, not, skinned, rigid, built-in
  EXPECT_EQ(table->header.size(), 6u);  // the kind, then the five lines
  EXPECT_EQ(withoutFigureMarks(table->rows[1][0].text), "normal-mapped [40 % of vertices, 25 % of primitives]");
  EXPECT_NE(table->rows[1][1].text.find("kind.fetched_over_baseline.normal_mapped.motor"), std::string::npos);
}

TEST(ReportKinds, AnOldReportSaysTheKindsAreNotRecorded) {
  json r = kindsReport();
  for (json& s : r["scenes"]) s.erase("contentKinds");
  r["figures"] = json::object();
  addAnswerFigures(r);
  for (const AnswerLine& l : answerLines(r)) {
    EXPECT_NE(l.text.find("by kind of content: not recorded in this report.json"), std::string::npos) << l.text;
    EXPECT_TRUE(l.kinds.empty());
  }
  EXPECT_EQ(answerJson(r)["headline"], "");
}

TEST(ReportKinds, SceneMeasurementCountsTheKindsOfABuiltInScene) {
  auto tube = loadScene("skinned_tube");
  ASSERT_TRUE(tube) << tube.error();
  const json cells = report::contentKindsJson(*tube)["cells"];
  ASSERT_FALSE(cells.empty());
  long long vertices = 0;
  for (const json& c : cells) {
    EXPECT_EQ(c["deformation"], "skinned");
    vertices += c["vertices"].get<long long>();
  }
  long long positions = 0;
  for (const Mesh& m : tube->meshes)
    for (const Primitive& p : m.primitives) positions += (long long)p.positions.size();
  EXPECT_EQ(vertices, positions);  // one node per mesh, no instances
}

}  // namespace
}  // namespace mb::document
