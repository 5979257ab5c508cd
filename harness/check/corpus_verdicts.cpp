#include "harness/check/corpus_verdicts.h"

#include <cmath>

namespace mb::check {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// A threshold as the rule names print it: 50, 1, 0.5.
std::string bound(double v) { return printed("%g", v); }

// "rest 0.0 %, t=0.4 2.1 %": per frame of `file` the fraction in `diffs` as a percentage.
std::string perFrame(const ojson& file, const ojson& diffs) {
  std::string s;
  for (size_t i = 0; i < std::min(member(file, "frames", ojson::array()).size(), diffs.size()); ++i)
    s += (s.empty() ? "" : ", ") + frameName(file, i) + printed(" %.1f %%", 100 * numberOf(diffs[i]));
  return s;
}

struct Lines {
  std::vector<std::string> drawn, rigid, compact, skinned, rigidTies, compactTies, skinnedMethod;
  std::vector<std::pair<std::string, std::string>> omitted;
};

void rigidLines(Lines& out, const ojson& f, const ojson& r, const std::string& name, const RuleSet& set) {
  const ojson worst = member(r, "worstRigidPsnr");
  if (!set.isFullPrecision(r["pipeline"].get<std::string>()) || worst.is_null() || numberOf(worst) >= set.minPsnr) return;
  if (truthy(member(r, "rigidFailFrames", 1))) {
    const ojson notTies = member(r, "worstRigidPsnrNotTies");
    out.rigid.push_back(name + printed(": %.2f dB", numberOf(worst)) +
                        (notTies.is_null() ? "" : ", " + psnrText(notTies) + " dB outside the tie pixels"));
    return;
  }
  for (const ojson& t : r["rigidTieFrames"])
    out.rigidTies.push_back(name + " " + frameName(f, t["frame"].get<size_t>()) + printed(": %.2f dB; ", numberOf(t["psnr"])) +
                            psnrText(t["psnrNotTies"]) + " dB outside the " + valueText(t["tiePixels"]) + " tie pixels (" +
                            valueText(t["differingPixels"]) + " px differ, " + valueText(t["differingNotTies"]) +
                            " of them not ties)");
}

void compactLines(Lines& out, const ojson& f, const ojson& r, const std::string& name, const ojson& byName,
                  const RuleSet& set) {
  const std::string pipeline = r["pipeline"].get<std::string>();
  const ojson outside = member(r, "outsideEnvelope"), notTies = member(r, "outsideEnvelopeNotTies");
  if (!set.isCompact(pipeline) || !truthy(outside)) return;
  if (!truthy(notTies)) {
    for (const ojson& t : r["compactTieFrames"])
      out.compactTies.push_back(name + " " + frameName(f, t["frame"].get<size_t>()) + ": " + valueText(t["outsideEnvelope"]) +
                                " px outside the envelope, every one of them an int16-cell tie pixel (" +
                                valueText(t["tiePixels"]) + " in the frame)");
    return;
  }
  std::string line = name + ": " + valueText(outside) + " px outside the envelope";
  if (!notTies.is_null() && notTies != outside) line += " (" + valueText(notTies) + " not tie pixels)";
  line += ", by up to " + valueText(member(r, "envelopeExcess")) + "/255 (bound " +
          printed("%.2g", numberOf(member(f, "boundPixels", 0.0))) + " px, radius " + valueText(member(f, "envelopeRadius")) +
          "; PSNR " + psnrText(member(r, "worstRigidPsnr"));
  if (pipeline != "matrix_c" && byName.contains("matrix_c"))
    line += "; matrix_c, the same positions through matrix math: " +
            valueText(member(byName["matrix_c"], "outsideEnvelope", 0)) + " px";
  out.compact.push_back(line + ")");
}

void skinnedLines(Lines& out, const ojson& f, const ojson& r, const std::string& name, const RuleSet& set) {
  const ojson own = member(r, "worstSkinnedReferenceDrawnDiff"), vsMatrix = member(r, "worstSkinnedDrawnDiff");
  if (!own.is_null() && numberOf(own) > set.maxDrawnDiff) {
    out.skinned.push_back(name + ": drawn pixels apart from " + r["skinReference"].get<std::string>() + " by " +
                          perFrame(f, r["referenceDrawnDiff"]));
  } else if (!vsMatrix.is_null() && numberOf(vsMatrix) > set.maxDrawnDiff) {
    const ojson psnr = member(r, "worstSkinnedPsnrReference");
    out.skinnedMethod.push_back(name + ": " + perFrame(f, r["drawnDiff"]) + " apart from matrix; from its own method's reference " +
                                perFrame(f, r["referenceDrawnDiff"]) + (psnr.is_null() ? "" : ", " + psnrText(psnr) + " dB"));
  }
}

void rowLines(Lines& out, const ojson& f, const ojson& r, const ojson& byName, const RuleSet& set) {
  const std::string pipeline = r["pipeline"].get<std::string>();
  const std::string name = f["file"].get<std::string>() + " [" + pipeline + "]";
  if (!truthy(r["drawn"]))
    out.drawn.push_back(name + ": " + (truthy(member(r, "error")) ? r["error"].get<std::string>()
                                                                   : "drawn pixels " + valueText(r["drawnPixels"])));
  rigidLines(out, f, r, name, set);
  compactLines(out, f, r, name, byName, set);
  for (const ojson& o : member(r, "omittedFrames", ojson::array()))
    out.omitted.emplace_back("counted omission: " + pipeline + " does not morph",
                             name + " " + frameName(f, o["frame"].get<size_t>()) + ": " + valueText(o["nodes"]) +
                                 " morphed node(s) drawn in their base shape" +
                                 (o["psnr"].is_null() ? "" : ", " + psnrText(o["psnr"]) + " dB against matrix"));
  skinnedLines(out, f, r, name, set);
}

bool crashedFile(const ojson& f) { return f["status"] == "crashed" || f["status"] == "worker-error"; }

}  // namespace

