#include "harness/claims/claims_morph.h"

#include <cmath>

#include "harness/figures/figure.h"

namespace mb::claims {
namespace {

using nlohmann::json;

// The 50 dB rule for a motor method on rigid (unskinned) morph frames: the bound every rigid
// frame of a motor pipeline meets against matrix.
constexpr double kRigidPsnr = 50.0;

Claim row(const std::string& id, const std::string& statement, const std::string& method) {
  Claim c{id, "Morph targets", statement};
  c.paper = "- (not claimed by the paper)";
  c.method = method;
  c.origin = "morph";
  return c;
}

std::optional<figures::Figure> named(const json& morph, const std::string& name) {
  auto f = figures::figureNamed(morph, name);
  if (f && std::isnan(f->value)) return std::nullopt;
  return f;
}

void notMeasurable(Claim& c, const std::string& why) {
  c.verdict = Verdict::NotMeasurable;
  c.verdictText = "not measurable here: " + why;
  c.measured = "-";
}

}  // namespace

std::vector<Claim> morphClaims(const json& report, const std::string& reportSource) {
  const json morph = report.is_object() && report.contains("morph") ? report["morph"] : json();
  const std::string from = "report.json 'morph' (" + reportSource + ", `motorbench morph`)";
  const std::string missing = morph.is_object() ? "" : "no morph figures: give `motorbench morph --json` to "
                                                       "`motorbench report --morph-json` and that report to --report";
  std::vector<Claim> out;

  Claim vertex = row("morph_vertex_bytes", "the paper's 9-float motor vertex survives morph targets",
                     "morph.bytes_per_vertex.<method> of " + from);
  auto mv = named(morph, "morph.bytes_per_vertex.motor_frame"), xv = named(morph, "morph.bytes_per_vertex.matrix");
  if (!missing.empty() || !mv || !xv) {
    notMeasurable(vertex, missing.empty() ? "no bytes figures" : missing);
  } else {
    vertex.measured = figures::valueText(*mv) + " per motor vertex vs " + figures::valueText(*xv) + " per matrix vertex";
    vertex.measuredValue = {{"motor", mv->value}, {"matrix", xv->value}};
    vertex.verdict = Verdict::Baseline;
    vertex.verdictText = mv->value == 36 ? "the motor vertex keeps its 9 floats: the deltas live in their own buffer"
                                         : "the motor vertex is not 9 floats with morph targets";
  }
  out.push_back(vertex);

  Claim target = row("morph_target_bytes", "bytes per vertex of one morph target, per method",
                     "morph.bytes_per_target_vertex.<method> of " + from);
  auto tm = named(morph, "morph.bytes_per_target_vertex.matrix"),
       ta = named(morph, "morph.bytes_per_target_vertex.motor_frame"),
       tb = named(morph, "morph.bytes_per_target_vertex.motor_rotor");
  if (!missing.empty() || !tm || !ta || !tb) {
    notMeasurable(target, missing.empty() ? "no bytes figures" : missing);
  } else {
    target.measured = "matrix " + figures::valueText(*tm) + ", motor (a) frame " + figures::valueText(*ta) +
                      ", motor (b) rotor " + figures::valueText(*tb);
    target.measuredValue = {{"matrix", tm->value}, {"motor_frame", ta->value}, {"motor_rotor", tb->value}};
    target.verdict = Verdict::Baseline;
    target.verdictText = "baseline: the rotor method stores " + fmt("%g", ta->value - tb->value) +
                         " bytes fewer per target vertex than the frame method";
  }
  out.push_back(target);

  for (const auto& [id, method, label] : {std::tuple{"morph_frame_image", "motor_frame", "(a) frame"},
                                          std::tuple{"morph_rotor_image", "motor_rotor", "(b) rotor deltas"}}) {
    const std::string name = std::string("morph.worst_psnr.rigid.") + method;
    Claim c = row(id, std::string("motor morph method ") + label + " draws rigid morph frames as matrix does (>= 50 dB)",
                  name + " of " + from);
    auto f = figures::figureNamed(morph, name);
    if (!missing.empty() || !f || (std::isnan(f->value) && f->why.rfind("identical", 0) != 0)) {
      notMeasurable(c, !missing.empty() ? missing : f ? f->why : "no figure " + name);
    } else {
      const bool identical = std::isnan(f->value);
      c.measured = identical ? "identical on every frame" : figures::figureText(*f);
      c.measuredValue = identical ? json(nullptr) : json(f->value);
      c.verdict = identical || f->value >= kRigidPsnr ? Verdict::Reproduced : Verdict::Differs;
      c.verdictText = c.verdict == Verdict::Reproduced
                          ? "holds: worst frame >= 50 dB against matrix"
                          : "differs: worst frame " + figures::valueText(*f) +
                                " (a linear blend of rotors is not the rotor of the blended frame)";
    }
    if (morph.is_object() && morph.contains("worst") && morph["worst"].contains(name) && !morph["worst"][name].is_null())
      c.method += "; worst frame: " + morph["worst"][name].value("scene", std::string("?")) + " anim " +
                  std::to_string(morph["worst"][name].value("anim", -1)) + " t " +
                  fmt("%.3g", morph["worst"][name].value("time", 0.0));
    out.push_back(c);
  }
  return out;
}

}  // namespace mb::claims
