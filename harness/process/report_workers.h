// Child processes of this executable for `motorbench report`: each scene is measured by a
// `motorbench report --worker ...` process, so scenes run in parallel (--jobs N; a GL context
// is per process, see pipelines/gl/context.h) and a scene that crashes or hangs the driver
// is recorded as failed while the run goes on.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::report {

struct WorkerTask {
  std::vector<std::string> args;  // after "motorbench"
  std::string resultPath;         // JSON the child writes
  nlohmann::json onFailure;       // returned (with "error" set) when the child writes nothing
};

// The path of the running executable (/proc/self/exe), for spawning workers and `bench`.
std::string selfExecutable();

// Runs every task, at most `jobs` at once, each killed after `timeoutS` seconds. Returns, in
// task order, the JSON each child wrote, or `onFailure` with "error" saying how it ended
// ("exit status 3", "killed by signal 11", "timed out after 600 s").
// `progress` ("scenes rendered"; empty: none) names the items of a Progress line per finished task.
std::vector<nlohmann::json> runWorkers(const std::vector<WorkerTask>& tasks, int jobs, double timeoutS,
                                       const std::string& progress = "");

// Runs one command (this executable with `args`) to completion, stdout sent to `stdoutPath`
// (or inherited when empty). Returns "" on exit status 0, else how it ended.
std::string runSelf(const std::vector<std::string>& args, const std::string& stdoutPath, double timeoutS);

// Runs `exe` (a path or a name on PATH) with `args` to completion; stdout, and stderr too when
// `bothStreams`, to `outputPath` (inherited when empty). "" on exit status 0, else how it ended
// ("exit status 127" when the program does not exist).
std::string runProgram(const std::string& exe, const std::vector<std::string>& args,
                       const std::string& outputPath, bool bothStreams, double timeoutS);

}  // namespace mb::report
