// Bezier patch evaluation and frames (shaders/bezier_patch.glsl, shaders/patch_transform.glsl)
// on the CPU through the GLSL shim: against an independent de Casteljau reference and finite
// differences, bit-identical positions along shared teapot edges (no cracks), finite frames on
// the degenerate edges, matrix and motor frames against each other, and the counted ops of
// both motor frame methods.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "tests/support/patch_test_support.h"
#include "shaders/shim/counted.h"

namespace {

using mbtest::evaluate;
using mbtest::referencePoint;
using PF = mb::PatchShaders<float>;
using PD = mb::PatchShaders<double>;

glm::dvec3 toGlm(const PD::vec3& v) { return {v.x, v.y, v.z}; }
glm::vec3 toGlm(const PF::vec3& v) { return {v.x, v.y, v.z}; }

class TeapotPatches : public ::testing::Test {
protected:
  void SetUp() override {
    pts_ = mbtest::teapotPoints();
    ASSERT_EQ(pts_.size(), 32u * 16u);
  }
  std::vector<glm::vec3> pts_;
};

TEST_F(TeapotPatches, PositionsMatchDeCasteljau) {
  double worst = 0.0;
  for (size_t p = 0; p < 32; ++p)
    for (int j = 0; j <= 8; ++j)
      for (int i = 0; i <= 8; ++i) {
        double u = i / 8.0, v = j / 8.0;
        glm::dvec3 ref = referencePoint(pts_, p, u, v);
        glm::dvec3 got(toGlm(evaluate<float>(pts_, p, u, v)[0]));
        worst = std::max(worst, glm::length(got - ref) / std::max(1.0, glm::length(ref)));
      }
  EXPECT_LT(worst, 1e-6) << "float evaluation vs double de Casteljau, relative";
}

TEST_F(TeapotPatches, DerivativesMatchFiniteDifferences) {
  const double h = 1e-5;
  int compared = 0;
  for (size_t p = 0; p < 32; ++p)
    for (int j = 1; j <= 7; ++j)  // interior: the degenerate-edge replacement is tested below
      for (int i = 1; i <= 7; ++i) {
        double u = i / 8.0, v = j / 8.0;
        auto s = evaluate<double>(pts_, p, u, v);
        glm::dvec3 du = (referencePoint(pts_, p, u + h, v) - referencePoint(pts_, p, u - h, v)) / (2 * h);
        glm::dvec3 dv = (referencePoint(pts_, p, u, v + h) - referencePoint(pts_, p, u, v - h)) / (2 * h);
        EXPECT_NEAR(glm::length(toGlm(s[1]) - du), 0.0, 1e-6 * std::max(1.0, glm::length(du))) << p << " " << u << " " << v;
        EXPECT_NEAR(glm::length(toGlm(s[2]) - dv), 0.0, 1e-6 * std::max(1.0, glm::length(dv))) << p << " " << u << " " << v;
        ++compared;
      }
  EXPECT_EQ(compared, 32 * 49);
}

// An edge of a patch: its 4 control points and how to evaluate along it at parameter t.
struct Edge {
  size_t patch;
  std::array<glm::vec3, 4> points;
  bool alongU;  // true: v fixed at `fixed`, t = u; false: u fixed, t = v
  double fixed;
};

std::vector<Edge> edgesOf(const std::vector<glm::vec3>& pts, size_t p) {
  auto at = [&](int r, int c) { return pts[16 * p + size_t(4 * r + c)]; };
  std::vector<Edge> e;
  for (int r : {0, 3}) e.push_back({p, {at(r, 0), at(r, 1), at(r, 2), at(r, 3)}, true, r / 3.0});
  for (int c : {0, 3}) e.push_back({p, {at(0, c), at(1, c), at(2, c), at(3, c)}, false, c / 3.0});
  return e;
}

PF::vec3 along(const std::vector<glm::vec3>& pts, const Edge& e, double t) {
  return e.alongU ? evaluate<float>(pts, e.patch, t, e.fixed)[0] : evaluate<float>(pts, e.patch, e.fixed, t)[0];
}

TEST_F(TeapotPatches, SharedEdgesEvaluateBitIdentically) {
  std::vector<Edge> edges;
  for (size_t p = 0; p < 32; ++p)
    for (const Edge& e : edgesOf(pts_, p)) edges.push_back(e);
  int shared = 0, reversed = 0;
  for (size_t a = 0; a < edges.size(); ++a)
    for (size_t b = a + 1; b < edges.size(); ++b) {
      if (edges[a].patch == edges[b].patch) continue;
      const auto &pa = edges[a].points, &pb = edges[b].points;
      bool same = pa == pb, flip = pa == std::array<glm::vec3, 4>{pb[3], pb[2], pb[1], pb[0]};
      if (!same && !flip) continue;
      if (pa[0] == pa[3] && pa[1] == pa[2] && pa[0] == pa[1]) continue;  // collapsed to a point
      ++shared;
      reversed += !same;
      for (int k = 0; k <= 64; ++k) {
        double t = k / 64.0;
        PF::vec3 x = along(pts_, edges[a], t), y = along(pts_, edges[b], same ? t : 1.0 - t);
        ASSERT_TRUE(x.x == y.x && x.y == y.y && x.z == y.z)
            << "crack between patches " << edges[a].patch << " and " << edges[b].patch << " at t=" << t;
      }
    }
  // The teapot's patches meet along many edges (rims, seams between quarters, handle, spout).
  EXPECT_GE(shared, 40);
  std::printf("shared edges: %d (%d in opposite directions)\n", shared, reversed);
}

// Patches 21-24 (lid knob, apex) and 29-32 (bottom, centre) have their first row collapsed.
TEST_F(TeapotPatches, DegenerateEdgesGetTheLimitNormal) {
  for (size_t p : {20u, 21u, 22u, 23u, 28u, 29u, 30u, 31u}) {
    for (int c = 1; c < 4; ++c) ASSERT_EQ(pts_[16 * p + size_t(c)], pts_[16 * p]) << "patch " << p + 1;
    for (int i = 0; i <= 16; ++i) {
      double u = i / 16.0;
      auto edge = evaluate<double>(pts_, p, u, 0.0);
      glm::dvec3 n = glm::cross(toGlm(edge[1]), toGlm(edge[2]));
      ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
      ASSERT_GT(glm::length(n), 1e-6) << "patch " << p + 1 << " u=" << u;
      // The limit of the normal from inside the patch.
      auto inside = evaluate<double>(pts_, p, u, 1e-4);
      glm::dvec3 m = glm::cross(toGlm(inside[1]), toGlm(inside[2]));
      EXPECT_GT(glm::dot(glm::normalize(n), glm::normalize(m)), 0.9999) << "patch " << p + 1 << " u=" << u;
      // Both centres lie on the axis of revolution: the normal there is the axis (z).
      EXPECT_GT(std::fabs(glm::normalize(n).z), 0.9999) << "patch " << p + 1 << " u=" << u;
      // The float path (the GPU's precision) gives a finite, non-zero normal too.
      auto f = evaluate<float>(pts_, p, u, 0.0);
      glm::vec3 nf = glm::cross(toGlm(f[1]), toGlm(f[2]));
      ASSERT_TRUE(std::isfinite(nf.x) && std::isfinite(nf.y) && std::isfinite(nf.z) && glm::length(nf) > 0.0f);
    }
  }
}

TEST_F(TeapotPatches, MatrixAndMotorFramesAgree) {
  // A node transform: rotation, translation, uniform scale 1.7, as the matrix pipeline builds it.
  glm::dquat q = glm::normalize(glm::dquat(0.8, -0.3, 0.5, 0.1));
  glm::dvec3 t(0.4, -1.2, 2.5);
  double scale = 1.7;
  glm::dmat4 model = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), glm::dvec3(scale));
  glm::dmat4 normal = glm::transpose(glm::inverse(model));
  normal[3][3] = 1.0;  // sign(det(model)), as matrix::normalMatrix stores it
  PD::mat4 M, N;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) M[c][r] = model[c][r], N[c][r] = normal[c][r];
  // The glTF mapping of pga.glsl: rotor [w, -x, -y, -z], translator [1 | -t/2], motor = T R.
  PD::motor R(PD::vec4(q.w, -q.x, -q.y, -q.z), PD::vec4(0.0));
  PD::motor T(PD::vec4(1.0, 0.0, 0.0, 0.0), PD::vec4(-t.x / 2, -t.y / 2, -t.z / 2, 0.0));
  PD S;
  PD::motor world = S.gp_tr(T, R);
  for (size_t p = 0; p < 32; p += 3)
    for (double u : {0.0, 0.3, 1.0})
      for (double v : {0.0, 0.55, 1.0}) {
        auto s = evaluate<double>(pts_, p, u, v);
        auto m = S.matrixPatchVertex(M, N, s);
        auto a = S.motorPatchVertex(world, scale, s);
        auto b = S.motorPatchVertexRotor(world, scale, s);
        glm::dvec3 pm(m[0].x, m[0].y, m[0].z), pa(a[0].x, a[0].y, a[0].z), pb(b[0].x, b[0].y, b[0].z);
        EXPECT_LT(glm::length(pm - pa), 1e-12 * 10) << p;
        EXPECT_LT(glm::length(pm - pb), 1e-12 * 10) << p;
        auto dir = [](const PD::vec4& x) { return glm::normalize(glm::dvec3(x.x, x.y, x.z)); };
        EXPECT_GT(glm::dot(dir(m[1]), dir(a[1])), 1.0 - 1e-12) << "normal, method (a), patch " << p;
        EXPECT_GT(glm::dot(dir(m[1]), dir(b[1])), 1.0 - 1e-12) << "normal, method (b), patch " << p;
        EXPECT_GT(glm::dot(dir(m[2]), dir(a[2])), 1.0 - 1e-12) << "tangent, method (a), patch " << p;
        EXPECT_GT(glm::dot(dir(m[2]), dir(b[2])), 1.0 - 1e-12) << "tangent, method (b), patch " << p;
        EXPECT_EQ(m[2].w, 1.0);
        EXPECT_EQ(a[2].w, 1.0);
      }
}

