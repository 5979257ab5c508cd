#include "harness/document/report_answer.h"

#include <cmath>
#include <optional>

#include "harness/document/report_answer_figures.h"
#include "harness/document/report_answer_kinds.h"
#include "harness/document/report_format.h"
#include "harness/document/report_layout_common.h"
#include "harness/document/scope_ladder.h"
#include "harness/figures/figure.h"

namespace mb::document {

std::optional<figures::Figure> FigureQuote::get(const std::string& name) {
  line.figures.push_back(name);
  std::optional<figures::Figure> f = figures::figureNamed(report, name);
  return f && std::isfinite(f->value) ? f : std::nullopt;
}

std::string FigureQuote::value(const std::string& name, int digits) {
  const std::optional<figures::Figure> f = get(name);
  if (!f) return "-";
  return figureMark(name, digits == 3 ? figures::valueText(*f)
                                      : fmt(f->value, digits) + (f->unit.empty() ? "" : " " + f->unit));
}

double FigureQuote::number(const std::string& name) {
  const std::optional<figures::Figure> f = get(name);
  return f ? f->value : std::nan("");
}

namespace {

using namespace layout;
using figures::Figure;

using Quote = FigureQuote;

std::string marked(const Figure& f) { return figureMark(f.name, figures::valueText(f)); }

std::string spreadOf(const Figure& f) {
  if (!f.q1 || !f.q3) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, " [IQR %.3g..%.3g]", *f.q1, *f.q3);
  return buf;
}

// The headline pair: the baseline and "motor" (else the first motor-family pipeline).
std::pair<std::string, std::string> headline(const json& r) {
  const std::vector<std::string> pipes = pipelinesOf(r);
  std::string matrix = pipes.empty() ? "matrix" : pipes[0], motor;
  for (const std::string& p : pipes)
    if (p == "motor" || (motor.empty() && pipelineFamily(p) == "motor")) motor = p;
  return {matrix, motor.empty() ? "motor" : motor};
}

std::string cheaper(double ratio, const std::string& what) {
  if (!std::isfinite(ratio)) return "not measured";
  if (ratio < 1) return "motor side cheaper: " + what;
  if (ratio > 1) return "matrix side cheaper: " + what;
  return "equal";
}

AnswerLine bytesLine(const json& r, const std::string& m, const std::string& M) {
  AnswerLine l{"bytes per vertex and per frame fetched", "#gpu-evidence"};
  Quote q{r, l};
  const auto ratio = q.get("vertex_fetch.bytes_per_frame_over_baseline." + M);
  l.text = "fetched per vertex (GPU fetch model, not timed): " + m + " " + q.value("vertex_fetch.bytes_per_vertex." + m) +
           ", " + M + " " + q.value("vertex_fetch.bytes_per_vertex." + M) + "; per frame " + M + " / " + m + " " +
           (ratio ? marked(*ratio) + spreadOf(*ratio) + " over " + std::to_string(ratio->n) + " scene(s)" : "-") +
           "; uploaded per vertex: " + m + " " + q.value("bytes_per_vertex." + m) + ", " + M + " " +
           q.value("bytes_per_vertex." + M);
  l.verdict = cheaper(ratio ? ratio->value : std::nan(""), "it fetches fewer bytes");
  return l;
}

// "to world 1.05x as cheap": a ladder cell as the answer prints it, each figure quoted by name.
std::string cellText(Quote& q, const LadderCell* c) {
  if (!c || c->verdict == "-") return "-";
  q.line.cells.push_back({{"stage", c->stage}, {"measure", c->measure}, {"baseline", c->baseline}, {"text", c->text},
                          {"verdict", c->verdict}});
  for (const auto& [a, b] : c->samples) {
    q.get(a);
    if (!b.empty()) q.get(b);
  }
  return c->text + " " + c->verdict;
}

// The ops line reads the scope ladder's cells (the paper's baseline): the same numbers the
// claims judge, with the scope each answers named.
AnswerLine opsLine(const json& r, const std::vector<LadderCell>& ladder, const std::string& m, const std::string& M) {
  AnswerLine l{"ops counted and SPIR-V", "#scope-ladder"};
  Quote q{r, l};
  const std::string world = "transform to world", clip = "transform to clip";
  const LadderCell* wc = ladderCell(ladder, world, "counted ops", "paper");
  const LadderCell* cc = ladderCell(ladder, clip, "counted ops", "paper");
  l.text = "rigid vertex with frame, " + M + " / " + m + ": to world (the paper's scope) counted " +
           q.value("ops_per_vertex.rigid.counted." + M) + " / " + q.value("ops_per_vertex.rigid.counted." + m) + " " +
           cellText(q, wc) + ", SPIR-V probe " + cellText(q, ladderCell(ladder, world, "SPIR-V probe", "paper")) +
           "; to clip (the camera added) counted " + q.value("ops_per_vertex.to_clip.counted." + M) + " / " +
           q.value("ops_per_vertex.to_clip.counted." + m) + " " + cellText(q, cc) + ", SPIR-V probe " +
           cellText(q, ladderCell(ladder, clip, "SPIR-V probe", "paper"));
  if (!wc || wc->verdict == "-") l.verdict = "not counted";
  else l.verdict = "to world " + wc->verdict + ", to clip " + (cc ? cc->verdict : "-");
  return l;
}

AnswerLine isaLine(const json& r, const std::vector<LadderCell>& ladder, const std::string& m, const std::string& M) {
  AnswerLine l{"AMD ISA per family", "#scope-ladder"};
  Quote q{r, l};
  const std::string whole = "whole vertex shader";
  const LadderCell* ins = ladderCell(ladder, whole, "ISA instructions", "paper");
  const LadderCell* thr = ladderCell(ladder, whole, "ISA inverse throughput", "paper");
  const LadderCell* occ = ladderCell(ladder, whole, "occupancy", "paper");
  if (!ins || ins->verdict == "-") {
    const json& why = at(r, {"isa", "error"});  // --no-isa, or why the report's own run did not measure it
    l.text = why.is_string() ? why.get<std::string>()
                             : "not measured in this report (motorbench isa --json FILE, then report --isa-json FILE)";
    l.verdict = "not measured";
    return l;
  }
  l.text = "whole rigid vertex shader " + M + " / " + m + ", " + std::to_string(ins->ratios.size()) +
           " families (RADV null device, compiled, not timed): instructions " + cellText(q, ins) +
           "; ACO's inverse-throughput estimate " + cellText(q, thr) + "; occupancy cost " + cellText(q, occ);
  l.verdict = "instructions " + ins->verdict + ", throughput estimate " + (thr ? thr->verdict : "-");
  return l;
}

// "; motor drew with its exact fallback in 2 scenes of 7: 8 draws, 51 joints, 4000 vertices" (the
// fallback's cost is in the times), "; motor took no exact fallback (0 scenes)", or "" without the figures.
std::string fallbackClause(Quote& q, const std::string& M) {
  const auto scenes = q.get("fallback.scenes." + M);
  if (!scenes) return "";
  if (scenes->value == 0) return "; " + M + " took no exact fallback (" + marked(*scenes) + ")";
  return "; " + M + " drew with its exact fallback in " + marked(*scenes) + " of " + std::to_string(scenes->n) + ": " +
         q.value("fallback.draws." + M) + ", " + q.value("fallback.joints." + M) + ", " +
         q.value("fallback.vertices." + M) + " (the most in any frame; its cost is in these times)";
}

AnswerLine timeLine(const json& r, const std::string& M) {
  AnswerLine l{"time", "#scenes"};
  Quote q{r, l};
  const auto f = q.get("frame_time.motor_over_matrix");
  const json& gl = at(r, {"machine", "gl"});
  const bool cpu = gl.is_object() && !gl.value("realGpu", false);  // llvmpipe, softpipe
  l.text = "frame motor / matrix " + (f ? marked(*f) + spreadOf(*f) + " over " + std::to_string(f->n) + " scene(s)" : "-") +
           " on " + str(at(r, {"machine", "gl", "renderer"}), "an unnamed device") +
           (cpu ? " (a CPU rasterizer)" : "") + fallbackClause(q, M);
  // --frames 0 timed nothing: no verdict to give, whatever the device.
  const json& frames = at(r, {"settings", "frames"});
  if (frames.is_number() && frames.get<double>() == 0 && (!f || f->n == 0)) {
    l.text = "not measured (--frames 0: no frame was timed)";
    l.verdict = "not measured";
    l.figures.clear();
    return l;
  }
  if (cpu) l.verdict = "inconclusive: a CPU rasterizer cannot discriminate";
  else if (!f || !f->q1 || !f->q3) l.verdict = "not measured";
  else l.verdict = *f->q3 < 1 ? "motor side faster" : *f->q1 > 1 ? "matrix side faster" : "no difference beyond the spread";
  return l;
}

// The first frame the report could not judge, with its reason (summary.images.<p>.notJudged).
std::string firstNotJudged(const json& r, const std::string& p) {
  const json& list = at(r, {"summary", "images", p.c_str(), "notJudged"});
  return list.is_array() && !list.empty() && list[0].is_string() ? "first: " + list[0].get<std::string>()
                                                                 : "no reason recorded";
}

// A count figure, quoted (named in the line's figures) only when it is above 0, as the text
// prints it only then.
std::optional<Figure> countAboveZero(Quote& q, const std::string& name) {
  const std::optional<Figure> f = figures::figureNamed(q.report, name);
  return f && std::isfinite(f->value) && f->value > 0 ? q.get(name) : std::nullopt;
}

AnswerLine imageLine(const json& r, const std::string& m, const std::string& M) {
  AnswerLine l{"image cost (PSNR, FLIP)", "#scenes"};
  Quote q{r, l};
  const auto psnr = q.get("image.worst_psnr." + M);
  const auto same = q.get("image.identical_frames." + M);
  const auto own = countAboveZero(q, "image.skinned_frames_own_reference." + M);
  const auto notJudged = countAboveZero(q, "image.frames_not_judged." + M);
  const auto flip = q.get("image.flip_mean_worst." + M);
  l.text = M + " vs " + m + ", each frame against its own reference: worst PSNR " +
           (psnr ? marked(*psnr) : "- (none differs)") + ", " +
           (same ? fmt(same->value, 6) + " of " + std::to_string(same->n) : std::string("-")) + " frames identical" +
           (own ? " (of them " + marked(*own) + " skinned, against the motor-blend reference: " + M +
                      "'s own skinning method, not " + m + "'s)"
                : std::string()) +
           "; worst frame mean FLIP " + (flip ? figureMark(flip->name, fmt(flip->value, 3)) : std::string("not measured")) +
           (notJudged ? "; " + marked(*notJudged) + " not judged (" + firstNotJudged(r, M) + ")" : std::string());
  const std::string unjudged = notJudged ? figures::valueText(*notJudged) + " not judged" : "";
  if (!same || same->n == 0) l.verdict = notJudged ? "not judged (" + unjudged + ")" : "not compared";
  else if (!psnr || psnr->value >= 50) l.verdict = "equivalent (every differing frame >= 50 dB)";
  else l.verdict = "differs: worst " + figures::valueText(*psnr);
  if (notJudged && same && same->n > 0) l.verdict += "; " + unjudged;
  return l;
}

// A line's figures by kind, as claims.json carries them (null for a share or ratio not measured).
json kindsJson(const AnswerLine& l) {
  json out = json::array();
  auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  for (const KindAnswer& k : l.kinds)
    out.push_back({{"kind", k.kind}, {"label", k.label}, {"shareVertices", number(k.shareVertices)},
                   {"sharePrimitives", number(k.sharePrimitives)}, {"ratio", number(k.ratio)}, {"text", k.text}});
  return out;
}

// "dir/" of "dir/report.md" ("" for "" or "report.md").
std::string folderOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

}  // namespace

