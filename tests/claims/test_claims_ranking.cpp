// claims' ops_ranking rows print the report's ranking as it is: the verdict is
// report.json's line, the measured value its table of the three; a report without the ranking
// gives "not measurable", never a ranking of claims' own.
#include <gtest/gtest.h>

#include "harness/claims/claims_ranking.h"

namespace {

using json = nlohmann::json;

// One scope as harness/document/ops_ranking.h writes it: A and B, the ISA reversing them.
json scope(bool reversed) {
  return {{"scope", "rigid vertex to clip"},
          {"measures", {{{"key", "counted"}, {"name", "counted ops"}, {"definition", "d1"}, {"device", "v1"}},
                        {{"key", "isa"}, {"name", "AMD ISA instructions"}, {"definition", "d2"}, {"device", "v2"}}}},
          {"pipelines", {"A", "B"}},
          {"table", {{"A", {{"counted", 10}, {"isa", reversed ? 6 : 3}}}, {"B", {{"counted", 20}, {"isa", 4}}}}},
          {"pairs", 1},
          {"reversed", reversed ? json::array({{{"a", "A"}, {"b", "B"}}}) : json::array()},
          {"line", reversed ? "op ranking of the rigid vertex to clip: ... disagree on the order of 1 of 1 pipeline pairs"
                            : "op ranking of the rigid vertex to clip: ... order all 1 pipeline pairs alike"}};
}

TEST(ClaimsRanking, RowPrintsTheReportsLineAndTable) {
  const json s = scope(true);
  const mb::claims::Claim c = mb::claims::rankingClaim(s, "rigid", "report.json (its \"opsRanking\")");
  EXPECT_EQ(c.id, "ops_ranking_rigid");
  EXPECT_EQ(c.verdictText, s["line"]);
  EXPECT_EQ(c.measured, "A 10 / 6, B 20 / 4 (counted ops / AMD ISA instructions)");
  EXPECT_NE(c.method.find("report.json (its \"opsRanking\")"), std::string::npos) << c.method;
  EXPECT_NE(c.method.find("counted ops: d1 (v1)"), std::string::npos) << c.method;
  EXPECT_EQ(c.measuredValue["reversed"].size(), 1u);
  EXPECT_EQ(mb::claims::disagreementLine(s), s["line"]);
}

TEST(ClaimsRanking, AgreeingMeasuresAddNothingToTheSpeedRows) {
  EXPECT_EQ(mb::claims::disagreementLine(scope(false)), "");
  EXPECT_EQ(mb::claims::disagreementLine(json()), "");
}

TEST(ClaimsRanking, NoRankingIsNotMeasurable) {
  const mb::claims::Claim c = mb::claims::rankingClaim(json(), "skinned", "old/report.json");
  EXPECT_EQ(c.verdict, mb::claims::Verdict::NotMeasurable);
  EXPECT_NE(c.verdictText.find("no opsRanking.skinned in old/report.json"), std::string::npos) << c.verdictText;
}

}  // namespace