// ---- counted ops (mb::Counted through the shim) ----------------------------------------------

using PC = mb::PatchShaders<mb::Counted>;
using mb::Counted;
using mb::countOps;

struct Expect {
  uint64_t mul, add, div = 0, sqrt = 0, other = 0;
};

std::string summary(const mb::OpCounts& c) {
  std::string s = std::to_string(c.mul) + " mul, " + std::to_string(c.add) + " add";
  if (c.div) s += ", " + std::to_string(c.div) + " div";
  if (c.sqrt) s += ", " + std::to_string(c.sqrt) + " sqrt";
  if (c.other) s += ", " + std::to_string(c.other) + " other (" + c.otherCalls() + ")";
  return s;
}

void expectCounts(const mb::OpCounts& c, const Expect& e, const std::string& what) {
  EXPECT_EQ(c.mul, e.mul) << what;
  EXPECT_EQ(c.add, e.add) << what;
  EXPECT_EQ(c.div, e.div) << what;
  EXPECT_EQ(c.sqrt, e.sqrt) << what;
  EXPECT_EQ(c.other, e.other) << what;
}

// Generic inputs: an interior vertex of a real teapot patch, a unit motor, arbitrary matrices.
struct CountInputs {
  std::array<PC::mat4x3, 4> rows;
  PC::vec2 uv{Counted(0.3), Counted(0.6)};
  PC::mat4 model, normal;
  PC::motor world;
  CountInputs(const std::vector<glm::vec3>& pts) {
    rows = mbtest::patchRows<Counted>(pts, 5);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        model[c][r] = Counted(0.9 + 0.37 * c - 0.21 * r);
        normal[c][r] = Counted(-0.4 + 0.3 * c + 0.11 * r);
      }
    glm::dquat q = glm::normalize(glm::dquat(0.8, -0.3, 0.5, 0.1));
    world = PC::motor(PC::vec4(Counted(q.w), Counted(-q.x), Counted(-q.y), Counted(-q.z)),
                      PC::vec4(Counted(0.2), Counted(-0.6), Counted(1.25), Counted(0.07)));
  }
};