std::string answerQuestion() {
  return "\"Look, Ma, No Matrices!\" (SIGGRAPH 2024) asks: can PGA motors replace 4x4 matrices in a forward "
         "renderer's vertex stage with fewer bytes, no more arithmetic or time, and the same images?";
}

std::vector<AnswerLine> answerLines(const json& r) {
  const auto [m, M] = headline(r);
  const std::vector<LadderCell> ladder = scopeLadder(r);
  std::vector<AnswerLine> lines = {bytesLine(r, m, M), opsLine(r, ladder, m, M), isaLine(r, ladder, m, M), timeLine(r, M),
                                   imageLine(r, m, M)};
  addKindAnswers(lines, r, m, M);
  for (AnswerLine& l : lines) l.marked = l.text, l.text = withoutFigureMarks(l.text);
  return lines;
}

json answerJson(const json& r) {
  json lines = json::array();
  const std::vector<AnswerLine> all = answerLines(r);
  for (const AnswerLine& l : all)
    lines.push_back({{"evidence", l.evidence}, {"table", l.anchor}, {"text", l.text}, {"verdict", l.verdict},
                     {"figures", l.figures}, {"kinds", kindsJson(l)}, {"cells", l.cells}});
  return {{"question", answerQuestion()}, {"headline", answerHeadline(all, r)}, {"lines", lines}};
}

