// Time by phase: a PhaseTimes record of seconds per phase and a ScopedPhase guard that adds the time of one
// phase to it when it leaves its scope (Mitsuba 3's ScopedPhase is the model: one line per phase).
//
//   enum class Step { Trace, Resolve, Count };   // the phases of some work, Count last
//   PhaseTimes<Step> spent;
//   {
//     const ScopedPhase timing(spent, Step::Trace);
//     samples = trace(...);
//   }                                            // spent.wall(Step::Trace), spent.cpu(Step::Trace) added to
//
// Each phase keeps wall seconds (core/stopwatch.h Stopwatch) and CPU seconds (CpuStopwatch: the calling
// thread's and the inner threads' its parallelFor started). A PhaseTimes is written by one thread at a time:
// parallel tasks each fill their own slot's and the caller adds the slots up afterwards (operator+=), so
// timing never touches what the tasks compute.
#pragma once
#include <array>
#include <cstddef>

#include "core/stopwatch.h"

namespace aliaslab {

template <class Step>
class PhaseTimes {
 public:
  static constexpr size_t kSteps = static_cast<size_t>(Step::Count);
  double wall(Step s) const { return wall_[index(s)]; }
  double cpu(Step s) const { return cpu_[index(s)]; }
  void add(Step s, double wallSeconds, double cpuSeconds) { wall_[index(s)] += wallSeconds, cpu_[index(s)] += cpuSeconds; }
  PhaseTimes& operator+=(const PhaseTimes& o) {
    for (size_t i = 0; i < kSteps; ++i) wall_[i] += o.wall_[i], cpu_[i] += o.cpu_[i];
    return *this;
  }

 private:
  static size_t index(Step s) { return static_cast<size_t>(s); }
  std::array<double, kSteps> wall_{}, cpu_{};
};

/// Adds the wall and CPU seconds from its construction to its destruction to `times` under `step`. Make and
/// destroy it on one thread.
template <class Step>
class ScopedPhase {
 public:
  ScopedPhase(PhaseTimes<Step>& times, Step step) : times_(times), step_(step) {}
  ~ScopedPhase() { times_.add(step_, wall_.seconds(), cpu_.seconds()); }
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

 private:
  PhaseTimes<Step>& times_;
  Step step_;
  Stopwatch wall_;
  CpuStopwatch cpu_;
};

}  // namespace aliaslab
