// The answer block's lines by kind of content (report_kind_figures.h): each line's figures for
// the content as a whole, for each kind with its share of the drawn vertices and primitives,
// and for the built-in scenes as controlled cases; each quoted by name (figureMark). And the
// headline: which kinds the paper's claim holds for and which it does not.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/document/report_answer.h"

namespace mb::document {

// Gives each line (bytes, ops, ISA, time, image) its figures by kind (line.kinds: text and
// marked, the names quoted in line.figures), and gives the bytes, ops and ISA lines the verdict of
// the content as a whole (weighted by drawn vertices; the headline names each side's kinds).
// A report.json without the kinds: each line's text says they are not recorded.
void addKindAnswers(std::vector<AnswerLine>& lines, const nlohmann::json& report, const std::string& matrix,
                    const std::string& motor);

// The lines by kind as a table (id "answer-kinds"): a row per kind (its share), a column per line.
void answerKindsTable(Document& d, const std::vector<AnswerLine>& lines, const nlohmann::json& report);

// "motor fetches fewer bytes on normal-mapped (12 % of vertices), more on not normal-mapped
// (88 %); ..." over the evidence that has kinds; "" where the report recorded none.
std::string answerHeadline(const std::vector<AnswerLine>& lines, const nlohmann::json& report);

}  // namespace mb::document
