// `motorbench merge` for reports: the report folders of `motorbench report --shard I/N` runs
// (one per shard, possibly made on different machines) put back together into one report.json,
// report.md, report.html with plots, as if one run had measured every scene.
#pragma once
#include <string>
#include <vector>

#include "harness/report/report_run.h"

namespace mb::report {

// Reads DIR/report.json of every folder in `dirs`, checks that they are shards 1..N of the same
// input list made with the same settings -- a missing or duplicated shard, a different list or
// different settings is an error naming the folders, never a partial merge -- copies each
// scene's images into options.outDir and writes the merged report there (writeReportFolder).
// Returns 0, or 2 with the reason printed.
int mergeReports(const std::vector<std::string>& dirs, const Options& options);

}  // namespace mb::report
