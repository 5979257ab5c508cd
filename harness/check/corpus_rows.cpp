#include "harness/check/corpus_rows.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "harness/render/drawn_check.h"
#include "harness/render/skin_judgement.h"
#include "pipelines/pipeline.h"
#include "pipelines/registry.h"
#include "pipelines/skin_method.h"

namespace mb::check {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// An object member that may be absent or null, read as an object ({} then).
ojson objectAt(const ojson& j, const char* key) {
  ojson v = member(j, key);
  return v.is_object() ? v : ojson::object();
}

// A frame's PSNR against the baseline: +inf when identical, null when not compared.
ojson psnrOf(const ojson& frame) {
  if (truthy(member(frame, "identical"))) return kIdentical;
  return member(frame, "psnr");
}

// The smallest / largest of `values` (the first one on ties), null when empty.
ojson minOf(const std::vector<ojson>& values) {
  ojson best = nullptr;
  for (const ojson& v : values)
    if (best.is_null() || v.get<double>() < best.get<double>()) best = v;
  return best;
}
ojson maxOf(const std::vector<ojson>& values) {
  ojson best = nullptr;
  for (const ojson& v : values)
    if (best.is_null() || v.get<double>() > best.get<double>()) best = v;
  return best;
}

// Drawn-pixel counts as the fraction they are apart (drawn_check.h's measure).
double apartFraction(const ojson& a, const ojson& b) {
  const int64_t da = a.get<int64_t>(), db = b.get<int64_t>();
  return checkDrawn("a", da, "b", db, false, false).apartPercent / 100.0;
}

// One rigid frame of a full-precision pipeline against matrix: "pass" when its PSNR reaches the
// bound or it is identical; "ties" when below, but at the bound (or identical) once the frame's
// tie pixels (those matrix itself draws differently when the vertex positions are jittered: not
// determined by the transform) count as equal; "fail" when the pixels outside the ties alone stay
// below it (or the survey gave no tie data).
ojson judgeRigidFrame(const ojson& frame, const ojson& tiePixels, const RuleSet& set) {
  const ojson psnr = psnrOf(frame);
  ojson out = {{"psnr", psnr},
               {"tiePixels", tiePixels},
               {"differingPixels", member(frame, "differingPixels")},
               {"differingNotTies", member(frame, "differingNotTies")},
               {"psnrNotTies", truthy(member(frame, "identicalNotTies")) ? ojson(kIdentical) : member(frame, "psnrNotTies")}};
  if (!psnr.is_null() && psnr.get<double>() >= set.minPsnr) {
    out["verdict"] = "pass";
    if (out["psnrNotTies"].is_null()) out["psnrNotTies"] = psnr;
  } else if (!out["psnrNotTies"].is_null() && out["psnrNotTies"].get<double>() >= set.minPsnr) {
    out["verdict"] = "ties";
  } else {
    out["verdict"] = "fail";
    if (out["psnrNotTies"].is_null()) out["psnrNotTies"] = psnr;
  }
  return out;
}

std::vector<ojson> drawnOf(const ojson& frames) {
  std::vector<ojson> out;
  for (const ojson& f : frames) out.push_back(f.at("drawnPixels"));
  return out;
}

// The per-frame fractions `drawn` lies apart from `reference` (as many as the shorter list).
ojson apartList(const std::vector<ojson>& drawn, const std::vector<ojson>& reference) {
  ojson out = ojson::array();
  for (size_t i = 0; i < std::min(drawn.size(), reference.size()); ++i) out.push_back(apartFraction(drawn[i], reference[i]));
  return out;
}

// Values of `list` at the frames whose kind is `kind`.
std::vector<ojson> ofKind(const ojson& list, const std::vector<std::string>& kinds, const char* kind) {
  std::vector<ojson> out;
  for (size_t i = 0; i < std::min(list.size(), kinds.size()); ++i)
    if (kinds[i] == kind) out.push_back(list[i]);
  return out;
}

// The skinned rule's reference: the motor blend's CPU reference for the motor-blend pipelines
// when the survey could make it (else matrix, the strict reading), matrix for the others.
void skinReference(ojson& row, const std::string& name, const ojson& doc, const ojson& frames,
                   const std::vector<std::string>& kinds, const std::vector<ojson>& drawn) {
  const ojson reference = objectAt(doc, "motorBlendReference");
  std::vector<ojson> refDrawn;
  bool everyFrame = true;
  for (const ojson& fr : doc.at("frames")) {
    refDrawn.push_back(member(objectAt(fr, "motorBlendReference"), "drawnPixels"));
    everyFrame = everyFrame && !refDrawn.back().is_null();
  }
  const bool ownIsMotorBlend = std::string(skinReferenceOf(name)) == kMotorBlendReference;
  if (ownIsMotorBlend && truthy(member(reference, "available")) && everyFrame) {
    row["skinReference"] = "motor blend (GLM dual quaternions, drawn by matrix)";
    row["referenceDrawnDiff"] = apartList(drawn, refDrawn);
    std::vector<ojson> psnrs;
    for (size_t i = 0; i < std::min(frames.size(), kinds.size()); ++i) {
      if (kinds[i] != "skinned") continue;
      const ojson blend = objectAt(frames[i], "motorBlend");
      const ojson p = truthy(member(blend, "identical")) ? ojson(kIdentical) : member(blend, "psnr");
      if (!p.is_null()) psnrs.push_back(p);
    }
    row["worstSkinnedPsnrReference"] = minOf(psnrs);
  } else {
    const bool unavailable = ownIsMotorBlend && !ofKind(row["drawnDiff"], kinds, "skinned").empty();
    const ojson why = member(reference, "why", "not stated");
    row["skinReference"] = std::string("matrix") +
                           (unavailable ? " (motor blend reference unavailable: " + valueText(why) + ")" : "");
    row["referenceDrawnDiff"] = row["drawnDiff"];
  }
  row["worstSkinnedReferenceDrawnDiff"] = maxOf(ofKind(row["referenceDrawnDiff"], kinds, "skinned"));
}

// The 16-byte rule's figures, judged by survey in the geometry view (positions and uv alone),
// outside the int16-cell ties (pixels matrix draws differently with its positions moved within
// their int16 cells; surveys without tie data: every pixel counts).
void envelopeFigures(ojson& row, const ojson& doc, const ojson& frames, const std::vector<std::string>& kinds) {
  std::vector<ojson> outside, outsideNotTies, excess;
  ojson tieFrames = ojson::array();
  const ojson& docFrames = doc.at("frames");
  for (size_t i = 0; i < std::min(frames.size(), kinds.size()); ++i) {
    const ojson& f = frames[i];
    if (kinds[i] != "rigid") continue;
    if (f.contains("outsideEnvelope")) {
      outside.push_back(f["outsideEnvelope"]);
      outsideNotTies.push_back(f.contains("outsideEnvelopeNotTies") ? f["outsideEnvelopeNotTies"] : f["outsideEnvelope"]);
    }
    if (f.contains("envelopeExcess")) excess.push_back(f["envelopeExcess"]);
    const ojson notTies = member(f, "outsideEnvelopeNotTies");
    if (truthy(member(f, "outsideEnvelope")) && notTies.is_number() && notTies.get<double>() == 0) {
      const ojson ties = i < docFrames.size() ? member(objectAt(docFrames[i], "int16Ties"), "pixels") : ojson(nullptr);
      tieFrames.push_back({{"frame", i}, {"outsideEnvelope", f["outsideEnvelope"]}, {"tiePixels", ties}});
    }
  }
  row["outsideEnvelope"] = maxOf(outside);
  row["outsideEnvelopeNotTies"] = maxOf(outsideNotTies);
  row["compactTieFrames"] = tieFrames;
  row["envelopeExcess"] = maxOf(excess);
}

// The rigid rule's figures: the worst PSNR, and each frame judged outside its tie pixels.
void rigidFigures(ojson& row, const ojson& doc, const ojson& frames, const std::vector<std::string>& kinds,
                  const RuleSet& set) {
  std::vector<ojson> rigid;
  for (size_t i = 0; i < std::min(frames.size(), kinds.size()); ++i)
    if (kinds[i] == "rigid" && !psnrOf(frames[i]).is_null()) rigid.push_back(psnrOf(frames[i]));
  row["worstRigidPsnr"] = minOf(rigid);
  row["rigidIdentical"] = !rigid.empty() && row["worstRigidPsnr"].get<double>() == kIdentical;
  ojson ties = ojson::array();
  for (const ojson& f : doc.at("frames")) ties.push_back(member(objectAt(f, "ties"), "pixels"));
  row["tiePixels"] = ties;
  ojson tieFrames = ojson::array();
  int failing = 0;
  std::vector<ojson> notTies;
  for (size_t i = 0; i < std::min({frames.size(), kinds.size(), ties.size()}); ++i) {
    if (kinds[i] != "rigid" || psnrOf(frames[i]).is_null()) continue;
    ojson j = judgeRigidFrame(frames[i], ties[i], set);
    j["frame"] = i;
    notTies.push_back(j["psnrNotTies"]);
    if (j["verdict"] == "ties") tieFrames.push_back(j);
    if (j["verdict"] == "fail") ++failing;
  }
  row["rigidTieFrames"] = tieFrames;
  row["rigidFailFrames"] = failing;
  row["worstRigidPsnrNotTies"] = minOf(notTies);
}

// Each frame's figures for the per-frame verdicts (corpus_junit.h): kind, drawn pixels and the
// baseline's, PSNR, the rigid judgement outside the ties, the envelope counts, the distance from
// its skinning method's reference. Kept in memory only (checkDocument leaves it out).
ojson perFrameFigures(const ojson& row, const ojson& doc, const ojson& frames, const std::vector<std::string>& kinds,
                      const RuleSet& set) {
  ojson out = ojson::array();
  const ojson& base = doc.at("pipelines").at(doc.at("baseline").get<std::string>()).at("frames");
  for (size_t i = 0; i < std::min(frames.size(), kinds.size()); ++i) {
    const ojson& f = frames[i];
    const ojson ties = row["tiePixels"].size() > i ? row["tiePixels"][i] : ojson(nullptr);
    out.push_back({{"kind", kinds[i]},
                   {"drawn", f.at("drawnPixels")},
                   {"baseDrawn", i < base.size() ? base[i].at("drawnPixels") : ojson(nullptr)},
                   {"rigid", psnrOf(f).is_null() ? ojson(nullptr) : judgeRigidFrame(f, ties, set)},
                   {"outsideEnvelope", member(f, "outsideEnvelope")},
                   {"outsideEnvelopeNotTies", member(f, "outsideEnvelopeNotTies", member(f, "outsideEnvelope"))},
                   {"referenceDiff", row["referenceDrawnDiff"].size() > i ? row["referenceDrawnDiff"][i] : ojson(nullptr)},
                   {"morphNotDrawnNodes", member(member(f, "fallbacks", ojson::object()), "morphNotDrawnNodes", 0)}});
  }
  return out;
}

// The row of one file x pipeline from its survey document.
ojson pipelineRow(const std::string& rel, const std::string& name, const ojson& doc, const WorkerRecord& rec,
                  std::vector<std::string> kinds, const std::vector<ojson>& bounds, const RuleSet& set) {
  const ojson& p = doc.at("pipelines").at(name);
  const ojson& base = doc.at("pipelines").at(doc.at("baseline").get<std::string>()).at("frames");
  const ojson& frames = p.at("frames");
  // Frames where this pipeline drew morphed nodes in their base shape (a counted omission,
  // PipelineStats::morphNotDrawnNodes) are judged by no image rule: listed apart.
  ojson omissions = ojson::array();
  for (size_t i = 0; i < std::min(frames.size(), kinds.size()); ++i) {
    const ojson nodes = member(objectAt(frames[i], "fallbacks"), "morphNotDrawnNodes", 0);
    if (!truthy(nodes)) continue;
    omissions.push_back({{"frame", i}, {"kind", kinds[i]}, {"nodes", nodes}, {"psnr", psnrOf(frames[i])}});
    kinds[i] = "omitted";
  }
  const std::vector<ojson> drawn = drawnOf(frames), baseDrawn = drawnOf(base);
  ojson row = {{"file", rel},
               {"pipeline", name},
               {"exit", rec.exit},
               {"signal", rec.signal},
               {"status", "ok"},
               {"error", member(p, "error")},
               {"seconds", std::round(member(p, "seconds", 0.0).get<double>() * 1000) / 1000},
               {"drawnPixels", ojson(drawn)},
               {"kind", kinds.empty() ? ojson(nullptr) : ojson(doc.at("frames")[0].at("kind"))},
               {"fallbacks", member(p, "fallbacks", ojson::object())},
               {"omittedFrames", omissions}};
  if (truthy(row["error"])) row["status"] = "error";
  // Drawn: some pixel in every frame where the baseline drew some, and in one frame at least.
  bool any = false, everyFrame = true;
  for (size_t i = 0; i < drawn.size(); ++i) {
    any = any || drawn[i].get<int64_t>() > 0;
    if (i < baseDrawn.size()) everyFrame = everyFrame && (drawn[i].get<int64_t>() > 0 || baseDrawn[i].get<int64_t>() == 0);
  }
  row["drawn"] = !truthy(row["error"]) && any && everyFrame;
  rigidFigures(row, doc, frames, kinds, set);
  row["drawnDiff"] = apartList(drawn, baseDrawn);
  row["worstSkinnedDrawnDiff"] = maxOf(ofKind(row["drawnDiff"], kinds, "skinned"));
  skinReference(row, name, doc, frames, kinds, drawn);
  envelopeFigures(row, doc, frames, kinds);
  row["boundPixels"] = maxOf(bounds);
  row["perFrame"] = perFrameFigures(row, doc, frames, kinds, set);
  return row;
}

}  // namespace

