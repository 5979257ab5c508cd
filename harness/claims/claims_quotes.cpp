#include "harness/claims/claims_quotes.h"

#include <cstring>

namespace mb::claims {
namespace {

struct PaperQuote {
  const char* id;
  const char* tallyAs;  // the table row printed as one with another id, or nullptr
  const char* quote;
};

// Short quotations of reference/paper-look-ma-no-matrices.txt (section in brackets).
const PaperQuote kQuotes[] = {
    {"mat4_mul_mat4", nullptr, "\"the product of two 4x4 matrices requires 64 multiplications and 48 additions\" (Composition)"},
    {"gp_mm", nullptr, "table: \"gp_mm 48 40\" (Composition)"},
    {"gp_rr", nullptr, "table: \"gp_rr 16 12\" (Composition)"},
    {"gp_tt", nullptr, "table: \"gp_tt 0 3\" (Composition)"},
    {"gp_rt", "gp_rt / gp_tr", "table: \"gp_rt / gp_tr 12 8\" (Composition)"},
    {"gp_tr", "gp_rt / gp_tr", "table: \"gp_rt / gp_tr 12 8\" (Composition)"},
    {"gp_rm", "gp_rm / gp_mr", "table: \"gp_rm / gp_mr 32 24\" (Composition)"},
    {"gp_mr", "gp_rm / gp_mr", "table: \"gp_rm / gp_mr 32 24\" (Composition)"},
    {"gp_tm", "gp_tm / gp_mt", "table: \"gp_tm / gp_mt 12 12\" (Composition)"},
    {"gp_mt", "gp_tm / gp_mt", "table: \"gp_tm / gp_mt 12 12\" (Composition)"},
    {"composition", nullptr, "\"For two general PGA motors, their composition clocks in at just 48 multiplications and 40 additions\" (Composition)"},
    {"mat4_mul_vec4", nullptr, "\"the 16 multiplications and 12 additions required for the matrix-vector equivalent\" (Transforming points)"},
    {"sw_mp_naive", nullptr, "\"Working out these two geometric products naively results in a whopping 33 multiplications and 29 additions\" (Transforming points)"},
    {"sw_mp", nullptr, "\"allows us to reduce the operations needed to 21 multiplications and 18 additions\" (Transforming points)"},
    {"sw_md", nullptr, "\"a solution that requires only 18 multiplications and 12 additions\" (directions)"},
    {"sw_mx", nullptr, "\"if we produce an output normalized to 0.5 instead\" (basis directions; listing: 6 mul, 4 add)"},
    {"normalize_m", nullptr, "the inverse square root of a Study number (Normalization; table: 21 mul, 5 add)"},
    {"sqrt_m", nullptr, "sqrt_m = normalize_m(1 + R) (Square roots; table: 21 mul, 6 add)"},
    {"exp_b", nullptr, "listing comment \"17 muls 8 add 2 div 1 sqrt 1 cos 1 sin\" (Exp and log)"},
    {"log_m", nullptr, "listing comment \"14 muls 5 add 1 div 1 acos 1 sqrt\" (Exp and log)"},
    {"extractNormalTangent", nullptr, "\"extract the world-space normal and tangent directly with just 9 multiplications and 8 additions\" (Tangent frames)"},
    {"vertex_frame_motor", nullptr, "\"our PGA approach needs only (16 + 9 + 21 + 1 = 47) multiplications and (12 + 8 + 18 = 38) additions\" (Tangent frames)"},
    {"vertex_frame_matrix", nullptr, "\"the 48 multiplications and 36 additions that would be required if we use 4x4 matrices\" (Tangent frames)"},
    {"as_fast_as_matrices", nullptr, "\"PGA motors can be just as fast as 4x4 matrices to transform your mesh vertices\" (Tangent frames)"},
    {"handedness_rule", nullptr, "\"float handedness = sign(1/tangentRotor.x)\", \"we depend on the signed representation of zero\" (Tangent frames)"},
    {"floats_per_vertex", nullptr, "\"from 12 floats (3 position, 3 normal, 4 tangent, 2 uv) down to 9 (3 position, 4 tangentRotor, 2 uv)\" (Tangent frames)"},
    {"floats_per_transform", nullptr, "table: \"floats/transform 32 ... 8 -75%\" (Tangent frames)"},
    {"vertices_per_storage", nullptr, "\"an extra 33% vertices in the same storage\" (Conclusion)"},
    {"quaternion_to_rotor", nullptr, "\"conversion free inclusion of quaternions\""},
    {"uniform_scale_overhead", nullptr, "\"it requires only one floating point number per node\" (Scaling)"},
    {"scene_graph_update", nullptr, "\"a substantial optimization on the amount of computation needed to update the scene graph hierarchy\" (Model - View - Projection)"},
    {"animated_scale_corpus", nullptr, "\"less than 0.5% of the almost 400 random glTF files tested had any animation on the scale\" (Scaling)"},
    {"nonuniform_scale_leaves", nullptr, "\"we could only find non-uniform scale applied on leaf nodes\" (Handling non-uniform scaling)"},
    {"fragment_rotor", nullptr, "\"we could just pass the tangentRotor unmodified to the fragmentShader [...] requiring one less varying parameter, and removing the need for expensive orthogonalization in the fragment shader\" (Fragment Shader)"},
};

}  // namespace

void applyPaperQuotes(std::vector<Claim>& rows) {
  for (Claim& c : rows) {
    const PaperQuote* q = nullptr;
    for (const PaperQuote& k : kQuotes)
      if (c.id == k.id) q = &k;
    if (q) {
      c.quote = q->quote;
      c.tallyAs = q->tallyAs ? q->tallyAs : "";
      c.origin.clear();  // the paper's claim: it quotes its sentence
    } else if (c.origin.empty()) {
      c.origin = "not claimed by the paper";
    }
  }
}

}  // namespace mb::claims
