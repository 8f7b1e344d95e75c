// One group of the sweep: the K seeds of one (scene, sampler, spp, prefilter), each sample set traced once and
// reconstructed into every row of the group.
//
// Protocol: runGroup takes the seeds in windows of at most `threads` sample sets (the memory bound,
// study/sweep/sweep_memory.h), and runs each window in three phases of tasks:
//   A  traceSampleSet  one task per seed: "trace this sample set" (+ the shared Accumulator pass of the
//                      weighted rows); adaptive samplers trace their own set (render/adaptive.h)
//   B  reconstructRow  one task per (seed, row): that row's image of that seed (importance rows trace their own)
//   C  foldSeeds       one task per row: the window's images added to its metrics IN SEED ORDER
// Every task writes only its own slot; slots are folded in (seed, row) order, so nothing depends on which thread
// ran what or when it finished (tests/programs/sweep_parallel_test.cpp runs the tasks in a shuffled order). Time goes into
// the SweepPhases' trace, splat, resolve, flip, metrics and waiting (study/sweep/sweep_summary.h), as thread-seconds, and
// each row's own work per seed (its set's trace + its reconstruction) as thread CPU time (inner threads included)
// into PendingRow::cpuMs, in seed order. Each task times its steps with one ScopedPhase line each into its slot's
// PhaseTimes (core/phase_timer.h); the parallel phases' idle time comes from timedParallelFor (core/stopwatch.h).
#pragma once
#include <functional>
#include <vector>

#include "render/tracer.h"
#include "study/config.h"
#include "study/study_scene.h"
#include "study/sweep/sweep_memory.h"
#include "study/sweep/sweep_rows.h"
#include "study/sweep/sweep_summary.h"

namespace aliaslab {

struct GroupContext {
  const StudyConfig& config;
  const StudyScene& scene;
  const SampleSetGroup& group;
  const Tracer& tracer;  ///< the scene's tracer, or its pre-filtering twin for prefilter=footprint groups
  std::vector<PendingRow>& rows;
  int threads;  ///< resolved, >= 1
  bool images;
  InFlight& inFlight;
  SweepPhases& phases;
  SweepSummary& sum;
  GroupSpent& spent;
};

/// Runs the K seeds of one group into its rows' accumulators; `advance(n)` after each window of n seeds.
void runGroup(const GroupContext& g, const std::function<void(double)>& advance);

}  // namespace aliaslab