TEST_F(TeapotPatches, CountedOpsOfEvaluationAndBothMotorFrames) {
  PC S;
  CountInputs in(pts_);
  PC::mat3 surface;
  auto eval = countOps([&] { surface = S.bezierPatch(in.rows[0], in.rows[1], in.rows[2], in.rows[3], in.uv); });
  auto matrix = countOps([&] { S.matrixPatchVertex(in.model, in.normal, surface); });
  auto motorA = countOps([&] { S.motorPatchVertex(in.world, Counted(1.0), surface); });
  auto motorB = countOps([&] { S.motorPatchVertexRotor(in.world, Counted(1.0), surface); });
  std::printf("evaluation: %s\nmatrix frame: %s\nmotor frame (a) sandwich + cross: %s\nmotor frame (b) rotor + gp_rr: %s\n",
              summary(eval).c_str(), summary(matrix).c_str(), summary(motorA).c_str(), summary(motorB).c_str());
  // Bases 2 x (8/1) + 2 x (6/1); four rows 4 x (21/24); P and dP/du 2 x (12/9); dP/dv 9/15;
  // the two squared lengths 6/4; the relative degenerate test 2 mul.
  expectCounts(eval, {16 + 12 + 84 + 24 + 9 + 6 + 2, 2 + 2 + 96 + 18 + 15 + 4}, "bezierPatch (interior vertex)");
  // cross 6/3, three mat4 * vec4 48/36, handedness 1/0.
  expectCounts(matrix, {55, 39}, "matrixPatchVertex");
  // sw_mp 21/18 after the scale 3/0, two sw_md 2 x (18/12), cross 6/3.
  expectCounts(motorA, {66, 45}, "motorPatchVertex (a)");
  // (b) at this vertex (frame trace <= 0, largest diagonal branch): normalize(dP/du) 6/2 + 1
  // inversesqrt; cross 6/3 and its normalize 6/2 + 1 inversesqrt; frameRotor: bitangent cross
  // 6/3, trace 0/2, s = 2 sqrt(1 + a - b - c) 1/3 + 1 sqrt, 0.25 s 1/0, three (x + y) / s
  // 0/3 + 3 div; gp_rr 16/12; extractNormalTangent 9/8; sw_mp 21/18 after the scale 3/0.
  expectCounts(motorB, {75, 56, 3, 1, 2}, "motorPatchVertexRotor (b)");
  EXPECT_GT(motorB.mul + motorB.add, motorA.mul + motorA.add) << "method (a) is the cheaper one, kept";
}

TEST(PatchOps, DegenerateVertexPaysForTheMixedDerivative) {
  auto pts = mbtest::teapotPoints();
  ASSERT_FALSE(pts.empty());
  PC S;
  auto rows = mbtest::patchRows<Counted>(pts, 20);  // lid knob: row 0 collapsed to the apex
  auto interior = countOps([&] { S.bezierPatch(rows[0], rows[1], rows[2], rows[3], PC::vec2(Counted(0.3), Counted(0.6))); });
  auto apex = countOps([&] { S.bezierPatch(rows[0], rows[1], rows[2], rows[3], PC::vec2(Counted(0.3), Counted(0.0))); });
  // The mixed derivative: 3 differences 9 add, 3 scalings 9 mul, 2 sums 6 add; one more
  // relative test (1 mul) picks which derivative to replace. Negating it is free.
  EXPECT_EQ(apex.mul - interior.mul, 9u + 1u - 1u);
  EXPECT_EQ(apex.add - interior.add, 15u);
}

}  // namespace
