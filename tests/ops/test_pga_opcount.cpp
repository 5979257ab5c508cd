// Op counts of shaders/pga.glsl, measured by executing it on mb::Counted (the rows of
// `motorbench ops`): the values the issue requires, every "measured:" comment in pga.glsl
// equals the count, and the table/JSON report them with the claims.
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "harness/ops/op_kernels.h"

namespace {

std::map<std::string, mb::ops::Row> measuredRows() {
  std::map<std::string, mb::ops::Row> m;
  for (const auto& r : mb::ops::measureAll(mb::ops::allKernels())) m.emplace(r.kernel.name, r);
  return m;
}

}  // namespace

TEST(PgaOpCount, PaperValuesMeasuredByExecution) {
  const auto rows = measuredRows();
  const std::pair<const char*, std::pair<int, int>> want[] = {
      {"gp_mm", {48, 40}}, {"gp_rr", {16, 12}}, {"sw_mp", {21, 18}},
      {"sw_md", {18, 12}}, {"sw_mx", {6, 4}},   {"extractNormalTangent", {9, 8}},
      {"mat4*mat4", {64, 48}}, {"mat4*vec4", {16, 12}}};
  for (const auto& [name, mulAdd] : want) {
    ASSERT_TRUE(rows.count(name)) << name;
    const mb::OpCounts& c = rows.at(name).counts;
    EXPECT_EQ(c.mul, uint64_t(mulAdd.first)) << name;
    EXPECT_EQ(c.add, uint64_t(mulAdd.second)) << name;
    EXPECT_EQ(c.div + c.sqrt + c.other, 0u) << name;
    EXPECT_EQ(rows.at(name).agree(), "yes") << name;
  }
  // Known disagreements are reported, not hidden.
  EXPECT_EQ(rows.at("normalize_m").agree(), "NO");
  EXPECT_EQ(rows.at("gp_vv").agree(), "-");
}

// Every function of pga.glsl has a "measured:" comment above it (or shares the one of the
// group it belongs to) that equals what the counter measures.
TEST(PgaOpCount, CommentsInPgaGlslStateTheMeasuredCounts) {
  std::ifstream in(std::string(MB_SOURCE_DIR) + "/shaders/pga.glsl");
  ASSERT_TRUE(in) << "cannot read shaders/pga.glsl";
  const auto rows = measuredRows();
  const std::regex fn(R"(^(motor|line|point|direction|vec4|mat2x3)\s+(\w+)\s*\()");
  const std::regex measured(R"(measured:\s*([^(]*))");
  const std::regex item(R"((\d+)\s+(\w+))");
  std::string line, lastMeasured;
  int functions = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, measured)) lastMeasured = m[1];
    if (!std::regex_search(line, m, fn)) continue;
    const std::string name = m[2];
    ++functions;
    ASSERT_TRUE(rows.count(name)) << name << " has no row in harness/ops/op_kernels.h";
    ASSERT_FALSE(lastMeasured.empty()) << name;
    mb::OpCounts stated;
    for (std::sregex_iterator it(lastMeasured.begin(), lastMeasured.end(), item), end; it != end; ++it) {
      const uint64_t n = std::stoull((*it)[1]);
      const std::string what = (*it)[2];
      if (what == "mul") stated.mul = n;
      else if (what == "add") stated.add = n;
      else if (what == "div") stated.div = n;
      else if (what == "sqrt") stated.sqrt = n;
      else stated.other += n;  // inversesqrt, sin, cos, acos...
    }
    const mb::OpCounts& c = rows.at(name).counts;
    EXPECT_EQ(c.mul, stated.mul) << name;
    EXPECT_EQ(c.add, stated.add) << name;
    EXPECT_EQ(c.div, stated.div) << name;
    EXPECT_EQ(c.sqrt, stated.sqrt) << name;
    EXPECT_EQ(c.other, stated.other) << name;
  }
  EXPECT_EQ(functions, int(mb::ops::pgaKernels().size()));
}

TEST(PgaOpCount, TableAndJsonCarryClaimsAndAgreement) {
  const auto rows = mb::ops::measureAll(mb::ops::allKernels());
  const std::string table = mb::ops::formatTable(rows);
  EXPECT_NE(table.find("gp_mm"), std::string::npos);
  EXPECT_NE(table.find("48/40"), std::string::npos);
  EXPECT_NE(table.find("mat3*vec3"), std::string::npos);
  const nlohmann::json j = mb::ops::toJson(rows);
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), rows.size());
  EXPECT_EQ(j[0]["kernel"], "gp_mm");
  EXPECT_EQ(j[0]["measured"]["mul"], 48);
  EXPECT_EQ(j[0]["claim"]["add"], 40);
  EXPECT_EQ(j[0]["agree"], true);
  // An extra column (e.g. a SPIR-V count) shows in both.
  auto withExtra = rows;
  withExtra[0].extra.push_back({"spirv", "47/40"});
  EXPECT_NE(mb::ops::formatTable(withExtra).find("47/40"), std::string::npos);
  EXPECT_EQ(mb::ops::toJson(withExtra)[0]["extra"]["spirv"], "47/40");
}
