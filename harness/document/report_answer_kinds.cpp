#include "harness/document/report_answer_kinds.h"

#include <cmath>
#include <optional>

#include "harness/document/report_format.h"
#include "harness/document/report_kind_figures.h"
#include "harness/figures/figure.h"

namespace mb::document {
namespace {

using json = nlohmann::json;
using figures::Figure;

using KindQuote = FigureQuote;

bool isShare(const std::string& kind) { return kind != "all" && kind != "built_in"; }

// "normal-mapped [12 % of vertices, 10 % of primitives]", "all content [2.3e+04 vertices]".
std::string kindHead(KindQuote& q, KindAnswer& k) {
  if (!isShare(k.kind)) {
    k.shareVertices = k.sharePrimitives = std::nan("");
    const std::string label = k.kind == "built_in" ? "built-in scenes (controlled cases)" : k.label;
    return label + " [" + q.value("kind.vertices." + k.kind, 6) + ", " + q.value("kind.primitives." + k.kind, 6) + "]";
  }
  k.shareVertices = q.number("kind.share_vertices." + k.kind);
  k.sharePrimitives = q.number("kind.share_primitives." + k.kind);
  auto pct = [&](double v, const std::string& name) {
    return std::isfinite(v) ? figureMark(name, fmt(v, 3) + " %") : std::string("-");
  };
  return k.label + " [" + pct(k.shareVertices, "kind.share_vertices." + k.kind) + " of vertices, " +
         pct(k.sharePrimitives, "kind.share_primitives." + k.kind) + " of primitives]";
}

std::string bytesText(KindQuote& q, KindAnswer& k, const std::string& m, const std::string& M) {
  const std::string id = k.kind;
  const std::optional<Figure> r = q.get("kind.fetched_over_baseline." + id + "." + M);
  k.ratio = r ? r->value : std::nan("");
  return "fetched per vertex " + m + " " + q.value("kind.fetched_bytes_per_vertex." + id + "." + m) + ", " + M + " " +
         q.value("kind.fetched_bytes_per_vertex." + id + "." + M) + ", per frame " + M + " / " + m + " " +
         (r ? figureMark(r->name, figures::valueText(*r)) : std::string("-")) + "; uploaded per vertex " + m + " " +
         q.value("kind.uploaded_bytes_per_vertex." + id + "." + m) + ", " + M + " " +
         q.value("kind.uploaded_bytes_per_vertex." + id + "." + M) + ", per frame " + M + " / " + m + " " +
         q.value("kind.uploaded_over_baseline." + id + "." + M);
}

std::string opsText(KindQuote& q, KindAnswer& k, const std::string& m, const std::string& M) {
  const std::string id = k.kind;
  const double a = q.number("kind.ops_counted." + id + "." + m), b = q.number("kind.ops_counted." + id + "." + M);
  k.ratio = a > 0 ? b / a : std::nan("");
  q.line.figures.resize(q.line.figures.size() - 2);  // quoted again below, marked
  return "counted " + m + " " + q.value("kind.ops_counted." + id + "." + m) + ", " + M + " " +
         q.value("kind.ops_counted." + id + "." + M) + "; SPIR-V whole shader " + m + " " + q.value("kind.ops_spirv." + id + "." + m) +
         ", " + M + " " + q.value("kind.ops_spirv." + id + "." + M);
}

std::string isaText(KindQuote& q, KindAnswer& k, const std::string& m, const std::string& M) {
  std::string text;
  double sumM = 0, summ = 0;
  for (const json& fam : at(q.report, {"isa", "families"}).is_array() ? q.report["isa"]["families"] : json::array()) {
    const std::string id = fam.value("id", "");
    const std::string a = "kind.isa_instructions." + k.kind + "." + id + "." + m, b = "kind.isa_instructions." + k.kind + "." + id + "." + M;
    const double va = q.number(a), vb = q.number(b);
    if (!std::isfinite(va) || !std::isfinite(vb)) continue;
    summ += va, sumM += vb;
    text += (text.empty() ? "" : ", ") + id + " " + figureMark(b, fmt(vb, 3)) + "/" + figureMark(a, fmt(va, 3));
  }
  k.ratio = summ > 0 ? sumM / summ : std::nan("");
  return text.empty() ? "not measured" : M + "/" + m + " " + text;
}

std::string timeText(KindQuote& q, KindAnswer& k) {
  const std::optional<Figure> f = q.get("kind.frame_time." + k.kind);
  k.ratio = f ? f->value : std::nan("");
  if (!f) return "not measured";
  return "frame motor / matrix " + figureMark(f->name, figures::valueText(*f)) + " over " + std::to_string(f->n) + " scene(s)";
}

std::string imageText(KindQuote& q, KindAnswer& k, const std::string& M) {
  const std::optional<Figure> psnr = q.get("kind.image_worst_psnr." + k.kind + "." + M);
  const std::optional<Figure> same = q.get("kind.image_identical_frames." + k.kind + "." + M);
  k.ratio = std::nan("");
  if (!same || same->n == 0) return "no frame compared";
  return "worst PSNR " + (psnr ? figureMark(psnr->name, figures::valueText(*psnr)) : std::string("- (none differs)")) +
         ", " + figureMark(same->name, fmt(same->value, 6)) + " of " + std::to_string(same->n) + " frames identical";
}

std::string kindText(KindQuote& q, KindAnswer& k, const std::string& evidence, const std::string& m, const std::string& M) {
  if (evidence.rfind("bytes", 0) == 0) return bytesText(q, k, m, M);
  if (evidence.rfind("ops", 0) == 0) return opsText(q, k, m, M);
  if (evidence.rfind("AMD ISA", 0) == 0) return isaText(q, k, m, M);
  if (evidence.rfind("time", 0) == 0) return timeText(q, k);
  return imageText(q, k, M);
}

// "normal-mapped 40 %, skinned 60 %, ...": each kind of `l` the content draws, with its share of the
// drawn vertices (the headline names the kinds by label after it).
std::string sharesText(const AnswerLine& l) {
  std::string out;
  for (const KindAnswer& k : l.kinds)
    if (isShare(k.kind) && std::isfinite(k.shareVertices))
      out += (out.empty() ? "" : ", ") + k.label + " " + fmt(k.shareVertices, 3) + " %";
  return out;
}

const KindAnswer* kindOf(const AnswerLine& l, const std::string& id) {
  for (const KindAnswer& k : l.kinds)
    if (k.kind == id) return &k;
  return nullptr;
}

std::string sideOf(double ratio, const std::string& what) {
  return ratio < 1 ? "motor side cheaper: " + what : ratio > 1 ? "matrix side cheaper: " + what : "equal";
}

// The content-weighted verdict of the bytes, ops and ISA lines (the kinds each side wins are the headline's).
void kindsVerdictOf(AnswerLine& l) {
  const bool timeOrImage = l.evidence.rfind("time", 0) == 0 || l.evidence.rfind("image", 0) == 0;
  const KindAnswer* all = kindOf(l, "all");
  if (timeOrImage || !all || !std::isfinite(all->ratio)) return;
  const std::string what = l.evidence.rfind("bytes", 0) == 0 ? "fewer bytes fetched"
                           : l.evidence.rfind("ops", 0) == 0 ? "fewer arithmetic ops"
                                                              : "fewer ISA instructions";
  const std::string before = l.verdict;  // the rigid vertex's verdict on the scope ladder
  l.verdict = sideOf(all->ratio, what) + ", weighted by drawn vertices (by kind: above";
  if (const KindAnswer* b = kindOf(l, "built_in"); b && std::isfinite(b->ratio))
    l.verdict += "; built-in scenes: " + std::string(b->ratio < 1 ? "motor" : b->ratio > 1 ? "matrix" : "neither") +
                 " side cheaper";
  if (l.evidence.rfind("ops", 0) == 0) l.verdict += "; rigid vertex alone: " + before;
  if (l.evidence.rfind("AMD ISA", 0) == 0) l.verdict += "; rigid shader alone: " + before;
  l.verdict += ")";
}

}  // namespace

void addKindAnswers(std::vector<AnswerLine>& lines, const json& r, const std::string& m, const std::string& M) {
  const bool recorded = kindsRecorded(r);
  const bool builtIn = hasBuiltInBesideFiles(r);
  for (AnswerLine& l : lines) {
    if (!recorded) {
      l.text += "; by kind of content: not recorded in this report.json";
      continue;
    }
    KindQuote q{r, l};
    for (const ContentKindDef& def : contentKindDefs()) {
      if (def.id == "built_in" && !builtIn) continue;
      const std::optional<Figure> v = figures::figureNamed(r, "kind.vertices." + def.id);
      if (isShare(def.id) && !(v && v->value > 0)) continue;  // a kind the content does not draw
      KindAnswer k{def.id, def.label};
      k.head = kindHead(q, k);
      k.marked = kindText(q, k, l.evidence, m, M);
      k.text = withoutFigureMarks(k.marked);
      l.kinds.push_back(k);
    }
    kindsVerdictOf(l);
  }
}

void answerKindsTable(Document& d, const std::vector<AnswerLine>& lines, const json& r) {
  if (!kindsRecorded(r) || lines.empty() || lines[0].kinds.empty()) return;
  d.paragraph("The answer by kind of content (weighted by drawn vertices; ops and ISA by the shader variant each "
              "primitive draws with, the exact fallback included): each row a kind with its share of the content's "
              "drawn vertices and primitives, the built-in scenes as controlled cases.");
  std::vector<std::string> headers = {"kind of content"};
  for (const AnswerLine& l : lines) headers.push_back(l.evidence);
  std::vector<std::vector<Cell>> rows;
  for (size_t i = 0; i < lines[0].kinds.size(); ++i) {
    std::vector<Cell> row = {{lines[0].kinds[i].head}};
    for (const AnswerLine& l : lines) row.push_back({i < l.kinds.size() ? l.kinds[i].marked : "-"});
    rows.push_back(row);
  }
  d.table(headers, rows);
  d.blocks.back().anchor = "answer-kinds";
}

std::string answerHeadline(const std::vector<AnswerLine>& lines, const json& r) {
  if (!kindsRecorded(r)) return "";
  std::string out, shares;
  const std::pair<const char*, const char*> verbs[] = {{"bytes", "fetches %s bytes"}, {"ops", "runs %s arithmetic ops"},
                                                       {"AMD ISA", "compiles to %s ISA instructions"}};
  for (const auto& [evidence, verb] : verbs)
    for (const AnswerLine& l : lines) {
      if (l.evidence.rfind(evidence, 0) != 0 || l.kinds.empty()) continue;
      std::string fewer, more;
      for (const KindAnswer& k : l.kinds) {
        if (!isShare(k.kind) || !std::isfinite(k.ratio) || k.ratio == 1) continue;
        std::string& list = k.ratio < 1 ? fewer : more;
        list += (list.empty() ? "" : ", ") + k.label;
      }
      if (fewer.empty() && more.empty()) continue;
      auto with = [&](const char* word) {
        char buf[96];
        std::snprintf(buf, sizeof buf, verb, word);
        return std::string(buf);
      };
      if (shares.empty()) shares = sharesText(l);
      std::string clause = fewer.empty() ? "" : with("fewer") + " on " + fewer;
      if (!more.empty()) clause += (fewer.empty() ? with("more") : ", more") + " on " + more;
      if (const KindAnswer* b = kindOf(l, "built_in"); b && std::isfinite(b->ratio) && b->ratio != 1)
        clause += std::string(" (built-in scenes: ") + (b->ratio < 1 ? "fewer" : "more") + ")";
      out += (out.empty() ? "motor " : "; ") + clause;
    }
  if (out.empty()) return "";
  return "The content decides the verdict (drawn vertices: " + shares + "): " + out + ".";
}

}  // namespace mb::document
