// The report folder between runs: a new run into a folder removes what an earlier report left
// there (its documents, images/, plots/, the kernel and ISA files it wrote, the PARTIAL marker)
// before it writes anything, so no stale image or table outlives the run that made it; and a
// run marks the folder PARTIAL until its report is complete.
#pragma once
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::report {

// The marker a run writes first and removes last: a folder with it holds no complete report.
inline constexpr const char* kPartialMarker = "PARTIAL";

// The names a report writes into its folder (files and folders).
const std::vector<std::string>& reportOwnedNames();

// Prepares `dir` for a new report: missing or empty, nothing to do; holding only a report's
// names, they are removed; holding other files too, they are kept (and named on stderr) when the
// folder holds an earlier report (report.json or the marker), else the run is refused naming
// them (a folder of the user's that is no report's). Files in `keep` (inputs the run reads, such
// as --bench-json DIR/bench.json, with the bench.txt / isa.txt beside such an input) are never removed.
Status clearOldReport(const std::string& dir, const std::vector<std::string>& keep);

// Writes the marker with `text` (why the folder is not complete).
Status markPartial(const std::string& dir, const std::string& text);
void clearPartialMark(const std::string& dir);

}  // namespace mb::report
