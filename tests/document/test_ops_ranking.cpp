// opsRanking on hand-made measures: three pipelines A, B, C whose orders are
// worked out by hand for each measure, so the pairs named and the word "disagree" are known.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/document/ops_ranking.h"
#include "harness/document/report_format.h"
#include "harness/figures/figure.h"

namespace {

using json = nlohmann::json;

json ops(double mul, double add) { return {{"mul", mul}, {"add", add}, {"div", 0}, {"sqrt", 0}, {"other", 0}}; }

// Variant rows as opsv::toJson writes them: counted and probe totals per pipeline of "rigid".
json variants(const json& counted, const json& probes) {
  json out = json::array();
  for (const auto& [p, total] : counted.items())
    out.push_back({{"pipeline", p}, {"variant", "rigid"}, {"counted", ops(total.get<double>(), 0)},
                   {"spirv_kernel_probes", probes.contains(p) ? ops(0, probes[p].get<double>()) : json()}});
  return out;
}

// Two families; instructions per pipeline as {p: [f1, f2]} (the ranking uses their median).
json isa(const json& perFamily) {
  json shaders = json::array();
  for (const auto& [p, v] : perFamily.items())
    for (int f = 0; f < 2; ++f)
      shaders.push_back({{"stage", "vertex"}, {"pipeline", p}, {"familyId", f ? "f2" : "f1"},
                         {"labels", {"rigid"}}, {"instructions", v[f]}});
  return {{"driver", "Mesa test"},
          {"families", {{{"id", "f1"}, {"generation", "G1"}}, {{"id", "f2"}, {"generation", "G2"}}}},
          {"shaders", shaders}};
}

TEST(OpsRanking, NamesThePairTheIsaReverses) {
  // counted and probe: A 10 < B 20 < C 30; ISA medians A (5+7)/2 = 6, B 4, C 10: B < A < C.
  const json r = mb::document::opsRanking(variants({{"A", 10}, {"B", 20}, {"C", 30}}, {{"A", 10}, {"B", 20}, {"C", 30}}),
                                        isa({{"A", {5, 7}}, {"B", {4, 4}}, {"C", {9, 11}}}))["rigid"];
  EXPECT_EQ(r["table"]["A"]["isa"], 6.0);
  EXPECT_EQ(r["ranks"]["isa"]["B"], 1);
  EXPECT_EQ(r["ranks"]["counted"]["B"], 2);
  EXPECT_EQ(r["pairs"], 3);
  ASSERT_EQ(r["reversed"].size(), 1u);
  EXPECT_EQ(r["reversed"][0]["a"], "A");
  EXPECT_EQ(r["reversed"][0]["b"], "B");
  EXPECT_EQ(r["line"],
            "op ranking of the rigid vertex to clip: counted ops, SPIR-V probe ops and AMD ISA instructions (median over 2 families) "
            "disagree on the order of 1 of 3 pipeline pairs: A vs B: A cheaper by counted and SPIR-V probe, B "
            "cheaper by ISA");
  EXPECT_EQ(mb::document::opsRankingTableText(r),
            "A 10 / 10 / 6, B 20 / 20 / 4, C 30 / 30 / 10 (counted ops / SPIR-V probe ops / AMD ISA instructions "
            "(median over 2 families))");
}

TEST(OpsRanking, AgreeingMeasuresSayAlikeAndATieOrdersNothing) {
  // ISA ties A and B (8, 8): a tie is no reversal; every other pair is ordered alike.
  const json r = mb::document::opsRanking(variants({{"A", 10}, {"B", 20}, {"C", 30}}, {{"A", 11}, {"B", 21}, {"C", 31}}),
                                        isa({{"A", {8, 8}}, {"B", {8, 8}}, {"C", {9, 9}}}))["rigid"];
  EXPECT_TRUE(r["reversed"].empty());
  EXPECT_EQ(r["ranks"]["isa"]["A"], 1);
  EXPECT_EQ(r["ranks"]["isa"]["B"], 1);
  EXPECT_EQ(r["line"].get<std::string>().find("disagree"), std::string::npos);
  EXPECT_NE(r["line"].get<std::string>().find("order all 3 pipeline pairs alike"), std::string::npos) << r["line"];
}

TEST(OpsRanking, OneMeasureRanksNothing) {
  // No probes, no ISA: nothing to compare the counted order with.
  const json r = mb::document::opsRanking(variants({{"A", 10}, {"B", 20}}, json::object()), json())["rigid"];
  EXPECT_EQ(r["pairs"], 0);
  EXPECT_EQ(r["line"].get<std::string>().find("disagree"), std::string::npos);
  EXPECT_NE(r["line"].get<std::string>().find("not ranked: only counted ops measured (no ISA statistics"), std::string::npos)
      << r["line"];
  EXPECT_TRUE(r["table"]["A"]["isa"].is_null());
  // Garbage in place of the inputs: an empty ranking, no throw.
  EXPECT_NO_THROW(mb::document::opsRanking(json("text"), json(3)));
}

TEST(OpsRanking, ReportGetsTheRankingAndItsFigureAndPrintsTheLine) {
  json report = {{"opsPerVertex", {{"detail", {{"variants", variants({{"A", 10}, {"B", 20}, {"C", 30}},
                                                                     {{"A", 10}, {"B", 20}, {"C", 30}})}}}}},
                 {"isa", isa({{"A", {5, 7}}, {"B", {4, 4}}, {"C", {9, 11}}})}};
  mb::document::addOpsRanking(report);
  const auto f = mb::figures::figureNamed(report, "ops_ranking.rigid.pairs_reversed");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->value, 1);
  EXPECT_EQ(f->n, 3);
  // No skinned variant: nothing measured, the figure says why.
  const auto s = mb::figures::figureNamed(report, "ops_ranking.skinned.pairs_reversed");
  ASSERT_TRUE(s);
  EXPECT_TRUE(std::isnan(s->value));
  mb::document::Document d;
  mb::document::opsRankingSection(d, report);
  const std::string md = mb::document::toMarkdown(d);
  EXPECT_NE(md.find(report["opsRanking"]["rigid"]["line"].get<std::string>()), std::string::npos) << md;
  EXPECT_NE(md.find("| B | 20 (2) | 20 (2) | 4 (1) |"), std::string::npos) << md;
}

}  // namespace
