// One judged claim: a declared row (claim_table.h) with the evidence it read, its verdict and
// the words for both. evaluate.h fills it; claims_layout.h prints it.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::claims {

// Inconclusive: measured, but the evidence cannot decide (kinds of evidence disagree, or the
// paper does not define what its number counts).
enum class Verdict { Reproduced, Differs, NotMeasurable, Baseline, Inconclusive };

struct Claim {
  std::string id;         // stable key, e.g. "gp_mm", "floats_per_vertex"
  std::string section;    // "Composition", "Sandwich products", "Memory", ...
  std::string statement;  // the claim in a few words
  std::string paper;      // the paper's value as text ("48 mul, 40 add")
  nlohmann::json paperValue;     // and as data
  std::string measured;   // the evidence as read, as text
  nlohmann::json measuredValue;  // and as data ({label: value}; null when nothing was read)
  std::string method;     // the scope and the rule in words
  Verdict verdict = Verdict::NotMeasurable;
  std::string verdictText;  // "reproduced", "differs: +1 mul", ...
  std::string origin;       // "" : the paper's claim; else our kind ("baseline", "vs strongest", ...)
  std::string quote;        // the paper's sentence (or table row) the row tests; empty: ours
  std::string tallyAs;      // rows the paper prints as one table entry share it ("" = the id)
  // The declared row's scope, rule, evidence (references, figures and values) and note.
  nlohmann::json declared;
};

// "paper" or "own: <kind>".
std::string originOf(const Claim& c);

// "reproduced", "differs", "not measurable here", "baseline", "inconclusive"
std::string verdictName(Verdict v);

nlohmann::json toJson(const Claim& c);

}  // namespace mb::claims
