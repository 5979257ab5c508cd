// Child processes of this executable for `motorbench report`: each scene is measured by a
// `motorbench report --worker ...` process, so scenes run in parallel (--jobs N; a GL context
// is per process, see pipelines/gl/context.h) and a scene that crashes or hangs the driver
// is recorded as failed while the run goes on.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::process {

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
// `progress` ("measured"; empty: none): one line per finished task on stderr (workerProgressLine).
// After SIGINT / SIGTERM (interrupt.h, when caught) the children running are stopped and every
// task without a result gets `onFailure` with "interrupted": true.
std::vector<nlohmann::json> runWorkers(const std::vector<WorkerTask>& tasks, int jobs, double timeoutS,
                                       const std::string& progress = "");

// "report: [12/340] measured cow: ok 1.2 s, 14 s elapsed, about 5 min left": the task's status
// ("failed (reason)" shortened), its own seconds, the run's and an estimate of the time left.
std::string workerProgressLine(const std::string& what, size_t done, size_t total, const std::string& item,
                               const nlohmann::json& result, double seconds, double elapsed);

// Runs one command (this executable with `args`) to completion, stdout sent to `stdoutPath`
// (or inherited when empty). Returns "" on exit status 0, else how it ended.
std::string runSelf(const std::vector<std::string>& args, const std::string& stdoutPath, double timeoutS);

// Runs `exe` (a path or a name on PATH) with `args` to completion; stdout, and stderr too when
// `bothStreams`, to `outputPath` (inherited when empty). "" on exit status 0, else how it ended
// ("exit status 127" when the program does not exist; "interrupted (SIGINT)" when stopped by one).
std::string runProgram(const std::string& exe, const std::vector<std::string>& args,
                       const std::string& outputPath, bool bothStreams, double timeoutS);

}  // namespace mb::process
