// `motorbench merge` for checks: the output folders of `motorbench check --shard I/N` runs put
// back together into one check.json and summary.html, with the exit status one run would have.
#pragma once
#include <string>
#include <vector>

namespace mb::check {

// Reads DIR/check.json of every folder, checks they are shards 1..N of one scene list against
// the same goldens (else exit 2 naming the folders), copies the images each shard wrote and
// writes check.json + summary.html into `outDir`. Returns 2 when an image errored or the merge
// failed, 1 when one failed its threshold, else 0 (as `motorbench check`).
int mergeCheckRuns(const std::vector<std::string>& dirs, const std::string& outDir);

}  // namespace mb::check