void answerSection(Document& d, const json& r, const std::string& reportPath) {
  d.heading(2, "The answer", "answer");
  d.paragraph(answerQuestion());
  const std::vector<AnswerLine> lines = answerLines(r);
  if (const std::string headline = answerHeadline(lines, r); !headline.empty()) {
    d.paragraph(headline);
    d.blocks.back().anchor = "answer-headline";
  }
  std::vector<std::vector<Cell>> rows;
  for (const AnswerLine& l : lines) rows.push_back({{l.evidence, "", reportPath + l.anchor}, {l.marked}, {l.verdict}});
  d.table({"evidence", "figures (report.json \"figures\")", "verdict"}, rows);
  d.blocks.back().anchor = "answer-table";
  for (const json& f : at(r, {"plots", "files"}).is_array() ? r["plots"]["files"] : json::array())
    if (f.value("name", "") == "design_space") {
      d.figure(folderOf(reportPath) + f.value("file", ""), f.value("title", ""), f.value("caption", ""));
      d.blocks.back().anchor = "design-space";
    }
  answerKindsTable(d, lines, r);
  scopeLadderSection(d, scopeLadder(r));
}

Document withAnswerFirst(const Document& doc, const json& report, const std::string& reportPath) {
  Document answer;
  answerSection(answer, report, reportPath);
  Document out = doc;
  out.blocks.insert(out.blocks.begin(), answer.blocks.begin(), answer.blocks.end());
  return out;
}

}  // namespace mb::document
