// The sweep: every configuration of a StudyConfig measured into one CSV row per target of the study.
//
// For each (scene, sampler, spp, prefilter) group of this shard, in canonical order:
// the references of every (filter, radius) plus the pixel-area reference and
// every target come from the cache (or are rendered in one pass; each keeps
// its halves' difference); then for each seed
// k = 0 .. K-1 the sample set is traced ONCE (render/render.h traceSamples,
// sampler seed k) and reconstructed from memory with every (filter, radius)
// in the weighted and classic modes, and with the 3x3-binomial supersample
// mode for the uniform sampler at square spp. Importance mode traces its own
// samples per filter (traceImportanceSamples). An adaptive sampler
// (adaptive-<method>:<base>, render/adaptive.h) is traced by traceAdaptive
// instead, and its sample set reconstructed the same way; mean_spp and
// max_spp record the samples it actually spent. Groups with prefilter
// "footprint" trace with a second Tracer of the same scene whose options
// turn pre-filtering on; every reference stays un-prefiltered. Each image goes
// straight into its configuration's RowMeasure (study/sweep/row_measure.h: against
// its own reference and every target at once). When the K seeds are done, the
// group's rows are appended whole (CsvAppender) and, when images are on,
// the seed-0 image, signed error and noise map are written. Each row's
// radial error and noise spectra (measure/spectrum.h; files: study/records/spectrum_files.h) go to
// <csv folder>/spectra/<scene>.csv (<scene>.<csv stem>.csv for shards or a
// --csv path) just before the row, and are put in canonical order at the end.
//
// Threads: the seeds of a group (at most min(seeds, threads) sample sets in
// flight) and each (seed, row) reconstruction run as tasks, folded into the
// rows' accumulators in seed order, so every number and image is the same
// for any thread count (steps and memory bound: docs/sweep_scheduling.md).
//
// The files of the sweep, in the order runSweep uses them: study/config.h
// (validateStudy: the StudyPlan), sweep_rows.h (planRows, finishRow,
// writeRows), sweep_scene.h (the scene's references, startRows),
// sweep_group.h (runGroup: phases A, B, C), group_writer.h (the background
// writer), sweep_memory.h (the memory bound and the in-flight count),
// sweep_summary.h (what the sweep reports). At the end the samplers' variance bounds are checked on the whole
// CSV (study/records/contract.h; SweepSummary::contract), which the program prints, violations as warnings.
//
// Resuming: configurations whose rows (one per target) are all in the CSV are
// skipped (a group whose rows are all present is not traced); one with a
// target row missing is measured again and only its missing rows written. At the end the CSV is
// rewritten in canonical order, so an interrupted-and-resumed run, or merged
// shards, give the same file as one uninterrupted run (timing aside).
#pragma once
#include "study/config.h"
#include "study/sweep/sweep_memory.h"   // sweepMemoryBound: the bound of peakInFlightBytes
#include "study/sweep/sweep_summary.h"  // SweepSummary, SweepPhases

namespace aliaslab {

/// Validates (InputError before any work), then runs the sweep.
SweepSummary runSweep(const StudyConfig& config);

}  // namespace aliaslab
