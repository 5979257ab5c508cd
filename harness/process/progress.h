// Progress of a long run (report phases, check, time) on stderr, with an estimate of the time
// left from the mean time per finished item. On a terminal one line is rewritten in place; in a
// log (stderr not a terminal) every step is a plain line of its own, so logs stay greppable.
#pragma once
#include <chrono>
#include <string>

namespace mb::process {

class Progress {
public:
  // `command` prefixes each line ("report"); `what` names the items ("scenes rendered").
  // `inPlace` false: plain lines even on a terminal (for commands whose rows go to stdout).
  // `minIntervalS` > 0: plain lines at most that often (the first and last always), for runs of
  // many quick items (inspect over a folder).
  Progress(std::string command, std::string what, size_t total, bool inPlace = true, double minIntervalS = 0);
  ~Progress();
  // One more item finished; `item` names it ("crowd").
  void done(const std::string& item);

private:
  std::string command_, what_;
  size_t total_, done_ = 0;
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
  double minIntervalS_;
  double lastPrintedS_ = -1;  // elapsed seconds at the last plain line, -1 before the first
};

// "45 s", "3 min 05 s", "1 h 02 min".
std::string durationText(double seconds);

}  // namespace mb::process
