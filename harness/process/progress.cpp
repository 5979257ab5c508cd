#include "harness/process/progress.h"

#include <unistd.h>

#include <cstdio>

namespace mb::process {

std::string durationText(double s) {
  char buf[64];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%d min %02d s", int(s) / 60, int(s) % 60);
  else std::snprintf(buf, sizeof buf, "%d h %02d min", int(s) / 3600, int(s) % 3600 / 60);
  return buf;
}

Progress::Progress(std::string command, std::string what, size_t total, bool inPlace, double minIntervalS)
    : command_(std::move(command)), what_(std::move(what)), total_(total), start_(std::chrono::steady_clock::now()),
      terminal_(inPlace && ::isatty(STDERR_FILENO) != 0), minIntervalS_(minIntervalS) {}

Progress::~Progress() {
  if (terminal_ && done_ > 0) std::fputc('\n', stderr);
}

void Progress::done(const std::string& item) {
  ++done_;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const bool first = lastPrintedS_ < 0, last = done_ >= total_;
  if (!terminal_ && !first && !last && elapsed - lastPrintedS_ < minIntervalS_) return;
  lastPrintedS_ = elapsed;
  std::string line = command_ + ": " + std::to_string(done_) + "/" + std::to_string(total_) + " " + what_ + " (" +
                     item + "), " + durationText(elapsed) + " elapsed";
  if (done_ < total_) line += ", about " + durationText(elapsed / double(done_) * double(total_ - done_)) + " left";
  // What the command printed so far goes out first: a progress line written while stdout's
  // buffer held half a line would land inside that line where both go to one pipe.
  std::fflush(stdout);
  if (terminal_) std::fprintf(stderr, "\r\033[K%s", line.c_str());
  else std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
}

}  // namespace mb::process
