// core/cpu.h's override and core/phase_timer.h's guard: ScopedCpuFeatures withholds features and gives them back
// (nested too), never adds one the processor lacks; ScopedPhase adds a phase's wall and CPU time to that phase
// only, and PhaseTimes add up phase by phase.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/cpu.h"
#include "core/phase_timer.h"

namespace aliaslab {
namespace {

TEST(Cpu, OverrideWithholdsAndRestores) {
  const CpuFeatures cpu = cpuFeatures();  // the processor's (no override alive)
  {
    const ScopedCpuFeatures none(CpuFeatures{});
    EXPECT_FALSE(cpuFeatures().avx2);
    EXPECT_FALSE(cpuFeatures().fma);
    {
      const ScopedCpuFeatures all(CpuFeatures{true, true});  // nested: cannot give back what the outer withholds
      EXPECT_FALSE(cpuFeatures().avx2);
    }
    EXPECT_FALSE(cpuFeatures().avx2);
  }
  EXPECT_EQ(cpuFeatures().avx2, cpu.avx2);
  EXPECT_EQ(cpuFeatures().fma, cpu.fma);
  {
    const ScopedCpuFeatures avx2Only(CpuFeatures{true, false});
    EXPECT_EQ(cpuFeatures().avx2, cpu.avx2);  // never more than the processor has
    EXPECT_FALSE(cpuFeatures().fma);
  }
  EXPECT_EQ(cpuFeatures().fma, cpu.fma);
  EXPECT_EQ(cpu.avx2, __builtin_cpu_supports("avx2") != 0);  // the processor asked the one way
}

enum class Step { A, B, Count };

TEST(PhaseTimer, ScopedPhaseAddsToItsPhaseOnly) {
  PhaseTimes<Step> t;
  {
    const ScopedPhase timing(t, Step::B);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // wall time, next to no CPU time
  }
  EXPECT_EQ(t.wall(Step::A), 0.0);
  EXPECT_EQ(t.cpu(Step::A), 0.0);
  EXPECT_GE(t.wall(Step::B), 0.019);
  EXPECT_LT(t.cpu(Step::B), t.wall(Step::B));
  {
    const ScopedPhase timing(t, Step::A);
    const Stopwatch spin;
    volatile double sink = 0;
    while (spin.seconds() < 0.01) sink = sink + 1;  // busy: some CPU time
  }
  EXPECT_GT(t.cpu(Step::A), 0.0);
  PhaseTimes<Step> sum;
  sum += t, sum += t;
  EXPECT_EQ(sum.wall(Step::B), 2 * t.wall(Step::B));
  EXPECT_EQ(sum.cpu(Step::A), 2 * t.cpu(Step::A));
}

}  // namespace
}  // namespace aliaslab