bool Verdicts::pass() const {
  for (const Rule& r : rules)
    if (!r.pass()) return false;
  return true;
}

Verdicts evaluate(const std::vector<ojson>& files, const RuleSet& set) {
  std::vector<std::string> crashed, load;
  for (const ojson& f : files)
    if (crashedFile(f)) crashed.push_back(f["file"].get<std::string>() + ": " + valueText(f["error"]));
  for (const ojson& f : files)
    for (const ojson& r : f["rows"])
      if (r["status"] == "crashed")
        crashed.push_back(f["file"].get<std::string>() + " [" + r["pipeline"].get<std::string>() + "]: " + valueText(r["signal"]));
  for (const ojson& f : files)
    if (f["status"] == "load-failed") load.push_back(f["file"].get<std::string>() + ": " + valueText(f["error"]));
  Lines lines;
  for (const ojson& f : files) {
    ojson byName = ojson::object();
    for (const ojson& r : f["rows"]) byName[r["pipeline"].get<std::string>()] = r;
    for (const ojson& r : f["rows"])
      if (r["status"] != "crashed") rowLines(lines, f, r, byName, set);
  }
  Verdicts v;
  v.rules = {{"0 crashes, signals or timeouts", crashed, {}},
             {"every file loads (files without data excepted)", load, {}},
             {"every drawable file drawn by every pipeline", lines.drawn, {}},
             {"rigid frames of " + joined(set.fullPrecision) + " vs matrix >= " + bound(set.minPsnr) +
                  " dB or identical (outside the tie pixels)",
              lines.rigid, lines.rigidTies},
             {"rigid frames of " + joined(set.compact) +
                  " within their position bound (geometry view, envelope; int16-cell tie pixels excepted)",
              lines.compact, lines.compactTies},
             {"skinned frames: drawn pixels within " + bound(100 * set.maxDrawnDiff) +
                  " % of their skinning method's reference (matrix; for " + joined(set.motorBlend) +
                  " the motor blend by GLM dual quaternions, drawn by matrix)",
              lines.skinned, lines.skinnedMethod, true}};
  v.countedName = "frames judged by no image rule: a feature the pipeline counts as not drawn";
  v.counted = lines.omitted;
  return v;
}

std::vector<std::string> ruleLines(const Verdicts& v, const RuleSet& set) {
  std::vector<std::string> out;
  for (const Rule& r : v.rules) {
    std::string head = std::string("- ") + (r.pass() ? "PASS" : "FAIL") + ": " + r.name;
    if (!r.pass()) head += " (" + std::to_string(r.failures.size()) + ")";
    if (!r.passedMarked.empty())
      head += r.skinned ? " (" + std::to_string(r.passedMarked.size()) + " more than " + bound(100 * set.maxDrawnDiff) +
                              " % from matrix's linear blend)"
                        : " (" + std::to_string(r.passedMarked.size()) + " frames pass on ties)";
    out.push_back(head);
    for (const std::string& line : r.failures) out.push_back("  - " + line);
    const char* mark = r.skinned ? "the skinning method differs from matrix's" : "ties: undetermined by the transform";
    for (const std::string& line : r.passedMarked) out.push_back(std::string("  - PASS (") + mark + "): " + line);
  }
  out.push_back("- COUNTED: " + v.countedName + " (" + std::to_string(v.counted.size()) + ")");
  for (const auto& [mark, line] : v.counted) out.push_back("  - " + mark + ": " + line);
  return out;
}

