// What a sweep reports: its counts and where its time went (runSweep's result, study/sweep/sweep.h).
//
// The parallel phases' thread-seconds are accounted by one helper (core/stopwatch.h timedParallelFor); the
// serial steps' wall seconds by a Stopwatch each. Every step of the sweep adds to its own fields only.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "study/records/contract.h"

namespace aliaslab {

/// Where the sweep's time went (seconds). setup, trace, splat, resolve, flip, metrics and finish are thread-seconds
/// of work summed over tasks: setup = each row's metric and spectrum accumulators at the start of its group; trace
/// includes importance traces; resolve includes classic/supersample/importance reconstruction; flip = the flip
/// column's comparisons, one per (seed, row); metrics = folding the seeds into the rows; finish = finishRow
/// (metric and spectrum results, images). waiting is thread-seconds idle inside the parallel phases (threads x wall
/// - work; core/stopwatch.h timedParallelFor accounts every phase the same way). references (scene load, reference
/// cache or pass, manifest) and io (CSV and spectrum lines, canonical order, contact sheets) are wall seconds of
/// the serial steps.
struct SweepPhases {
  double setup = 0, trace = 0, splat = 0, resolve = 0, metrics = 0, flip = 0, finish = 0, waiting = 0;
  double references = 0, io = 0;  ///< wall seconds on the main thread (io: waiting for the writer, canonical order)
  double writer = 0;               ///< seconds the writer thread spent on CSV/spectrum lines, overlapped with work
  double motion = 0;               ///< wall seconds of the frames pass (frames > 1, study/sweep/sweep_motion.h)
  /// The references rendered by this run (none from the cache), thread-seconds (study/reference/reference.h ReferenceSet)
  double refTrace = 0, refSplat = 0, refResolve = 0;
  /// The fixed grid's alignment (study/sweep/alignment.h), wall seconds: its offset references (cache or pass) and its
  /// passes over the offsets (the grid traced, reconstructed and measured at each).
  double alignmentReferences = 0, alignment = 0;
};

struct SweepSummary {
  size_t groups = 0;            ///< sample-set groups of this shard
  size_t sampleSetsTraced = 0;  ///< traceSamples calls (one per group and seed, when needed)
  size_t importanceTraces = 0;  ///< traceImportanceSamples calls
  uint64_t primaryRays = 0;     ///< primary rays traced for sample sets (references excluded)
  size_t rowsWritten = 0, rowsSkipped = 0;
  size_t nonFiniteSamples = 0;  ///< NaN / infinite samples left out of this run's images (CSV nonfinite_samples)
  size_t configurations = 0;    ///< rows this shard is responsible for
  bool images = false;          ///< whether images were written
  double seconds = 0;
  std::vector<std::string> notes;  ///< skipped combinations etc.
  SweepPhases phases;
  size_t peakInFlightBytes = 0;    ///< peak task state counted by the scheduler; at most sweepMemoryBound
  std::vector<ContractCheck> contract;  ///< the sampler bounds checked on the whole CSV at the end (study/records/contract.h)
};

}  // namespace aliaslab
