// The paper's arithmetic claims, each measured by executing the kernel of shaders/pga.glsl (or
// the GLSL matrix operator) once on the op-counting scalar: the `motorbench ops` table
// (harness/ops/op_kernels.h) and the per-vertex functions of harness/ops/ops_vertex.h.
#include <map>
#include <stdexcept>

#include "harness/bench/bench_shaders.h"
#include "harness/claims/claims_sources.h"
#include "harness/ops/op_count.h"
#include "harness/ops/op_kernels.h"
#include "harness/ops/ops_vertex.h"
#include "shaders/shim/paper_listings.h"

namespace mb::claims {
namespace {

const char* kCounted =
    "executed once on the op-counting scalar (mb::Counted) through the GLSL shim, generic inputs "
    "(no zero coefficient, so no product is skipped); subtraction counts as addition, negation is free";

// Every `motorbench ops` kernel by name: counted here, and run again inside other counts.
std::map<std::string, ops::Kernel> kernels() {
  std::map<std::string, ops::Kernel> out;
  for (const ops::Kernel& k : ops::allKernels()) out.emplace(k.name, k);
  return out;
}

// Counted ops of the per-vertex function `fn` of ops_vertex.h.
OpCounts vertexFunction(const std::string& fn) {
  for (const opsv::VertexKernel& k : opsv::vertexKernels())
    if (k.function == fn) return opsv::countVertexKernel(k);
  throw std::runtime_error("ops_vertex.h has no per-vertex function " + fn);
}

// The paper's printed listings (shaders/paper_listings.glsl), counted on generic inputs: a
// non-unit motor (normalize_m's input), a motor with scalar part != 1 (log_m's closed form), a
// bivector with a non-zero Euclidean part (exp_b's closed form).
struct Listings {
  OpCounts normalize, sqrt, log, exp;
};
Listings countListings() {
  static PaperListings<Counted> L;
  using PL = PaperListings<Counted>;
  const PL::motor m(0.9, 0.2, -0.3, 0.1, 0.4, -0.2, 0.3, 0.05);
  const PL::motor unit = L.normalize_m(m);
  const PL::line b(Counted(0.3), Counted(-0.2), Counted(0.5), Counted(0.1), Counted(0.4), Counted(-0.6));
  return {countOps([&] { L.paper_normalize_m(m); }), countOps([&] { L.paper_sqrt_m(unit); }),
          countOps([&] { L.paper_log_m(unit); }), countOps([&] { L.paper_exp_b(b); })};
}

const char* kListing =
    "the paper's printed listing transcribed expression for expression in shaders/paper_listings.glsl and "
    "counted the same way";

// The rows being written, with the kernels they count: each row judged as it is added.
class OpRows {
public:
  // The kernel `name` of op_kernels.h (throws when there is none).
  const ops::Kernel& kernel(const std::string& name) const {
    auto it = k_.find(name);
    if (it == k_.end()) throw std::runtime_error("op_kernels.h has no kernel " + name);
    return it->second;
  }
  // The counted ops of one execution of kernel `name`.
  OpCounts get(const std::string& name) const { return countOps(kernel(name).run); }
  // A row judged against the paper's counts.
  void add(const std::string& id, const std::string& section, const std::string& statement, PaperOps paper,
           const OpCounts& measured, const std::string& method) {
    Claim c{id, section, statement};
    c.method = method;
    judgeOps(c, paper, measured);
    out.push_back(c);
  }
  // A row judged three ways: the paper's counts, its printed listing counted, and ours.
  void three(const std::string& id, const std::string& statement, PaperOps paper, const OpCounts& printed,
             const OpCounts& ours, const std::string& method, const std::string& why) {
    Claim c{id, kToolbox, statement};
    c.method = method;
    judgeOpsThree(c, paper, printed, ours, why);
    out.push_back(c);
  }
  static constexpr const char* kToolbox = "Normalisation, square root, exp and log";
  std::vector<Claim> out;

private:
  const std::map<std::string, ops::Kernel> k_ = kernels();
};

// Composition (table 1): mat4 * mat4 and every geometric product of motors, rotors and
// translators.
void compositionRows(OpRows& rows) {
  const OpCounts mm = rows.get("mat4*mat4");
  const std::string vsMat4 = " (mat4*mat4 measured the same way: " + opsText(mm) + ")";
  const std::string composition = "Composition (table 1)";
  rows.add("mat4_mul_mat4", composition, "4x4 matrix product", {64, 48}, mm,
           std::string("GLSL mat4 * mat4 through the shim, ") + kCounted);
  struct Row { const char* id; const char* what; int mul, add; };
  for (const Row& r : {Row{"gp_mm", "motor * motor", 48, 40}, Row{"gp_rr", "rotor * rotor", 16, 12},
                       Row{"gp_tt", "translator * translator", 0, 3}, Row{"gp_rt", "rotor * translator", 12, 8},
                       Row{"gp_tr", "translator * rotor", 12, 8}, Row{"gp_rm", "rotor * motor", 32, 24},
                       Row{"gp_mr", "motor * rotor", 32, 24}, Row{"gp_tm", "translator * motor", 12, 12},
                       Row{"gp_mt", "motor * translator", 12, 12}})
    rows.add(r.id, composition, std::string(r.id) + ": " + r.what + ", against mat4*mat4 64/48", {r.mul, r.add},
             rows.get(r.id), std::string(r.id) + " of shaders/pga.glsl " + kCounted + vsMat4);
}

// Sandwich products: mat4 * vec4 and the point, direction and basis-direction sandwiches (the
// naive point sandwich inconclusive: the paper does not define its expansion).
void sandwichRows(OpRows& rows) {
  const OpCounts mv = rows.get("mat4*vec4");
  const std::string sandwich = "Sandwich products";
  rows.add("mat4_mul_vec4", sandwich, "matrix * point (the reference for the sandwiches)", {16, 12}, mv,
           std::string("GLSL mat4 * vec4 through the shim, ") + kCounted);
  const std::string vsMv = " (mat4*vec4 measured: " + opsText(mv) + ")";
  {
    // The paper prints no naive expansion: its 33/29 counts some order of the two products that
    // is not given. Ours is one definite expansion; the row cannot decide the paper's number.
    Claim c{"sw_mp_naive", sandwich, "naive point sandwich M p ~M (two geometric products)"};
    c.method = std::string("sw_mp_naive of shaders/pga.glsl: the two full geometric products of M p ~M, "
                           "written as (M p) first (its e0 and trivector parts: x0 = A.p - e0123, "
                           "T = s p + p x A - Ad), then the trivector part of (M p) ~M = s T + T x A + x0 A "
                           "- s Ad + A x Ad - e0123 A (A = rotor bivector, Ad = dual bivector), ") +
               kCounted + vsMv;
    judgeOps(c, {33, 29}, rows.get("sw_mp_naive"));
    const std::string against = c.verdictText;
    c.verdict = Verdict::Inconclusive;
    c.verdictText = "inconclusive: the paper does not print or define the expansion behind its 33/29; ours "
                    "(defined in the method) " + against.substr(0, against.find(';')) +
                    ", and another grouping of the same two products counts differently";
    rows.out.push_back(c);
  }
  rows.add("sw_mp", sandwich, "optimised point sandwich (uses M~M = 1), vs mat4*vec4 16/12", {21, 18}, rows.get("sw_mp"),
           std::string("sw_mp of shaders/pga.glsl ") + kCounted + vsMv);
  rows.add("sw_md", sandwich, "direction sandwich", {18, 12}, rows.get("sw_md"),
           std::string("sw_md of shaders/pga.glsl ") + kCounted);
  rows.add("sw_mx", sandwich, "basis-direction sandwich (x axis, output scaled by 1/2)", {6, 4}, rows.get("sw_mx"),
           std::string("sw_mx of shaders/pga.glsl ") + kCounted + "; y and z axes measured: sw_my " +
               opsText(rows.get("sw_my")) + ", sw_mz " + opsText(rows.get("sw_mz")));
}

// Normalisation, square root, exp and log: ours and the paper's printed listings, each against
// the paper's counts (and the relation sqrt_m = normalize_m + 1 add on both).
void toolboxRows(OpRows& rows) {
  const Listings listing = countListings();
  const OpCounts normOurs = rows.get("normalize_m"), sqrtOurs = rows.get("sqrt_m");
  rows.three("normalize_m", "motor normalisation (Study-number inverse square root)", {21, 5}, listing.normalize,
             normOurs,
             std::string("ours: normalize_m of shaders/pga.glsl on a non-unit motor; listing: ") + kListing + "; " +
                 kCounted,
             "ours takes inversesqrt and scales the dual correction once");
  {
    rows.three("sqrt_m", "motor square root = normalize(1 + M): the cost of normalize_m plus one addition", {21, 6},
               listing.sqrt, sqrtOurs,
               std::string("ours: sqrt_m of shaders/pga.glsl; listing: ") + kListing + "; " + kCounted,
               "ours is our normalize_m + 1 add");
    // The paper's relation itself, checked on both codes.
    Claim& c = rows.out.back();
    const bool oursRel = sqrtOurs.mul == normOurs.mul && sqrtOurs.add == normOurs.add + 1;
    const bool listRel = listing.sqrt.mul == listing.normalize.mul && listing.sqrt.add == listing.normalize.add + 1;
    c.verdictText += std::string("; the relation sqrt_m = normalize_m + 1 add: ") +
                     (oursRel && listRel ? "reproduced by ours and by the listing"
                                         : oursRel ? "reproduced by ours only" : listRel ? "reproduced by the listing only"
                                                                                         : "not reproduced");
  }
  rows.three("exp_b", "exponential of a line (bivector) -> motor", {17, 8, 2, 1, 2, "1 cos, 1 sin"}, listing.exp,
             rows.get("exp_b"),
             std::string("ours: exp_b of shaders/pga.glsl on a general bivector (non-zero, so the closed form runs); "
                         "listing: ") + kListing + "; " + kCounted,
             "");
  rows.three("log_m", "logarithm of a motor -> line", {14, 5, 1, 1, 1, "1 acos"}, listing.log, rows.get("log_m"),
             std::string("ours: log_m of shaders/pga.glsl on a general motor (scalar part != 1); listing: ") + kListing +
                 "; " + kCounted,
             "our accuracy rewrite of 1 - s^2 as (1 - s)(1 + s) (exact near s = 1, small rotations, in float) costs "
             "one addition");
}

// Vertex with tangent frame: the frame extraction, the paper's 47/38 motor vertex (its pieces
// counted together as the shader executes them) and the 48/36 matrix vertex.
void vertexRows(OpRows& rows) {
  const std::string vertex = "Vertex with tangent frame";
  rows.add("extractNormalTangent", vertex, "world normal + tangent from the frame rotor", {9, 8},
           rows.get("extractNormalTangent"), std::string("extractNormalTangent of shaders/pga.glsl ") + kCounted);

  // The paper's 47/38: sw_mp + gp_rr + extractNormalTangent + 1 for the handedness, counted
  // as one execution of the four pieces.
  static MotorShader<Counted> P;
  const auto handedness = [] { P.motorHandedness(MotorShader<Counted>::vec4(-0.5, 0.5, -0.5, 0.5)); };
  const OpCounts hand = countOps(handedness);
  const OpCounts pieces = countOps([&] {
    rows.kernel("sw_mp").run();
    rows.kernel("gp_rr").run();
    rows.kernel("extractNormalTangent").run();
    handedness();
  });
  const OpCounts motorVertex = vertexFunction("motorRigidVertex");
  // Judged on what the shader executes, never on the paper's 1 mul added to
  // our count: the paper counts its handedness as 1 multiplication; its listing and our shader
  // compute it as sign(1/x), which keeps the sign of a zero scalar part.
  rows.add("vertex_frame_motor", vertex,
           "motor vertex with full tangent frame to world space: 16 + 9 + 21 + 1 = 47 mul, 12 + 8 + 18 = 38 add",
           {47, 38}, pieces,
           "the pieces the paper names, executed once each and counted together as the shader executes them: sw_mp " +
               opsText(rows.get("sw_mp")) + " + gp_rr " + opsText(rows.get("gp_rr")) + " + extractNormalTangent " +
               opsText(rows.get("extractNormalTangent")) + " + the handedness sign(1/x) " + opsText(hand) +
               " (the paper counts it as 1 mul). Rule: every op column executed against the paper's (mul, add; columns the "
               "paper does not state listed); reproduced only when each stated column is equal. The pipeline's whole "
               "function motorRigidVertex (shaders/motor_transform.glsl, incl. the uniform scale applied in the shader) "
               "counts " + opsText(motorVertex));
  rows.out.back().verdictText += "; the paper's 47th mul is its handedness, which the shader executes as sign(1/x) (" +
                                 opsText(hand) + "): executed " + opsText(pieces) + " beside the paper's 47 mul, 38 add";
  const OpCounts matrixFrame = vertexFunction("matrixRigidVertex");
  rows.add("vertex_frame_matrix", vertex,
           "matrix vertex with normal and tangent: three mat4*vec4 = 48 mul, 36 add", {48, 36},
           countOps([&] { for (int i = 0; i < 3; ++i) rows.kernel("mat4*vec4").run(); }),
           "three counted mat4*vec4 (position and tangent by the model matrix, normal by the normal matrix). "
           "The pipeline's whole function matrixRigidVertex (shaders/matrix_transform.glsl, as the glTF "
           "Sample Viewer, incl. the handedness sign from the normal matrix) counts " + opsText(matrixFrame));
}

}  // namespace

std::vector<Claim> opClaims() {
  OpRows rows;
  compositionRows(rows);
  sandwichRows(rows);
  toolboxRows(rows);
  vertexRows(rows);
  return std::move(rows.out);
}

}  // namespace mb::claims
