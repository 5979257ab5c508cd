#include "harness/process/interrupt.h"

#include <signal.h>

#include <atomic>

namespace mb::process {
namespace {

std::atomic<int> g_signal{0};

extern "C" void onInterrupt(int sig) {
  g_signal.store(sig);
  // The next one ends the process as a terminal user expects of a second Ctrl-C.
  signal(sig, SIG_DFL);
}

}  // namespace

void catchInterrupts() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int interruptSignal() { return g_signal.load(); }

const char* interruptName() {
  const int s = interruptSignal();
  return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "a signal";
}

}  // namespace mb::process
