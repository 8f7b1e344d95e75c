// Timing of work phases: a Stopwatch, and a parallel loop that accounts its time the one way the study reports it.
//
// A Stopwatch starts when made; seconds() and ms() read the time since then (steady clock).
// A CpuStopwatch likewise reads CPU time: the calling thread's (CLOCK_THREAD_CPUTIME_ID) plus that of the threads
// parallelFor started from it in the meantime (core/parallel.h threadCpuSeconds), so the work's own cost however
// many inner threads it used, and not the time it waited for a core a competing load held. Read it on the thread
// that made it.
// timedParallelFor(n, threads, inner, body) runs body(i) for i in [0, n) with parallelFor (core/parallel.h) and
// returns the phase's time as thread-seconds:
//   work = the sum over tasks of (task's wall seconds x `inner`, the threads the task uses inside itself),
//   idle = wall seconds of the loop x threads - work, at least 0 (threads waiting for the loop's last task).
// Timing never changes what the body computes: results still depend only on the slots the tasks write.
#pragma once
#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

#include "core/parallel.h"

namespace aliaslab {

class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;
  Stopwatch() : start_(Clock::now()) {}
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  double ms() const { return 1000.0 * seconds(); }

 private:
  Clock::time_point start_;
};

class CpuStopwatch {
 public:
  CpuStopwatch() : start_(threadCpuSeconds()) {}
  double seconds() const { return threadCpuSeconds() - start_; }
  double ms() const { return 1000.0 * seconds(); }

 private:
  double start_;
};

/// Thread-seconds of one parallel phase.
struct PhaseTime {
  double work = 0;  ///< sum over tasks of seconds x inner threads
  double idle = 0;  ///< wall x threads - work, at least 0
};

/// Runs body(i), i in [0, n), on `threads` threads (resolved, >= 1) and returns its PhaseTime; `inner` is the number
/// of threads each task uses inside itself.
inline PhaseTime timedParallelFor(int n, int threads, int inner, const std::function<void(int)>& body) {
  const Stopwatch wall;
  std::vector<double> busy(size_t(std::max(n, 0)), 0);
  if (n > 0)
    parallelFor(n, threads, [&](int i) {
      const Stopwatch task;
      body(i);
      busy[i] = task.seconds() * inner;
    });
  const double wallSeconds = wall.seconds();
  PhaseTime t;
  for (double b : busy) t.work += b;  // in task order: the sum does not depend on which thread ran what
  t.idle = std::max(0.0, wallSeconds * threads - t.work);
  return t;
}

}  // namespace aliaslab
