#include "harness/check/corpus_junit.h"

namespace mb::check {
namespace {

// Why frame `fr` of `row` fails a rule ("" when it passes every one), as corpus_verdicts judges
// the row: drawn, the rigid PSNR outside the ties, the 16-byte envelope outside the int16-cell
// ties, the skinned drawn pixels against the method's reference.
std::string frameFailure(const ojson& row, const ojson& fr, bool anyDrawn, const RuleSet& set) {
  const std::string pipeline = row["pipeline"].get<std::string>();
  const std::string kind = fr["kind"].get<std::string>();
  std::vector<std::string> why;
  if (numberOf(fr["drawn"]) == 0 && (!anyDrawn || numberOf(member(fr, "baseDrawn", 0)) > 0))
    why.push_back("every drawable file drawn by every pipeline: drew nothing (matrix drew " +
                  valueText(member(fr, "baseDrawn", 0)) + " pixels)");
  const ojson rigid = fr["rigid"];
  if (kind == "rigid" && set.isFullPrecision(pipeline) && !rigid.is_null() && rigid["verdict"] == "fail")
    why.push_back("rigid frames vs matrix >= " + printed("%g", set.minPsnr) + " dB: " + printed("%.2f dB", numberOf(rigid["psnr"])) +
                  ", " + psnrText(rigid["psnrNotTies"]) + " dB outside the tie pixels");
  if (kind == "rigid" && set.isCompact(pipeline) && truthy(fr["outsideEnvelopeNotTies"]))
    why.push_back("rigid frames within their position bound: " + valueText(fr["outsideEnvelope"]) +
                  " px outside the envelope (" + valueText(fr["outsideEnvelopeNotTies"]) + " not int16-cell tie pixels)");
  if (kind == "skinned" && !fr["referenceDiff"].is_null() && numberOf(fr["referenceDiff"]) > set.maxDrawnDiff)
    why.push_back("skinned frames within " + printed("%g", 100 * set.maxDrawnDiff) + " % of their skinning method's reference: " +
                  printed("%.1f %%", 100 * numberOf(fr["referenceDiff"])) + " apart from " + row["skinReference"].get<std::string>());
  std::string text;
  for (const std::string& w : why) text += (text.empty() ? "" : "; ") + w;
  return text;
}

JunitCase fileCase(const ojson& f, JunitCase::Kind kind, const std::string& message) {
  JunitCase c;
  c.classname = "check.rules." + f["file"].get<std::string>();
  c.name = "file";
  c.seconds = numberOf(f["seconds"]);
  c.kind = kind;
  c.message = message;
  return c;
}

}  // namespace

std::vector<JunitCase> junitCases(const std::vector<ojson>& files, const RuleSet& set) {
  std::vector<JunitCase> cases;
  for (const ojson& f : files) {
    const std::string status = f["status"].get<std::string>();
    const std::string error = valueText(f["error"]);
    if (status == "no-data") cases.push_back(fileCase(f, JunitCase::Kind::Skipped, "no data: " + error));
    if (status == "load-failed") cases.push_back(fileCase(f, JunitCase::Kind::Fail, "every file loads: " + error));
    if ((status == "crashed" || status == "worker-error") && f["rows"].empty())
      cases.push_back(fileCase(f, JunitCase::Kind::Error, "0 crashes, signals or timeouts: " + error));
    for (const ojson& r : f["rows"]) {
      const std::string pipeline = r["pipeline"].get<std::string>();
      if (r["status"] == "crashed") {
        JunitCase c = fileCase(f, JunitCase::Kind::Error, "0 crashes, signals or timeouts: " + valueText(r["error"]));
        c.name = pipeline;
        cases.push_back(c);
        continue;
      }
      const ojson frames = member(r, "perFrame", ojson::array());
      bool anyDrawn = false;
      for (const ojson& fr : frames) anyDrawn = anyDrawn || numberOf(fr["drawn"]) > 0;
      const size_t count = member(f, "frames", ojson::array()).size();
      for (size_t k = 0; k < count; ++k) {
        JunitCase c;
        c.classname = "check.rules." + f["file"].get<std::string>();
        c.name = frameName(f, k) + "." + pipeline;
        c.seconds = count ? numberOf(member(r, "seconds", 0)) / double(count) : 0;
        if (r["status"] == "error" && k >= frames.size()) {
          c.kind = JunitCase::Kind::Error;
          c.message = "pipeline error: " + valueText(r["error"]);
        } else if (k >= frames.size()) {
          c.kind = JunitCase::Kind::Error;
          c.message = "no frame drawn";
        } else if (frames[k]["kind"] == "omitted") {
          c.kind = JunitCase::Kind::Skipped;
          c.message = "counted omission: " + valueText(frames[k]["morphNotDrawnNodes"]) +
                      " morphed node(s) drawn in their base shape, judged by no image rule";
        } else if (std::string why = frameFailure(r, frames[k], anyDrawn, set); !why.empty()) {
          c.kind = JunitCase::Kind::Fail;
          c.message = why;
        }
        cases.push_back(c);
      }
    }
  }
  return cases;
}

Status writeRulesJunit(const std::string& path, const std::vector<ojson>& files, const RuleSet& set) {
  return writeJunit(path, "motorbench check --rules", junitCases(files, set));
}

}  // namespace mb::check
