// The claims as declared rows: what each states, on which scope, which figures it reads (by
// name) and the rule that turns them into a verdict. Nothing here measures or computes: the
// evaluator (evaluate.h) applies the rule to the figures of a run's JSON (figure_set.h).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::claims {

// What a row's figures cover. Every row states all three, so two rows that answer on different
// scopes say so in their own words.
struct Scope {
  std::string stage;     // "transform to world", "transform to clip", "whole vertex shader",
                         // "fragment stage", "operator", "CPU kernel", "CPU update", "frame",
                         // "vertex data", "scene data", "animation"
  std::string baseline;  // "the paper's 4x4", "the Sample Viewer's pipeline", "the strongest
                         // matrix form", "none"
  std::string content;   // "built-in scenes", "real corpus", "normal-mapped real content", ...
};

// One kind of evidence: the figure `value`, or the ratio value / `over`. A reference is
// "<source>:<figure name>" (figure_set.h lists the sources).
struct Evidence {
  std::string label;  // what it is, e.g. "counted ops"
  std::string value;
  std::string over;   // "" : the value itself
};

enum class RuleKind {
  // evidence[0].value names a prefix whose .mul/.add/.div/.sqrt/.other figures must equal
  // every column paperValue states.
  PaperColumns,
  // The same on evidence[0] (ours) or evidence[1] (the paper's printed listing): either is
  // enough (the paper's code costs what its table says).
  PaperColumnsOrListing,
  // As PaperColumns, but the paper defines no expansion behind its number: a difference is
  // inconclusive, not "differs".
  PaperColumnsUndefined,
  AtMost,      // every evidence <= limit
  AtLeast,     // every evidence >= limit
  Baseline,    // no verdict: the figures are printed
};

struct Rule {
  RuleKind kind = RuleKind::Baseline;
  double limit = 0;  // AtMost / AtLeast: the bound (1.10 for "motor / matrix within 10 %")
  int minN = 0;      // an evidence whose figure aggregates fewer samples carries no verdict
  // A frame time stands for a GPU only when a GPU measured it: one from a CPU rasterizer is
  // left out (it is printed, not judged).
  bool gpuTimed = false;
};

// How several kinds of evidence combine (printed with the verdict): every kind passes:
// reproduced; none passes: differs; some do: inconclusive. A kind without a figure, with a
// disturbed timing or with n < minN is left out and named; no kind left: not measurable.
struct ClaimRow {
  std::string id;
  std::string section;    // "Composition", "Speed", ...
  std::string statement;  // the claim in a few words
  std::string origin;     // "paper", or our kind: "baseline", "vs strongest", "beyond the paper", ...
  std::string quote;      // paper rows: the sentence or table row, with its section in brackets
  std::string tallyAs;    // rows the paper prints as one table entry share it ("" = the id)
  Scope scope;
  std::string paper;          // the paper's value as text ("48 mul, 40 add"; "-" for ours)
  nlohmann::json paperValue;  // and as data ({"mul": 48, "add": 40} for the column rules)
  std::vector<Evidence> evidence;
  Rule rule;
  std::string note;  // a caveat printed with the verdict ("" : none)
};

// The ISA families the isa room compiles for (its figures isa.<measure>.<variant>.<family>.<p>).
inline constexpr const char* kIsaFamilies[] = {"tahiti", "polaris10", "vega10", "navi10", "navi21-nonggc", "navi21-ngg",
                                               "gfx1100"};

// `a` / `b` of one figure family: "<prefix><a>" over "<prefix><b>", e.g.
// ratioOf("counted ops", "report:ops_per_vertex.rigid.counted.", "motor", "matrix").
inline Evidence ratioOf(std::string label, const std::string& prefix, const std::string& a, const std::string& b) {
  return {std::move(label), prefix + a, prefix + b};
}

// The declared table in print order, and its parts by family (claim_rows_*.cpp).
std::vector<ClaimRow> claimTable();
std::vector<ClaimRow> opRows();        // arithmetic of the kernels, baselines, composition
std::vector<ClaimRow> accuracyRows();  // handedness, blending, skin volume, drift, conversion
std::vector<ClaimRow> corpusRows();    // scale statistics and fallbacks over real files
std::vector<ClaimRow> memoryRows();    // bytes and floats per vertex, transform, joint
std::vector<ClaimRow> speedRows();     // as fast as matrices, the scope ladder's rows, CPU
std::vector<ClaimRow> compactRows();   // compact vertices, fragment rotor, morph, curved

}  // namespace mb::claims