const std::vector<std::string>& fallbackCounters() {
  static const std::vector<std::string> names = {
      "linearFallbackDraws", "skinFallbackDraws", "skinFallbackJoints", "fallbackVertices", "nonUniformScaleNodes",
      "negativeScaleNodes", "shearMatrixNodes", "scaleFallbackInstances", "zeroScalarFrames", "biasedFrames",
      "rotorSplitVertices", "rotorUnresolvedTriangles", "morphNotDrawnNodes"};
  return names;
}

ojson totals(const std::vector<ojson>& files, const std::vector<std::string>& pipelines, const RuleSet& set) {
  ojson per = ojson::object();
  for (const std::string& name : pipelines) {
    std::vector<std::pair<const ojson*, const ojson*>> rows;  // (file, row)
    for (const ojson& f : files)
      for (const ojson& r : f["rows"])
        if (r["pipeline"] == name) rows.emplace_back(&f, &r);
    ojson worst = nullptr, worstFile = nullptr;
    int64_t drawn = 0, errors = 0, below = 0, over = 0, overOwn = 0, outside = 0, outsideNotTies = 0, failing = 0;
    int64_t rigidTies = 0, compactTies = 0;
    double seconds = 0;
    for (const auto& [f, r] : rows) {
      const ojson psnr = member(*r, "worstRigidPsnr");
      if (!psnr.is_null()) {
        if (worst.is_null() || numberOf(psnr) < numberOf(worst)) worst = psnr, worstFile = (*f)["file"];
        if (numberOf(psnr) < set.minPsnr) ++below;
      }
      drawn += truthy(member(*r, "drawn"));
      errors += (*r)["status"] == "error" || (*r)["status"] == "crashed";
      over += numberOf(member(*r, "worstSkinnedDrawnDiff", 0)) > set.maxDrawnDiff;
      overOwn += numberOf(member(*r, "worstSkinnedReferenceDrawnDiff", 0)) > set.maxDrawnDiff;
      outside += truthy(member(*r, "outsideEnvelope"));
      outsideNotTies += truthy(member(*r, "outsideEnvelopeNotTies"));
      failing += truthy(member(*r, "rigidFailFrames"));
      rigidTies += int64_t(member(*r, "rigidTieFrames", ojson::array()).size());
      if (!truthy(member(*r, "outsideEnvelopeNotTies")))
        compactTies += int64_t(member(*r, "compactTieFrames", ojson::array()).size());
      seconds += numberOf(member(*r, "seconds", 0));
    }
    ojson fallbacks = ojson::object();
    for (const std::string& key : fallbackCounters()) {
      ojson total = 0;
      int64_t with = 0;
      for (const auto& [f, r] : rows) {
        const ojson v = member(member(*r, "fallbacks", ojson::object()), key.c_str(), 0);
        total = total.is_number_integer() && v.is_number_integer() ? ojson(total.get<int64_t>() + v.get<int64_t>())
                                                                   : ojson(numberOf(total) + numberOf(v));
        with += truthy(v);
      }
      fallbacks[key] = {{"total", total}, {"files", with}};
    }
    per[name] = {{"rows", rows.size()},
                 {"drawn", drawn},
                 {"errors", errors},
                 {"worstRigidPsnr", worst},
                 {"worstRigidFile", worstFile},
                 {"worstRigidIdentical", !worst.is_null() && numberOf(worst) == kIdentical},
                 {"rigidFilesBelow50dB", below},
                 {"skinnedFilesOver1Percent", over},
                 {"skinnedFilesOver1PercentOfReference", overOwn},
                 {"compactFilesOutsideEnvelope", outside},
                 {"compactFilesOutsideEnvelopeNotTies", outsideNotTies},
                 {"rigidFilesFailing", failing},
                 {"rigidTieFrames", set.isFullPrecision(name) ? rigidTies : 0},
                 {"compactTieFrames", set.isCompact(name) ? compactTies : 0},
                 {"fallbacks", fallbacks},
                 {"seconds", std::round(seconds * 10) / 10}};
  }
  return per;
}

}  // namespace mb::check
