// The corpus rules' reading of one `motorbench survey` document: a file's result and its rows
// (one per pipeline) with every figure the rules judge (corpus_verdicts.h). Values are JSON in
// the order corpus-check.json writes them; an identical frame's PSNR is +infinity in memory and
// null in the file (nlohmann writes infinities as null; "rigidIdentical" says which).
#pragma once
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::check {

using ojson = nlohmann::ordered_json;

// The thresholds and the pipelines each rule judges.
struct RuleSet {
  double minPsnr = 50.0;       // dB: rigid frames of the full-precision pipelines against matrix
  double maxDrawnDiff = 0.01;  // skinned frames: drawn-pixel counts at most this fraction apart
  std::vector<std::string> pipelines;      // --pipelines (empty: every one of the file's space)
  std::vector<std::string> fullPrecision;  // judged by PSNR against matrix (rigid frames)
  std::vector<std::string> compact;        // judged by their position bound (rigid frames)
  std::vector<std::string> motorBlend;     // skinned frames judged against the motor-blend reference
  bool isFullPrecision(const std::string& p) const;
  bool isCompact(const std::string& p) const;
  bool blendsMotors(const std::string& p) const;
};

// The rule set of the registry's Euclidean pipelines (`only` non-empty: those of them alone):
// the full-precision ones are every one but matrix and the 16-byte ones, the motor-blend ones
// those whose skinning method is the motor blend (pipelines/skin_method.h).
RuleSet defaultRuleSet(const std::vector<std::string>& only = {});

// How one survey worker ended.
struct WorkerRecord {
  ojson exit = nullptr;    // exit status, null when it died by a signal or never ran
  ojson signal = nullptr;  // "SIGSEGV", null when it exited
  bool timeout = false;
  std::string stderrTail;  // its last 2000 bytes of stderr
  ojson doc = nullptr;     // the survey document, null when none was written
  double seconds = 0;
};

// An identical frame's PSNR.
inline constexpr double kIdentical = std::numeric_limits<double>::infinity();

// A JSON number as a double.
inline double numberOf(const ojson& v) { return v.get<double>(); }

// j[key] when j is an object holding it, not null; else `fallback`.
ojson member(const ojson& j, const char* key, const ojson& fallback = nullptr);
// Python's truth of a value: null, false, 0, "" and empty lists and objects are false.
bool truthy(const ojson& v);
// `v` printed by a printf format of one double ("%.2f dB").
std::string printed(const char* format, double v);

// A frame of file result `file` by index: "rest" or "t=0.4" (the time to 3 significant digits).
std::string frameName(const ojson& file, size_t index);

// "identical", "42.4", "-" (null).
std::string psnrText(const ojson& psnr);

// Python's str() of a JSON value as the lines print it: null "None", lists "[1, 2]".
std::string valueText(const ojson& v);

// The file's result from its worker: {"file", "features", "seconds", "exit", "signal", "timeout",
// "rows", "status" (ok, error, no-data, load-failed, crashed, worker-error), "error", ...} and,
// for a file drawn, its kind, bound and frames and a row per pipeline.
ojson fileResult(const std::string& rel, const WorkerRecord& rec, const std::string& features, const RuleSet& set);

// The row of a pipeline that crashed when run alone.
ojson crashedRow(const std::string& rel, const std::string& pipeline, const WorkerRecord& rec, const ojson& error);

}  // namespace mb::check
