// CpuStopwatch (core/stopwatch.h): busy work counts, sleeping does not, and the CPU time of the threads a
// parallelFor starts counts for the thread that ran it (also nested), not for its neighbours. Every busy loop
// spins until ITS OWN thread has used a given CPU time, so the expected readings hold however loaded the
// machine is (a competing load stretches the wall time, not these).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <thread>
#include <vector>

#include "core/parallel.h"
#include "core/stopwatch.h"

namespace aliaslab {
namespace {

double ownThreadMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

/// Spins until the calling thread has used `ms` more milliseconds of CPU.
void spinCpu(double ms) {
  const double until = ownThreadMs() + ms;
  volatile double sink = 0;
  while (ownThreadMs() < until)
    for (int i = 0; i < 1000; ++i) sink = sink + 1e-9 * i;
}

double rusageThreadMs() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return 1e3 * (double(u.ru_utime.tv_sec) + double(u.ru_stime.tv_sec)) +
         1e-3 * (double(u.ru_utime.tv_usec) + double(u.ru_stime.tv_usec));
}

TEST(CpuStopwatch, BusyWorkCountsAsTheKernelSeesIt) {
  const double before = rusageThreadMs();
  const CpuStopwatch cpu;
  spinCpu(60);
  const double got = cpu.ms(), kernel = rusageThreadMs() - before;
  EXPECT_GE(got, 60);
  EXPECT_LT(got, 80);
  EXPECT_NEAR(got, kernel, 10);  // getrusage's own accounting (tick-granular on some kernels)
}

TEST(CpuStopwatch, SleepDoesNotCount) {
  const CpuStopwatch cpu;
  const Stopwatch wall;
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  EXPECT_GE(wall.ms(), 150);
  EXPECT_LT(cpu.ms(), 10);
  // nor in the threads of a parallel loop
  const CpuStopwatch loop;
  parallelFor(4, 4, [](int) { std::this_thread::sleep_for(std::chrono::milliseconds(100)); });
  EXPECT_LT(loop.ms(), 20);
}

TEST(CpuStopwatch, InnerThreadsCountForTheThreadThatRanTheLoop) {
  // 4 items of 25 ms CPU each on 4 threads: 100 ms, whichever thread ran which item
  const CpuStopwatch cpu;
  parallelFor(4, 4, [](int) { spinCpu(25); });
  EXPECT_GE(cpu.ms(), 100);
  EXPECT_LT(cpu.ms(), 130);
}

TEST(CpuStopwatch, NestedLoopsCountForTheirOwnTaskOnly) {
  // 2 outer tasks on 2 threads, each running 2 inner items of 20 ms on 2 threads: each task reads its own 40 ms
  // (not its neighbour's), and the caller reads all 80 ms
  std::vector<double> task(2, 0);
  const CpuStopwatch all;
  parallelFor(2, 2, [&](int i) {
    const CpuStopwatch mine;
    parallelFor(2, 2, [](int) { spinCpu(20); });
    task[i] = mine.ms();
  });
  const double total = all.ms();
  for (double t : task) {
    EXPECT_GE(t, 40);
    EXPECT_LT(t, 55);
  }
  EXPECT_GE(total, 80);
  EXPECT_LT(total, 105);
}

}  // namespace
}  // namespace aliaslab
