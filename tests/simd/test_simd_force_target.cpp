// `motorbench bench --simd-target NAME` (harness/bench/cpu_machine.h forceSimdTarget): every
// target this CPU supports can be forced by its name and is then the one the kernels dispatch
// to (and the bench labels); an unknown name is refused with the list.
#include <gtest/gtest.h>

#include "harness/bench/cpu_machine.h"
#include "kernels/simd/simd_targets.h"

namespace {

TEST(SimdForceTarget, EachSupportedTargetByNameAndUnknownNamesRefused) {
  const std::vector<mb::simd::Target> all = mb::simd::supportedTargets();
  ASSERT_FALSE(all.empty());
  for (const mb::simd::Target& t : all) {
    EXPECT_EQ(mb::bench::forceSimdTarget(t.name), "") << t.name;
    EXPECT_EQ(mb::simd::currentTarget().name, t.name);
    EXPECT_EQ(mb::bench::cpuMachine().simdTarget, t.name);
    mb::simd::forceTarget(0);  // the CPU's full set again
  }
  const std::string error = mb::bench::forceSimdTarget("NOSUCH");
  EXPECT_NE(error.find("'NOSUCH' is not a target this CPU supports"), std::string::npos) << error;
  EXPECT_NE(error.find(all.front().name), std::string::npos) << error;
  EXPECT_EQ(mb::simd::currentTarget().name, all.front().name);  // nothing forced
}

}  // namespace
