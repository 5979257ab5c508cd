#include "harness/timing/timing_text.h"

#include <cstdio>

namespace mb::timing {
namespace {

// "median [q1-q3]" of a spread in ms, shown scaled by `scale` (1: ms, 1000: us).
std::string cell(const Spread& s, double scale = 1.0) {
  char b[96];
  std::snprintf(b, sizeof b, scale > 1 ? "%.2f [%.2f-%.2f]" : "%.3f [%.3f-%.3f]", s.median * scale, s.q1 * scale,
                s.q3 * scale);
  return b;
}

std::string format(const char* fmt, const std::string& a, const std::string& b, const std::string& c,
                   const std::string& d, const std::string& e) {
  char line[512];
  std::snprintf(line, sizeof line, fmt, a.c_str(), b.c_str(), c.c_str(), d.c_str(), e.c_str());
  return line;
}

const char* const kRow = "  %-10s %-24s %-22s %-28s %s\n";

// The space's matrix and motor pipelines (matrix / motor, s3_matrix / s3_motor, ...).
bool isMatrix(const std::string& p) { return p == "matrix" || p.ends_with("_matrix"); }
bool isMotor(const std::string& p) { return p == "motor" || p.ends_with("_motor"); }

// "exact fallback: motor 1 skinned draws (51 joints), 2940 vertices on 30 of 30 frames; ..." for
// every pipeline that took one (the most in one frame), or nothing.
std::string fallbackLines(const ConfigTiming& c) {
  std::string list;
  for (const PipelineTiming& t : c.pipelines) {
    if (!t.error.empty() || !t.fallbacks.any()) continue;
    const FallbackTally& f = t.fallbacks;
    char b[256];
    std::snprintf(b, sizeof b, "%s%s %d rigid + %d skinned draws (%d joints), %llu vertices on %d of %zu frames",
                  list.empty() ? "" : "; ", t.pipeline.c_str(), f.linearDraws, f.skinDraws, f.skinJoints,
                  (unsigned long long)f.vertices, f.frames, t.frameMs.size());
    list += b;
  }
  if (list.empty()) return "";
  return "  exact fallback (most in one frame; ratios marked \"fallback\" include it): " + list + "\n";
}

}  // namespace

std::string RatioText::text() const {
  if (spread.n == 0) return "-";
  char b[96];
  std::snprintf(b, sizeof b, "%.3f [%.3f-%.3f]%s", spread.median, spread.q1, spread.q3, noise() ? " noise" : "");
  if (tooFewFrames())
    std::snprintf(b, sizeof b, "%.3f [%.3f-%.3f] too few frames (%d < %d)", spread.median, spread.q1, spread.q3,
                  spread.n, kMinRatioFrames);
  return b;
}

RatioText pairedRatio(const std::vector<double>& baseline, const std::vector<double>& other) {
  return {spreadOf(pairedRatios(baseline, other))};
}

std::string timingLegend() {
  return "ratios: pipeline / matrix of the same space, < 1: motor (or the pipeline) faster; each is the median of "
         "the per-frame ratios (both render the same frame back to back) with [q1-q3] of those ratios; \"noise\": "
         "q1 <= 1 <= q3, the frames do not decide which is faster (time more --frames)\n";
}

std::string timingBlock(const ConfigTiming& c) {
  std::string out = c.scene + (c.patchLevel ? " N=" + std::to_string(c.patchLevel) : "") + " (" + c.config + " " +
                    std::to_string(c.width) + "x" + std::to_string(c.height) + ")" + disturbanceMark(c.disturbance) + "\n";
  out += format(kRow, "pipeline", "frame ms [q1-q3]", "update us [q1-q3]", "frame/matrix [q1-q3]",
                "update/matrix [q1-q3]");
  const PipelineTiming* matrix = nullptr;
  const PipelineTiming* motor = nullptr;
  for (const PipelineTiming& t : c.pipelines) {
    if (!t.error.empty()) continue;
    if (isMatrix(t.pipeline)) matrix = &t;
    if (isMotor(t.pipeline)) motor = &t;
  }
  for (const PipelineTiming& t : c.pipelines) {
    if (!t.error.empty()) {
      out += format(kRow, t.pipeline, "error: " + t.error, "", "", "");
      continue;
    }
    const bool base = &t == matrix;
    const std::string mark = t.fallbacks.any() ? " fallback" : "";
    const std::string frameRatio =
        base ? "1 (baseline)" : matrix ? pairedRatio(matrix->frameMs, t.frameMs).text() + mark : "-";
    const std::string updateRatio =
        base ? "1 (baseline)" : matrix ? pairedRatio(matrix->updateMs, t.updateMs).text() + mark : "-";
    out += format(kRow, t.pipeline, cell(t.frame), cell(t.update, 1000.0), frameRatio, updateRatio);
  }
  if (matrix && motor) {
    char ofMedians[32] = "-";
    if (c.frameRatio > 0) std::snprintf(ofMedians, sizeof ofMedians, "%.3f", c.frameRatio);
    out += "  " + motor->pipeline + "/" + matrix->pipeline + " frame: paired " +
           pairedRatio(matrix->frameMs, motor->frameMs).text() + ", of the medians " + ofMedians +
           "; process CPU time per frame: paired " + pairedRatio(matrix->cpuMs, motor->cpuMs).text() + "\n";
  }
  out += fallbackLines(c);
  // The update phase by phase (medians, us per call), every pipeline.
  std::string phases;
  for (const PipelineTiming& t : c.pipelines) {
    if (!t.error.empty()) continue;
    char b[300];
    double sum = 0;
    for (const Spread& ph : t.phases) sum += ph.median;
    // The phases come from their own blocks (clock reads between phases): their sum may exceed
    // the whole update a little; far above it, those blocks ran slower and the phases are shares.
    const bool slower = t.update.median > 0 && sum > 1.5 * t.update.median;
    std::snprintf(b, sizeof b, "    %-10s %.2f/%.2f/%.2f/%.2f/%.2f (sum %.2f; whole update %.2f)%s\n", t.pipeline.c_str(),
                  1e3 * t.phases[0].median, 1e3 * t.phases[1].median, 1e3 * t.phases[2].median,
                  1e3 * t.phases[3].median, 1e3 * t.phases[4].median, 1e3 * sum, 1e3 * t.update.median,
                  slower ? " the phase blocks ran slower than the timed update: read the phases as shares" : "");
    phases += b;
  }
  if (!phases.empty())
    out += "  update phases us (sampling/blending/conversion/hierarchy/palette; a separate block with the phase "
           "clock on):\n" + phases;
  // Vertices drawn (instances counted) per microsecond of median frame time, every pipeline.
  std::string rates;
  for (const PipelineTiming& t : c.pipelines) {
    if (!t.error.empty()) continue;
    char b[96];
    std::snprintf(b, sizeof b, "%s%s %.1f", rates.empty() ? "" : "; ", t.pipeline.c_str(), verticesPerUs(t));
    rates += b;
  }
  if (!rates.empty())
    out += "  vertices per us of frame time (" + std::to_string(c.pipelines.front().stats.drawnVertices) +
           " drawn vertices): " + rates + "\n";
  return out;
}

}  // namespace mb::timing
