// Numbers in the report's documents: counts print whole (a fallback count of 3240 vertices read
// "3.24e+03" in report.md), measurements keep their significant digits.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "harness/document/report_format.h"
#include "harness/document/report_layout_common.h"

namespace {

using mb::document::fmt;

TEST(ReportFormat, CountsPrintWholeAndMeasurementsKeepTheirDigits) {
  EXPECT_EQ(fmt(3240.0), "3240");
  EXPECT_EQ(fmt(nlohmann::json(3240)), "3240");  // report.json read back: an integer
  EXPECT_EQ(fmt(100.0, 2), "100");
  EXPECT_EQ(fmt(123456789.0), "123456789");
  EXPECT_EQ(fmt(0.0), "0");
  EXPECT_EQ(fmt(-42.0), "-42");
  EXPECT_EQ(fmt(3.14159), "3.14");
  EXPECT_EQ(fmt(3241.5), "3.24e+03");  // not a count: its 3 digits
  EXPECT_EQ(fmt(0.000123), "0.000123");
  EXPECT_EQ(fmt(nlohmann::json("x")), "-");
  const nlohmann::json pipeline = {{"fallbacks", {{"fallbackVertices", 3240}, {"linearFallbackDraws", 12}, {"zero", 0}}}};
  EXPECT_EQ(mb::document::layout::fallbacksText(pipeline), "fallbackVertices 3240, linearFallbackDraws 12");
}

}  // namespace
