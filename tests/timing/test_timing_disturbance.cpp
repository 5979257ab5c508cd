// Disturbance detection (harness/timing/disturbance.h): the judgement on hand-made
// samples, then live: a figure timed while a busy-loop child shares the measuring thread's core
// is marked disturbed, and the same figure timed alone is not. No time is asserted, only the mark.
#include <gtest/gtest.h>

#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "harness/timing/disturbance.h"

namespace {

using mb::timing::Disturbance;
using mb::timing::LoadSample;

TEST(Disturbance, JudgesCpuOverRealAndTheRunQueue) {
  const LoadSample quiet{0.2, 1}, busy{6.5, 5};
  const Disturbance alone = mb::timing::judgeDisturbance(0.95, 1.0, quiet, quiet, 2);
  EXPECT_FALSE(alone.disturbed) << alone.reason;
  EXPECT_TRUE(alone.reason.empty());
  // 53 ms real for 15 ms CPU (a build sharing the cores): 0.28 of the real time.
  const Disturbance shared = mb::timing::judgeDisturbance(0.015, 0.053, quiet, quiet, 2);
  EXPECT_TRUE(shared.disturbed);
  EXPECT_NE(shared.reason.find("CPU/real 0.28 < 0.90"), std::string::npos) << shared.reason;
  // Five runnable threads on two cores at both samples: busy, whatever the CPU share.
  const Disturbance crowded = mb::timing::judgeDisturbance(1.0, 1.0, busy, busy, 2);
  EXPECT_TRUE(crowded.disturbed);
  EXPECT_NE(crowded.reason.find("5 and 5 runnable threads"), std::string::npos) << crowded.reason;
  // One busy sample only (a compiler that ended meanwhile) is not enough.
  EXPECT_FALSE(mb::timing::judgeDisturbance(1.0, 1.0, busy, quiet, 2).disturbed);
  // Exactly the cores: nobody waits.
  EXPECT_FALSE(mb::timing::judgeDisturbance(1.0, 1.0, {2.0, 2}, {2.0, 2}, 2).disturbed);
  const nlohmann::json j = mb::timing::toJson(shared);
  EXPECT_EQ(j["disturbed"], true);
  EXPECT_NEAR(j["cpuOverReal"].get<double>(), 0.015 / 0.053, 1e-12);
  EXPECT_EQ(j["loadBefore"]["runnable"], 1);
  EXPECT_TRUE(mb::timing::toJson(alone)["reason"].is_null());
  EXPECT_EQ(mb::timing::disturbanceMark(alone), "");
  EXPECT_EQ(mb::timing::disturbanceMark(shared), " [disturbed: " + shared.reason + "]");
}

// The first CPU this process may run on, and the process pinned to it.
int pinToOneCpu() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return -1;
  int cpu = 0;
  while (cpu < CPU_SETSIZE && !CPU_ISSET(cpu, &set)) ++cpu;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  return sched_setaffinity(0, sizeof one, &one) == 0 ? cpu : -1;
}

void restoreAffinity(const cpu_set_t& all) { sched_setaffinity(0, sizeof all, &all); }

// A figure: 0.3 s of arithmetic on the calling thread, watched.
Disturbance timedFigure() {
  const mb::timing::DisturbanceWatch watch(mb::timing::CpuClock::Thread);
  volatile double x = 1.0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  while (std::chrono::steady_clock::now() < end)
    for (int i = 0; i < 10000; ++i) x = x * 1.0000001 + 1e-9;
  return watch.finish();
}

TEST(Disturbance, BusyLoopChildOnTheSameCoreMarksTheFigure) {
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  ASSERT_GE(pinToOneCpu(), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // inherits the one-CPU affinity: competes for the measuring thread's core
    volatile unsigned long spin = 0;
    for (;;) spin = spin + 1;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const Disturbance d = timedFigure();
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  restoreAffinity(all);
  EXPECT_TRUE(d.disturbed) << "CPU/real " << d.cpuOverReal();
  EXPECT_NE(d.reason.find("cores shared"), std::string::npos) << d.reason;
  EXPECT_LT(d.cpuOverReal(), mb::timing::kMinCpuOverReal);
}

TEST(Disturbance, FigureTimedAloneIsNotMarked) {
  // Only meaningful on a machine that is quiet now: other engineers' builds would (rightly)
  // mark it. Best of three figures, so a one-off wake-up of a system thread does not decide.
  const LoadSample now = mb::timing::sampleLoad();
  const unsigned cores = std::thread::hardware_concurrency();
  if (now.runnable > int(cores))
    GTEST_SKIP() << "machine busy now (" << now.runnable << " runnable, load " << now.average1 << " on " << cores
                 << " cores): an undisturbed figure cannot be taken";
  Disturbance best;
  for (int attempt = 0; attempt < 3; ++attempt) {
    best = timedFigure();
    if (!best.disturbed) break;
  }
  EXPECT_FALSE(best.disturbed) << best.reason;
  EXPECT_GE(best.cpuOverReal(), mb::timing::kMinCpuOverReal);
}

}  // namespace
