#include "harness/document/scope_ladder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/document/report_format.h"
#include "harness/figures/figure.h"

namespace mb::document {
namespace {

using json = nlohmann::json;

const char* const kStages[] = {"transform to world", "transform to clip", "whole vertex shader"};
const char* const kMeasures[] = {"counted ops",    "SPIR-V probe", "SPIR-V whole shader", "ISA instructions",
                                 "ISA inverse throughput", "VGPRs", "occupancy", "CPU kernel"};

double value(const json& figures, const std::string& name) {
  const auto f = figures::figureNamed(figures, name);
  if (!f || !std::isfinite(f->value)) return NAN;
  if (figures::isDisturbed(*f)) return NAN;
  return f->value;
}

// The figure-name pattern of a measure at a stage, with "{p}" for the pipeline and "{f}" for
// the family; "" where the measure does not reach that stage.
std::string pattern(const std::string& stage, const std::string& measure) {
  const bool world = stage == kStages[0], clip = stage == kStages[1], whole = stage == kStages[2];
  if (measure == "counted ops") return world ? "ops_per_vertex.rigid.counted.{p}" : clip ? "ops_per_vertex.to_clip.counted.{p}" : "";
  if (measure == "SPIR-V probe")
    return world ? "ops_per_vertex.rigid.spirv_probe.{p}" : clip ? "ops_per_vertex.to_clip.spirv_probe.{p}" : "";
  if (!whole) return "";
  if (measure == "SPIR-V whole shader") return "ops_per_vertex.rigid.spirv_whole_shader.{p}";
  if (measure == "ISA instructions") return "isa.instructions.rigid.{f}.{p}";
  if (measure == "ISA inverse throughput") return "isa.inverse_throughput.rigid.{f}.{p}";
  if (measure == "VGPRs") return "isa.vgprs.rigid.{f}.{p}";
  if (measure == "occupancy") return "isa.waves.rigid.{f}.{p}";
  return "";
}

std::string fill(std::string s, const std::string& p, const std::string& f) {
  for (auto [key, with] : {std::pair<std::string, std::string>{"{p}", p}, {"{f}", f}})
    if (const size_t at = s.find(key); at != std::string::npos) s.replace(at, key.size(), with);
  return s;
}

// The ISA family ids the figures name (isa.instructions.rigid.<id>.<pipeline>), in order seen.
std::vector<std::string> familiesOf(const json& figures, const std::string& motor) {
  std::vector<std::string> out;
  const std::string head = "isa.instructions.rigid.", tail = "." + motor;
  for (const auto& [name, _] : figures.items())
    if (name.rfind(head, 0) == 0 && name.size() > head.size() + tail.size() &&
        name.compare(name.size() - tail.size(), tail.size(), tail) == 0)
      out.push_back(name.substr(head.size(), name.size() - head.size() - tail.size()));
  return out;
}

void judge(LadderCell& c) {
  if (c.ratios.empty()) {
    c.worst = c.best = NAN;
    c.verdict = "-";
    c.text = "-";
    return;
  }
  c.worst = *std::max_element(c.ratios.begin(), c.ratios.end());
  c.best = *std::min_element(c.ratios.begin(), c.ratios.end());
  const bool all = c.worst <= kAsCheapLimit, none = c.best > kAsCheapLimit;
  c.verdict = all ? "as cheap" : none ? "dearer" : "split";
  c.text = c.best == c.worst ? sig3(c.worst) + "x" : sig3(c.best) + ".." + sig3(c.worst) + "x";
}

LadderCell opsCell(const json& figures, const std::string& stage, const std::string& measure, const std::string& baseline,
                   const std::vector<std::string>& matrixFamily, const std::vector<std::string>& families) {
  LadderCell c{stage, measure, baseline};
  c.kind = measure == "counted ops" ? "counted" : "compiled";
  c.paperScope = stage == kStages[0] && baseline == "paper";
  const std::string pat = pattern(stage, measure);
  if (pat.empty()) return judge(c), c;
  const bool perFamily = pat.find("{f}") != std::string::npos;
  for (const std::string& fam : perFamily ? families : std::vector<std::string>{""}) {
    std::string side = "matrix";
    if (baseline == "strongest") {  // the cheapest matrix-family pipeline of this sample
      double least = NAN;
      for (const std::string& p : matrixFamily) {
        // Occupancy is a benefit: the strongest form reaches the most waves.
        const double v = value(figures, fill(pat, p, fam));
        const bool better = measure == "occupancy" ? v > least : v < least;
        if (std::isfinite(v) && (!std::isfinite(least) || better)) least = v, side = p;
      }
    }
    const std::string a = fill(pat, "motor", fam), b = fill(pat, side, fam);
    c.samples.push_back({a, b});
    const double x = value(figures, a), y = value(figures, b);
    if (!std::isfinite(x) || !std::isfinite(y) || x == 0 || y == 0) continue;
    // Occupancy: a cost ratio, baseline waves / motor waves (fewer waves: dearer).
    c.ratios.push_back(measure == "occupancy" ? y / x : x / y);
    c.baselineSides.push_back(side);
  }
  judge(c);
  return c;
}

LadderCell cpuCell(const json& figures, const std::string& baseline) {
  LadderCell c{kStages[0], "CPU kernel", baseline, "measured"};
  c.paperScope = baseline == "paper";
  const std::string ratio = baseline == "paper" ? "shim_motor_over_shim_matrix" : "fastest_motor_over_fastest_matrix";
  for (const char* set : {"in_cache", "out_of_cache"}) {
    const std::string name = std::string("kernel_time.vertex_frame/") + set + "." + ratio;
    c.samples.push_back({name, ""});
    const double r = value(figures, name);
    if (std::isfinite(r)) c.ratios.push_back(r), c.baselineSides.push_back(baseline == "paper" ? "4x4 shader source" : "fastest");
  }
  judge(c);
  return c;
}

}  // namespace

std::vector<LadderCell> scopeLadder(const json& r) {
  const json figures = r.value("figures", json::object());
  std::vector<std::string> matrixFamily;
  const json familyOf = r.value("pipelineFamilies", json::object());
  for (const auto& [p, family] : familyOf.items())
    if (family == "matrix") matrixFamily.push_back(p);
  const std::vector<std::string> families = familiesOf(figures, "motor");
  std::vector<LadderCell> cells;
  for (const char* baseline : {"paper", "strongest"})
    for (const char* stage : kStages)
      for (const char* measure : kMeasures) {
        if (std::string(measure) == "CPU kernel") {
          if (stage == std::string(kStages[0])) cells.push_back(cpuCell(figures, baseline));
          continue;
        }
        if (pattern(stage, measure).empty()) continue;
        cells.push_back(opsCell(figures, stage, measure, baseline, matrixFamily, families));
      }
  return cells;
}

json ladderJson(const std::vector<LadderCell>& cells) {
  json out = json::array();
  auto number = [](double v) { return std::isfinite(v) ? json(v) : json(); };
  for (const LadderCell& c : cells) {
    json samples = json::array();
    for (const auto& [a, b] : c.samples) samples.push_back({{"motor", a}, {"baseline", b.empty() ? json() : json(b)}});
    out.push_back({{"stage", c.stage}, {"measure", c.measure}, {"baseline", c.baseline}, {"kind", c.kind},
                   {"paperScope", c.paperScope}, {"samples", samples}, {"ratios", c.ratios},
                   {"baselineSides", c.baselineSides}, {"worst", number(c.worst)}, {"best", number(c.best)},
                   {"n", c.ratios.size()}, {"verdict", c.verdict}, {"text", c.text}, {"limit", kAsCheapLimit}});
  }
  return out;
}

const LadderCell* ladderCell(const std::vector<LadderCell>& cells, const std::string& stage, const std::string& measure,
                             const std::string& baseline) {
  for (const LadderCell& c : cells)
    if (c.stage == stage && c.measure == measure && c.baseline == baseline) return &c;
  return nullptr;
}

void scopeLadderSection(Document& d, const std::vector<LadderCell>& cells) {
  d.heading(2, "Scope ladder: is the motor vertex as cheap as the matrix one?", "scope-ladder");
  d.paragraph("Each cell is motor / baseline (< 1: motor cheaper) with its range over the samples (ISA families, the "
              "CPU kernel's two working sets) and n, judged by the one rule every \"as cheap\" claim uses: as cheap when "
              "every sample is at most " + sig3(kAsCheapLimit) + "x, dearer when none is, split otherwise. The paper's "
              "sentence covers the transform to world against the 4x4 matrix (marked *); to clip adds the camera "
              "(the motor's camera sandwich and projection), and the whole shader adds main() and what only one side "
              "does there. Counted: the op-counting scalar; compiled: SPIR-V and RADV's null-device statistics (not "
              "timed); measured: the CPU kernels' Google Benchmark times. The strongest baseline is the cheapest "
              "matrix-family pipeline per sample (on the CPU the fastest matrix implementation, whatever its form).");
  std::vector<std::string> header = {"stage", "baseline"};
  for (const char* m : kMeasures) header.push_back(m);
  std::vector<std::vector<Cell>> rows;
  for (const char* baseline : {"paper", "strongest"})
    for (const char* stage : kStages) {
      std::vector<Cell> row = {{std::string(stage) + (stage == std::string(kStages[0]) && baseline == std::string("paper") ? " *" : "")},
                               {baseline == std::string("paper") ? "the paper's 4x4" : "strongest matrix form"}};
      for (const char* m : kMeasures) {
        const LadderCell* c = ladderCell(cells, stage, m, baseline);
        row.push_back({!c || c->verdict == "-" ? "-"
                                               : c->text + " " + c->verdict + " (n " + std::to_string(c->ratios.size()) + ")"});
      }
      rows.push_back(std::move(row));
    }
  d.table(header, rows);
}

}  // namespace mb::document
