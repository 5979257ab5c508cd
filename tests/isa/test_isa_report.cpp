// The report's ISA section (harness/document/report_isa.h): a variant of report.json's
// opsPerVertex finds its ISA row through the row's labels (one program can stand for two
// labels of the ops table), and a report without `isa` says how to get one.
#include <gtest/gtest.h>

#include "harness/document/report_isa.h"

namespace {

using nlohmann::json;
using mb::document::Block;

const Block* table(const mb::document::Document& d) {
  for (const Block& b : d.blocks)
    if (b.kind == Block::Kind::Table) return &b;
  return nullptr;
}

TEST(IsaReport, VariantRowsJoinTheirIsaRowsByLabel) {
  const json report = {
      {"opsPerVertex",
       {{"variants",
         {{{"pipeline", "matrix"}, {"label", "skinned, reference"}, {"counted", {{"mul", 241}, {"add", 180}}},
           {"spirv", {{"mul", 253}, {"add", 184}}}}}}}},
      {"isa",
       {{"driver", "Mesa 22.3.6"},
        {"families", {{{"id", "navi21-ngg"}, {"generation", "RDNA 2"}}, {{"id", "tahiti"}, {"generation", "GCN 1"}}}},
        {"shaders",
         {{{"pipeline", "matrix"}, {"stage", "vertex"}, {"familyId", "navi21-ngg"},
           {"labels", {"skinned", "skinned, reference"}}, {"instructions", 699}, {"vgprs", 128}, {"wavesPerSimd", 4}},
          {{"pipeline", "matrix"}, {"stage", "fragment"}, {"familyId", "tahiti"},
           {"labels", {"skinned", "skinned, reference"}}, {"instructions", 495}, {"vgprs", 36}, {"wavesPerSimd", 7}}}}}}};
  mb::document::Document d;
  mb::document::isaSection(d, report);
  const Block* t = table(d);
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->header.size(), 5u);
  EXPECT_EQ(t->header[3], "navi21-ngg (RDNA 2)");
  ASSERT_EQ(t->rows.size(), 1u);
  EXPECT_EQ(t->rows[0][0].text, "skinned, reference");
  EXPECT_EQ(t->rows[0][3].text, "699 / 128 / 4w");
  EXPECT_EQ(t->rows[0][4].text, "-");  // tahiti has only the fragment shader here
}

TEST(IsaReport, WithoutIsaJsonTheSectionSaysHowToGetIt) {
  mb::document::Document d;
  mb::document::isaSection(d, json{{"opsPerVertex", json::object()}});
  EXPECT_EQ(table(d), nullptr);
  bool told = false;
  for (const Block& b : d.blocks) told = told || b.text.find("--isa-json") != std::string::npos;
  EXPECT_TRUE(told);
}

}  // namespace
