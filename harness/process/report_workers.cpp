#include "harness/process/report_workers.h"

#include <optional>

#include "harness/process/interrupt.h"
#include "harness/process/progress.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>

extern char** environ;

namespace mb::process {
namespace {

using Clock = std::chrono::steady_clock;

struct Child {
  pid_t pid = -1;
  Clock::time_point start;
  size_t task = 0;
};

// Starts `exe` (a path, or a name looked up on PATH) with `args`; stdout (and stderr too when
// `bothStreams`) to `outputPath` unless it is empty. -1 when spawning failed.
pid_t spawn(const std::string& exe, const std::vector<std::string>& args,
            const std::string& outputPath, bool bothStreams) {
  std::vector<std::string> argvStore = {exe};
  argvStore.insert(argvStore.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argvStore) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!outputPath.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outputPath.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (bothStreams) posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  }
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

std::string describeStatus(int status) {
  if (WIFEXITED(status))
    return WEXITSTATUS(status) == 0 ? "" : "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = strsignal(sig);
    return "killed by signal " + std::to_string(sig) + (name ? std::string(" (") + name + ")" : "");
  }
  return "ended with wait status " + std::to_string(status);
}

// Polls `pid`; returns true when it ended (status in *how, "" = success). Kills it when it
// has run longer than `timeoutS`.
bool finished(const Child& c, double timeoutS, std::string* how) {
  int status = 0;
  const pid_t r = waitpid(c.pid, &status, WNOHANG);
  if (r == c.pid) {
    *how = describeStatus(status);
    return true;
  }
  if (r < 0) {
    *how = std::string("waitpid: ") + std::strerror(errno);
    return true;
  }
  const double ran = std::chrono::duration<double>(Clock::now() - c.start).count();
  if (ran > timeoutS) {
    kill(c.pid, SIGKILL);
    waitpid(c.pid, &status, 0);
    char buf[64];
    std::snprintf(buf, sizeof buf, "timed out after %.0f s", timeoutS);
    *how = buf;
    return true;
  }
  return false;
}

// SIGTERM, then SIGKILL after two seconds; reaped either way.
void stopChild(pid_t pid) {
  kill(pid, SIGTERM);
  int status = 0;
  for (int i = 0; i < 100; ++i) {
    if (waitpid(pid, &status, WNOHANG) == pid) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
}

}  // namespace

std::string workerProgressLine(const std::string& what, size_t done, size_t total, const std::string& item,
                               const nlohmann::json& result, double seconds, double elapsed) {
  char took[32];
  std::snprintf(took, sizeof took, "%.1f s", seconds);
  std::string status = result.is_object() ? result.value("status", "ok") : "ok";
  if (status != "ok" && result.is_object() && result.contains("error") && result["error"].is_string()) {
    std::string why = result["error"].get<std::string>();
    if (why.size() > 120) why = why.substr(0, 117) + "...";
    status += " (" + why + ")";
  }
  std::string line = "report: [" + std::to_string(done) + "/" + std::to_string(total) + "] " + what + " " + item + ": " +
                     status + " " + took + ", " + durationText(elapsed) + " elapsed";
  if (done < total) line += ", about " + durationText(elapsed / double(done) * double(total - done)) + " left";
  return line;
}

std::string selfExecutable() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "motorbench";
  return std::string(buf, size_t(n));
}

std::vector<nlohmann::json> runWorkers(const std::vector<WorkerTask>& tasks, int jobs, double timeoutS,
                                       const std::string& progress) {
  std::vector<nlohmann::json> results(tasks.size());
  const Clock::time_point runStart = Clock::now();
  size_t finishedCount = 0;
  std::vector<Child> running;
  size_t next = 0;
  // A result counts when the child marked it complete ("complete": true, written last), even
  // if the process then died on the way out (e.g. in driver teardown); that is noted.
  auto collect = [&](size_t i, const std::string& how) {
    std::ifstream in(tasks[i].resultPath);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_discarded() && j.is_object() && j.value("complete", false)) {
      j.erase("complete");
      if (!how.empty()) j["workerExit"] = how;
      results[i] = std::move(j);
      return;
    }
    results[i] = tasks[i].onFailure;
    results[i]["status"] = "failed";
    results[i]["error"] = "worker " + (how.empty() ? "ended without writing a result" : how);
    if (interruptSignal() != 0) {  // Ctrl-C reaches the workers too: stopped, not failed
      results[i]["interrupted"] = true;
      results[i]["error"] = std::string("not measured: the run was interrupted (") + interruptName() + ")";
    }
  };
  auto announce = [&](size_t i, double seconds) {
    ++finishedCount;
    if (progress.empty()) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - runStart).count();
    std::fprintf(stderr, "%s\n",
                 workerProgressLine(progress, finishedCount, tasks.size(),
                                    tasks[i].onFailure.value("id", "#" + std::to_string(i + 1)), results[i], seconds,
                                    elapsed)
                     .c_str());
    std::fflush(stderr);
  };
  while (next < tasks.size() || !running.empty()) {
    if (interruptSignal() != 0) break;
    while (next < tasks.size() && int(running.size()) < std::max(1, jobs)) {
      std::remove(tasks[next].resultPath.c_str());
      const pid_t pid = spawn(selfExecutable(), tasks[next].args, "", false);
      if (pid < 0) collect(next, "could not be started"), announce(next, 0);
      else running.push_back({pid, Clock::now(), next});
      ++next;
    }
    bool any = false;
    for (size_t r = 0; r < running.size();) {
      std::string how;
      if (finished(running[r], timeoutS, &how)) {
        collect(running[r].task, how);
        announce(running[r].task, std::chrono::duration<double>(Clock::now() - running[r].start).count());
        running.erase(running.begin() + long(r));
        any = true;
      } else {
        ++r;
      }
    }
    if (!any) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (interruptSignal() != 0) {
    // Interrupted: the children still running are stopped (and reaped); their scenes and those
    // never started are marked, not measured.
    for (const Child& c : running) stopChild(c.pid);
    for (size_t i = 0; i < tasks.size(); ++i)
      if (results[i].is_null()) {
        results[i] = tasks[i].onFailure;
        results[i]["status"] = "failed";
        results[i]["interrupted"] = true;
        results[i]["error"] = std::string("not measured: the run was interrupted (") + interruptName() + ")";
      }
  }
  return results;
}

std::string runSelf(const std::vector<std::string>& args, const std::string& stdoutPath, double timeoutS) {
  return runProgram(selfExecutable(), args, stdoutPath, false, timeoutS);
}

std::string runProgram(const std::string& exe, const std::vector<std::string>& args,
                       const std::string& outputPath, bool bothStreams, double timeoutS) {
  const pid_t pid = spawn(exe, args, outputPath, bothStreams);
  if (pid < 0) return "could not be started";
  Child c{pid, Clock::now(), 0};
  std::string how;
  while (!finished(c, timeoutS, &how)) {
    if (interruptSignal() != 0) {
      stopChild(pid);
      return std::string("interrupted (") + interruptName() + ")";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return how;
}

}  // namespace mb::process
