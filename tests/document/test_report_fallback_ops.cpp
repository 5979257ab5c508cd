// Ops per vertex of a scene (harness/report/report_ops.h sceneOpsPerVertex): the vertices a
// pipeline's exact fallback drew are priced at its fallback variants, the rest at the regular
// ones. Hand-made variant rows with round counts, so every mean below is worked by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "harness/report/report_ops.h"

namespace {

using nlohmann::json;

json row(const std::string& label, double mul) {
  const json c = {{"mul", mul}, {"add", 0}, {"div", 0}, {"sqrt", 0}, {"other", 0}};
  return {{"pipeline", "motor"}, {"label", label}, {"counted", c}, {"spirv", c}};
}

json motorOps() {
  return {{"variants", json::array({row("rigid", 10), row("skinned", 20), row("linear fallback", 100),
                                    row("skinned, linear fallback", 200)})}};
}

TEST(FallbackOps, FallbackVerticesArePricedAtTheirOwnVariants) {
  const json mix = {{"rigid", 10}, {"skinned", 30}, {"scaledFallback", 0}, {"bezierPatch", 0}, {"curvedInstance", 0}};
  // 4 rigid vertices on the linear fallback, 10 skinned on the skin fallback (of 14 in all).
  const json pipelines = {{"motor", {{"fallbacks", {{"fallbackVertices", 14}, {"skinFallbackVertices", 10}}}}}};
  const json out = mb::report::sceneOpsPerVertex(motorOps(), mix, pipelines);
  ASSERT_TRUE(out.contains("motor")) << out.dump();
  // (6 x 10 + 4 x 100 + 20 x 20 + 10 x 200) / 40 = 2860 / 40
  EXPECT_DOUBLE_EQ(out["motor"]["counted"]["mul"].get<double>(), 71.5);
  EXPECT_DOUBLE_EQ(out["motor"]["spirv"]["mul"].get<double>(), 71.5);
  EXPECT_EQ(out["motor"]["fallbackVertices"]["rigid"], 4.0);
  EXPECT_EQ(out["motor"]["fallbackVertices"]["skinned"], 10.0);
}

TEST(FallbackOps, WithoutFallbacksTheRegularVariantsPriceEveryVertex) {
  const json mix = {{"rigid", 10}, {"skinned", 30}, {"scaledFallback", 0}, {"bezierPatch", 0}, {"curvedInstance", 0}};
  const json none = {{"motor", {{"fallbacks", {{"fallbackVertices", 0}, {"skinFallbackVertices", 0}}}}}};
  // (10 x 10 + 30 x 20) / 40
  EXPECT_DOUBLE_EQ(mb::report::sceneOpsPerVertex(motorOps(), mix, none)["motor"]["counted"]["mul"].get<double>(), 17.5);
  EXPECT_DOUBLE_EQ(mb::report::sceneOpsPerVertex(motorOps(), mix)["motor"]["counted"]["mul"].get<double>(), 17.5);
}

}  // namespace
