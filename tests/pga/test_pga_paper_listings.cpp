// The paper's printed listings (shaders/paper_listings.glsl) counted through the
// shim beside its table and our implementations (pga.glsl). Expected values are counted by
// hand from the printed code (see the comments there); the listings must also compute what
// ours compute where both follow the same math (normalize_m, sqrt_m, the skinning blend).
#include <gtest/gtest.h>

#include <cmath>

#include "shaders/shim/counted.h"
#include "shaders/shim/paper_listings.h"

using mb::Counted;
using mb::OpCounts;

namespace {

using PC = mb::PaperListings<Counted>;
using PF = mb::PaperListings<double>;

void expectCounts(const OpCounts& c, uint64_t mul, uint64_t add, uint64_t div, uint64_t sqrt,
                  uint64_t other, const char* what) {
  EXPECT_EQ(c.mul, mul) << what;
  EXPECT_EQ(c.add, add) << what;
  EXPECT_EQ(c.div, div) << what;
  EXPECT_EQ(c.sqrt, sqrt) << what;
  EXPECT_EQ(c.other, other) << what;
}

template <class P>
typename P::motor someMotor(double k = 1.0) {
  // Not normalised on purpose (normalize_m's input), with rotor and translation parts.
  return typename P::motor(0.9 * k, 0.2, -0.3, 0.1, 0.4, -0.2, 0.3, 0.05);
}

}  // namespace

TEST(PaperListings, NormalizeAndSqrtAsPrinted) {
  PC p;
  const PC::motor m = someMotor<PC>();
  expectCounts(mb::countOps([&] { p.paper_normalize_m(m); }), 24, 10, 1, 1, 0,
               "printed normalize_m (table 21/5)");
  expectCounts(mb::countOps([&] { p.paper_sqrt_m(m); }), 24, 11, 1, 1, 0,
               "printed sqrt_m (table 21/6)");
  // Ours: inversesqrt instead of 1 / sqrt, and the dual correction folded into one product.
  const OpCounts ours = mb::countOps([&] { p.normalize_m(m); });
  expectCounts(ours, 22, 10, 0, 0, 1, "pga.glsl normalize_m");
  // sqrt_m = normalize_m + 1 add, in the listing as in ours (the table's own relation).
  const OpCounts oursSqrt = mb::countOps([&] { p.sqrt_m(m); });
  EXPECT_EQ(oursSqrt.add, ours.add + 1);
  EXPECT_EQ(oursSqrt.mul, ours.mul);
}

TEST(PaperListings, LogAndExpAsPrinted) {
  PC p;
  const PC::motor m = p.normalize_m(someMotor<PC>());
  expectCounts(mb::countOps([&] { p.paper_log_m(m); }), 14, 5, 1, 1, 1, "printed log_m");
  expectCounts(mb::countOps([&] { p.log_m(m); }), 14, 6, 1, 1, 1, "ours: (1 - s)(1 + s)");
  const PC::line b(Counted(0.3), Counted(-0.2), Counted(0.5), Counted(0.1), Counted(0.4),
                   Counted(-0.6));
  expectCounts(mb::countOps([&] { p.paper_exp_b(b); }), 17, 8, 2, 1, 2, "printed exp_b");
}

TEST(PaperListings, SkinBlendAsPrinted) {
  PC p;
  const PC::motor j = p.normalize_m(someMotor<PC>());
  expectCounts(mb::countOps([&] { p.paper_skin_blend(j, j, j, j, j, PC::vec4(0.4, 0.3, 0.2, 0.1)); }),
               4 * 8 + 3 * 4 + 24 + 48, 3 * 3 + 3 * 8 + 10 + 40, 1, 1, 0, "printed skinning");
}

TEST(PaperListings, ComputeWhatOursCompute) {
  PF p;
  const PF::motor m = someMotor<PF>();
  const PF::motor a = p.paper_normalize_m(m), b = p.normalize_m(m);
  const PF::motor sa = p.paper_sqrt_m(b), sb = p.sqrt_m(b);
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(a[c][r], b[c][r], 1e-12);
      EXPECT_NEAR(sa[c][r], sb[c][r], 1e-12);
    }
  // The printed blend = gp(toWorld, ours), on joints that need a hemisphere flip.
  const PF::motor toWorld = p.normalize_m(someMotor<PF>(0.5));
  const PF::motor j0 = b, j1 = -p.normalize_m(someMotor<PF>(2.0)), j2 = p.normalize_m(someMotor<PF>(-1.0));
  const PF::vec4 w(0.4, 0.3, 0.2, 0.1);
  const PF::motor printed = p.paper_skin_blend(toWorld, j0, j1, j2, j0, w);
  // Ours blends in motor_transform.glsl (a pipeline kernel); here the same rule written out.
  PF::motor r = j0 * w.x;
  r = r + j1 * (p.dot(r[0], j1[0]) <= 0.0 ? -w.y : w.y);
  r = r + j2 * (p.dot(r[0], j2[0]) <= 0.0 ? -w.z : w.z);
  r = r + j0 * (p.dot(r[0], j0[0]) <= 0.0 ? -w.w : w.w);
  const PF::motor ours = p.gp_mm(toWorld, p.normalize_m(r));
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(printed[c][k], ours[c][k], 1e-12);
}