ojson member(const ojson& j, const char* key, const ojson& fallback) {
  if (!j.is_object()) return fallback;
  auto it = j.find(key);
  return it == j.end() || it->is_null() ? fallback : *it;
}

bool truthy(const ojson& v) {
  if (v.is_null()) return false;
  if (v.is_boolean()) return v.get<bool>();
  if (v.is_number()) return v.get<double>() != 0;
  if (v.is_string()) return !v.get<std::string>().empty();
  return !v.empty();
}

std::string printed(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

bool RuleSet::isFullPrecision(const std::string& p) const { return contains(fullPrecision, p); }
bool RuleSet::isCompact(const std::string& p) const { return contains(compact, p); }
bool RuleSet::blendsMotors(const std::string& p) const { return contains(motorBlend, p); }


RuleSet defaultRuleSet(const std::vector<std::string>& only) {
  RuleSet set;
  set.pipelines = only;
  const std::vector<std::string> all = pipelineNames(Space::Euclidean);
  for (const std::string& p : all) {
    if (!only.empty() && !contains(only, p)) continue;
    if (skinMethodOf(p) == SkinMethod::MotorBlend) set.motorBlend.push_back(p);
    if (p == all.front()) continue;  // the baseline
    (hasSixteenByteVertex(p) ? set.compact : set.fullPrecision).push_back(p);
  }
  return set;
}

std::string frameName(const ojson& file, size_t index) {
  const ojson frames = member(file, "frames", ojson::array());
  if (index >= frames.size() || member(frames[index], "animation").is_null()) return "rest";
  return printed("t=%.3g", frames[index].at("time").get<double>());
}

std::string psnrText(const ojson& psnr) {
  if (psnr.is_null()) return "-";
  if (psnr.get<double>() == kIdentical) return "identical";
  return printed("%.1f", psnr.get<double>());
}

std::string valueText(const ojson& v) {
  if (v.is_null()) return "None";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "True" : "False";
  if (v.is_array()) {
    std::string s = "[";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + valueText(v[i]);
    return s + "]";
  }
  return v.dump();
}

ojson fileResult(const std::string& rel, const WorkerRecord& rec, const std::string& features, const RuleSet& set) {
  const ojson& doc = rec.doc;
  ojson res = {{"file", rel},
               {"features", features},
               {"seconds", std::round(rec.seconds * 1000) / 1000},
               {"exit", rec.exit},
               {"signal", rec.signal},
               {"timeout", rec.timeout},
               {"rows", ojson::array()}};
  if (!rec.signal.is_null() || rec.timeout) {
    res["status"] = "crashed";
    res["error"] = rec.timeout ? "worker ran past --timeout (killed by SIGKILL)"
                               : "worker killed by " + rec.signal.get<std::string>();
    return res;
  }
  if (doc.is_null()) {
    std::string tail = rec.stderrTail;
    while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back()))) tail.pop_back();
    while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.front()))) tail.erase(0, 1);
    if (tail.size() > 400) tail = tail.substr(tail.size() - 400);
    res["status"] = "worker-error";
    res["error"] = "exit " + valueText(rec.exit) + ", no JSON: " + tail;
    return res;
  }
  res["status"] = doc.at("status");
  res["error"] = member(doc, "error");
  res["loaderFallbacks"] = member(doc, "loaderFallbacks", ojson::object());
  res["scene"] = member(doc, "scene");
  const std::string status = doc.at("status").get<std::string>();
  if (status == "load-failed" || status == "no-data") return res;
  std::vector<std::string> kinds;
  std::vector<ojson> bounds, worlds, radii;
  ojson frames = ojson::array();
  for (const ojson& f : doc.at("frames")) {
    kinds.push_back(f.at("kind").get<std::string>());
    if (f.contains("positionBound")) {
      bounds.push_back(f["positionBound"].at("pixels"));
      worlds.push_back(f["positionBound"].at("worldUnits"));
      radii.push_back(f["positionBound"].at("envelopeRadius"));
    }
    frames.push_back({{"animation", f.at("animation")}, {"time", f.at("time")}});
  }
  res["kind"] = kinds.empty() ? ojson(nullptr) : ojson(kinds[0]);
  res["boundPixels"] = maxOf(bounds);
  res["boundWorld"] = maxOf(worlds);
  res["envelopeRadius"] = maxOf(radii);
  res["frames"] = frames;
  res["gl"] = member(doc, "gl");
  for (const ojson& name : doc.at("pipelineOrder"))
    res["rows"].push_back(pipelineRow(rel, name.get<std::string>(), doc, rec, kinds, bounds, set));
  return res;
}

ojson crashedRow(const std::string& rel, const std::string& pipeline, const WorkerRecord& rec, const ojson& error) {
  return {{"file", rel},
          {"pipeline", pipeline},
          {"exit", rec.exit},
          {"signal", rec.signal.is_null() ? ojson("timeout") : rec.signal},
          {"status", "crashed"},
          {"error", error},
          {"seconds", std::round(rec.seconds * 1000) / 1000},
          {"drawn", false},
          {"fallbacks", ojson::object()}};
}

}  // namespace mb::check
