// The scope ladder of the headline question "is the motor vertex as cheap as the matrix one?":
// per stage (transform to world: the paper's scope; transform to clip; the whole vertex shader)
// and per measure (counted ops, SPIR-V probe, SPIR-V whole shader, ISA instructions, ACO's
// inverse throughput, VGPRs, occupancy, CPU kernel), motor / baseline for the paper's baseline
// (the 4x4 matrix pipeline; the shader sources on the CPU) and for the strongest matrix form
// measured (the cheapest matrix-family pipeline per sample; the fastest CPU implementation).
// Each cell is judged by one rule, the one every "as cheap" claim uses. Read from report.json's
// "figures" and "pipelineFamilies" only: report.md, claims.md, the answer block and the claims
// rows all read these cells.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

// "As cheap": motor / baseline at most this (the paper calls 89 vs 85 ops "nearly identical").
inline constexpr double kAsCheapLimit = 1.10;
// "Cheaper" or "a gain": motor / baseline at most this (beyond the same 10 % tolerance).
inline constexpr double kCheaperLimit = 0.90;

struct LadderCell {
  std::string stage, measure, baseline;  // baseline: "paper" or "strongest"
  std::string kind;                       // counted, compiled, measured
  bool paperScope = false;                // the stage and baseline the paper's sentence covers
  // motor figure / baseline figure per sample (a family, a working set); `ratio`: one figure
  // that is already motor / baseline (CPU kernels) — then `over` is empty.
  std::vector<std::pair<std::string, std::string>> samples;
  std::vector<double> ratios;   // of the samples that were measured (undisturbed)
  std::vector<std::string> baselineSides;  // the matrix side each ratio is against
  double worst = 0, best = 0;   // max and min of ratios (NaN: none)
  std::string verdict;          // "as cheap", "dearer", "split", "-" (not measured)
  std::string text;             // "1.05x", "1.05..1.09x"
};

std::vector<LadderCell> scopeLadder(const nlohmann::json& report);
nlohmann::json ladderJson(const std::vector<LadderCell>& cells);
// The cell of `stage`, `measure`, `baseline`, or nullptr.
const LadderCell* ladderCell(const std::vector<LadderCell>& cells, const std::string& stage,
                             const std::string& measure, const std::string& baseline);
// A table: rows stage x baseline, columns measures; the paper's scope marked; the rule under it.
void scopeLadderSection(Document& d, const std::vector<LadderCell>& cells);

}  // namespace mb::document
