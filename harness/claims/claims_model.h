// One quantitative claim of "Look, Ma, No Matrices!" (or a baseline a reviewer would ask for)
// with the paper's value, the value measured in this run, how it was measured and a verdict.
// Every measured value is filled in by code that ran the measurement (claims_*.cpp); nothing
// here holds a measured number.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shaders/shim/counted.h"

namespace mb::claims {

// Inconclusive: measured, but the evidence cannot decide (kinds of evidence disagree, or the
// paper does not define what its number counts).
enum class Verdict { Reproduced, Differs, NotMeasurable, Baseline, Inconclusive };

// "As fast" for a timed figure = within this fraction of the other side (or faster): run-to-run
// noise of both measurements on a shared 2-core machine is a few per cent. The speed verdict
// (claims_speed.cpp) and the timed "vs strongest" rows (claims_strongest.cpp) use it.
inline constexpr double kTimeTolerance = 0.10;

struct Claim {
  std::string id;         // stable key, e.g. "gp_mm", "floats_per_vertex"
  std::string section;    // "Composition", "Sandwich products", "Memory", ...
  std::string statement;  // the claim in a few words
  std::string paper;      // the paper's value as text ("48 mul, 40 add")
  nlohmann::json paperValue;     // and as data
  std::string measured;   // the measured value as text
  nlohmann::json measuredValue;  // and as data (null when not measurable)
  std::string method;     // how it was measured
  Verdict verdict = Verdict::NotMeasurable;
  std::string verdictText;  // "reproduced", "differs: +2 mul, +5 add (+10 %)", ...
  // "" : a claim the paper makes; else one of our own rows, by kind ("baseline", "vs strongest",
  // "curved"): counted apart from the paper's claims in the tally.
  std::string origin;
  // The paper's sentence (or table row) this row tests (claims_quotes.cpp); empty: ours.
  std::string quote;
  // Rows the paper prints as one table entry share a key and are tallied once ("" = the id).
  std::string tallyAs;
  // A declared row's scope, rule, evidence (references and values) and note (evaluate.h);
  // null for rows not yet declared.
  nlohmann::json declared;
};

// "paper" or "own: <kind>": the origin above, plus rows whose paper value says the paper does
// not claim it ("(not claimed ...") and reviewer baselines, which are ours wherever they appear.
std::string originOf(const Claim& c);

// "reproduced", "differs", "not measurable here", "baseline", "inconclusive"
std::string verdictName(Verdict v);

// One number through a printf format ("%.2fx", "%.3g"), for the measured and verdict texts.
std::string fmt(const char* f, double v);

// Op counts as data and text: {"mul", "add", "div", "sqrt", "other", "calls"}; "48 mul, 40 add
// + 1 div + 1 sqrt (acos)".
nlohmann::json opsJson(const OpCounts& c);
std::string opsText(const OpCounts& c);

// Verdict of measured op counts against the paper's mul/add (and, when the paper states them,
// div/sqrt/other): Reproduced when all stated columns agree, else Differs with the signed
// differences, e.g. "differs: +2 mul, +5 add (paper 21/5, measured 23/10)". Unstated columns
// that are non-zero are mentioned ("not stated by the paper: 1 sqrt, 1 div").
struct PaperOps {
  int mul = 0, add = 0;
  int div = -1, sqrt = -1, other = -1;  // -1: not stated
  std::string otherText;                // e.g. "1 acos" (for the text only)
};
void judgeOps(Claim& c, const PaperOps& paper, const OpCounts& measured);
nlohmann::json paperOpsJson(const PaperOps& p);

// Three sources where they differ: the paper's table `paper`, the paper's printed
// listing counted through the shim `listing`, and ours `measured`. Reproduced when ours equals
// the table, or when the printed listing does (the paper's code costs what its table says;
// ours then differs for the reason `oursWhy`); else Differs, saying whether the listing reaches
// the table. measuredValue = {"ours", "listing"}; the verdict text names every comparison.
void judgeOpsThree(Claim& c, const PaperOps& paper, const OpCounts& listing,
                   const OpCounts& measured, const std::string& oursWhy);
std::string paperOpsText(const PaperOps& p);

nlohmann::json toJson(const Claim& c);

}  // namespace mb::claims
