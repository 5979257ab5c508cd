// The answer block that opens report.md / report.html: the paper's question in one
// line, one line per kind of evidence (bytes, ops, AMD ISA, time, image cost) with its verdict
// and a link to its table, then the design-space figure. Every value is a figure of
// report.json's "figures", quoted by name (report_answer_figures.h, report_figures.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"
#include "harness/figures/figure.h"

namespace mb::document {

// One line's figures for one kind of content (report_answer_kinds.h).
struct KindAnswer {
  std::string kind, label;           // "normal_mapped", "normal-mapped"
  double shareVertices = 0, sharePrimitives = 0;  // % of the content's drawn ones; NaN: not a share
  double ratio = 0;                  // motor / matrix of the line's measure; NaN: not measured
  std::string head;                  // the kind with its share, marked ("normal-mapped [12 % of vertices, ...]")
  std::string text, marked;          // the figures as printed, and marked by name
};

struct AnswerLine {
  std::string evidence;              // "bytes", "ops", ...
  std::string anchor;                // the table it links to ("#gpu-evidence")
  std::string text;                  // the figures, as printed
  std::string marked;                // the same with each figure marked by name (figureMark)
  std::string verdict;
  std::vector<std::string> figures;  // the names of the figures the text quotes
  std::vector<KindAnswer> kinds;     // the line by kind of content (empty: not recorded)
  // The scope-ladder cells the line quotes ({"stage", "measure", "baseline", "text", "verdict"}).
  nlohmann::json cells = nlohmann::json::array();
};

// The figures a line quotes, each looked up by name and remembered in line.figures (the tests
// check every quoted name against report.json).
struct FigureQuote {
  const nlohmann::json& report;
  AnswerLine& line;
  // The figure, or nothing when it is missing or not finite.
  std::optional<figures::Figure> get(const std::string& name);
  // Its value with its unit, marked with its name (figureMark), or "-"; `digits` other than 3
  // prints that many significant digits.
  std::string value(const std::string& name, int digits = 3);
  // Its value, NaN when missing.
  double number(const std::string& name);
};

// "Look, Ma, No Matrices!" asks: ...
std::string answerQuestion();
std::vector<AnswerLine> answerLines(const nlohmann::json& report);
// {"question", "headline", "lines": [{"evidence", "table", "text", "verdict", "figures", "kinds": [{"kind",
// "label", "shareVertices", "sharePrimitives", "ratio", "text"}]}]}: the block in claims.json.
nlohmann::json answerJson(const nlohmann::json& report);
// Heading "The answer" (id "answer"), the question, the lines as a table (id "answer-table"),
// the design-space plot (id "design-space") when plot.py drew it. `reportPath`: where report.md
// lies from the document written ("" in report.md itself; "report.md" for claims.md beside it),
// put before each line's table link and the figure's folder.
void answerSection(Document& d, const nlohmann::json& report, const std::string& reportPath = "");
// `doc` with the answer block of `report` in front (claims.md: the same lines as report.md's).
Document withAnswerFirst(const Document& doc, const nlohmann::json& report, const std::string& reportPath);

}  // namespace mb::document
