#include "study/sweep/sweep_group.h"

#include <algorithm>
#include <memory>

#include "core/phase_timer.h"
#include "film/film.h"
#include "render/adaptive/adaptive.h"
#include "render/render.h"
#include "render/sample_source.h"

namespace aliaslab {

namespace {

// The timed steps of a group's tasks (each task's own PhaseTimes, folded into SweepPhases in task order).
enum class Step { Trace, Splat, Resolve, Flip, Count };

// A traced sample set of one seed (phase A's slot).
struct SeedTrace {
  SampleBuffer samples;
  std::unique_ptr<Accumulator> weighted;  ///< every weighted-average row of the set in one pass
  PhaseTimes<Step> times;                 ///< the trace and the Accumulator pass (wall and CPU, inner threads too)
  SpentSamples spent;  ///< samples per pixel actually traced (adaptive samplers vary)
  Image density;       ///< per-pixel sample count (adaptive sampler, seed 0, images on)
};

// One (seed, row) image (phase B's slot), with the thread-seconds of its parts.
struct RowImage {
  Reconstruction r;
  std::vector<double> flip;  ///< per target: meanFlip(image, T), computed in the (seed, row) task
  PhaseTimes<Step> times;    ///< this task's share of the phases (its own trace for importance rows)
  double traceMs = 0, reconMs = 0;
  double cpuMs = 0;  ///< CPU time: the set's trace + this row's reconstruction (its share of the splat pass)
};

size_t bufferBytes(const SampleBuffer& b) { return b.samples().size() * sizeof(FilmSample); }

// The threads one of `tasks` concurrent tasks may use inside itself (results do not depend on it).
int innerThreads(int threads, size_t tasks) { return std::max(1, threads / int(std::max<size_t>(tasks, 1))); }

// Phase A: trace the sample set of seed k once and, when there are weighted-average rows, splat it into one
// Accumulator holding all of them. The sample buffer is kept for the classic and supersample rows.
SeedTrace traceSampleSet(const GroupContext& g, int k, int innerThreads) {
  SeedTrace t;
  const auto source = makeSampleSource(g.group.sampler, g.group.spp, static_cast<uint64_t>(k));
  {
    const ScopedPhase timing(t.times, Step::Trace);
    t.samples = source->trace(g.tracer, g.scene.width, g.scene.height, innerThreads);
  }
  t.spent = spentSamples(t.samples);
  if (k == 0 && g.images && source->adaptive()) t.density = sampleDensity(t.samples);
  g.inFlight.add(bufferBytes(t.samples));
  std::vector<const Filter*> filters;
  for (const PendingRow& p : g.rows)
    if (p.mode == ReconMode::WeightedAverage) filters.push_back(p.filter.filter.get());
  if (!filters.empty()) {
    const ScopedPhase timing(t.times, Step::Splat);
    t.weighted = std::make_unique<Accumulator>(g.scene.width, g.scene.height, filters);
    g.inFlight.add(t.weighted->bytes());
    t.weighted->measureShares();
    t.weighted->add(t.samples, innerThreads);
  }
  return t;
}

// The CSV's timings of row p's image `out` of the set `t`: its trace (the set's, or its own for importance rows),
// its reconstruction (weighted rows: plus its share of the Accumulator pass) and their CPU time.
void rowTimes(const SeedTrace& t, size_t weightedIndex, const PendingRow& p, RowImage& out) {
  const PhaseTimes<Step>& trace = p.mode == ReconMode::ImportanceSampled ? out.times : t.times;
  out.traceMs = 1000 * trace.wall(Step::Trace);
  out.reconMs = 1000 * out.times.wall(Step::Resolve);
  out.cpuMs = 1000 * (trace.cpu(Step::Trace) + out.times.cpu(Step::Resolve));
  if (p.mode != ReconMode::WeightedAverage) return;
  const std::vector<double>& shares = t.weighted->filterSeconds();
  out.reconMs += 1000.0 * shares[weightedIndex];
  // the row's share of the pass's CPU time in the proportion of its share of the wall time
  double all = 0;
  for (double v : shares) all += v;
  const double splatCpuMs = 1000 * t.times.cpu(Step::Splat);
  out.cpuMs += all > 0 ? splatCpuMs * shares[weightedIndex] / all : splatCpuMs / shares.size();
}

// Phase B: row `p`'s image of the set `t` (weighted: resolve from the shared Accumulator; classic and
// supersample: from the sample buffer; importance: its own trace with the row's filter).
RowImage reconstructRow(const GroupContext& g, const SeedTrace& t, size_t weightedIndex, const PendingRow& p, int k,
                        int innerThreads) {
  RowImage out;
  const Filter& filter = *p.filter.filter;
  SampleBuffer own;  // importance rows' own sample set
  if (p.mode == ReconMode::ImportanceSampled) {
    const auto source = makeSampleSource(g.group.sampler, g.group.spp, static_cast<uint64_t>(k));
    const ScopedPhase timing(out.times, Step::Trace);
    own = source->traceImportance(g.tracer, filter, g.scene.width, g.scene.height, innerThreads);
  }
  g.inFlight.add(bufferBytes(own));
  {
    const ScopedPhase timing(out.times, Step::Resolve);
    out.r = p.mode == ReconMode::WeightedAverage ? t.weighted->resolve(weightedIndex)
            : p.mode == ReconMode::ImportanceSampled ? reconstruct(own, filter, p.mode, innerThreads)
                                                      : reconstruct(t.samples, filter, p.mode, innerThreads);
  }
  g.inFlight.remove(bufferBytes(own));
  rowTimes(t, weightedIndex, p, out);
  {
    const ScopedPhase timing(out.times, Step::Flip);
    out.flip = meanFlips(out.r.image, p.flipTargets);  // the image's side of FLIP once for every target
  }
  g.inFlight.add(imageBytes(g.scene.width, g.scene.height));
  return out;
}

// Phase C: row p's images of seeds k0, k0+1, ... added in seed order.
void foldSeeds(const GroupContext& g, PendingRow& p, const std::vector<RowImage*>& seedImages, int k0) {
  for (size_t i = 0; i < seedImages.size(); ++i) {
    RowImage& img = *seedImages[i];
    p.measure->add(img.r.image);
    for (size_t j = 0; j < img.flip.size(); ++j) p.flipSums[j] += img.flip[j];
    p.stats += img.r.stats;
    p.traceMs += img.traceMs / g.config.seeds, p.reconMs += img.reconMs / g.config.seeds;
    p.cpuMs.push_back(img.cpuMs);
    if (g.config.frames > 1) p.frame0.push_back(img.r.image);  // frame 0 of the motion pass: traced once
    if (k0 + int(i) == 0 && g.images) p.seed0 = std::move(img.r.image);
  }
}

// What the window's sample sets spent, folded into the group's in seed order.
void foldSpent(const GroupContext& g, std::vector<SeedTrace>& traces, int k0) {
  const int K = g.config.seeds;
  for (size_t i = 0; i < traces.size(); ++i) {
    const int k = k0 + int(i);
    g.spent.meanSpp = (k == 0 ? 0.0 : g.spent.meanSpp) + traces[i].spent.mean / K;
    g.spent.maxSpp = k == 0 ? traces[i].spent.max : std::max(g.spent.maxSpp, traces[i].spent.max);
    if (k == 0) g.spent.density0 = std::move(traces[i].density);
  }
}

}  // namespace

void runGroup(const GroupContext& g, const std::function<void(double)>& advance) {
  const int K = g.config.seeds;
  const bool shared = std::any_of(g.rows.begin(), g.rows.end(),
                                  [](const PendingRow& p) { return p.mode != ReconMode::ImportanceSampled; });
  std::vector<size_t> weightedIndex(g.rows.size(), 0);
  for (size_t i = 0, w = 0; i < g.rows.size(); ++i)
    if (g.rows[i].mode == ReconMode::WeightedAverage) weightedIndex[i] = w++;
  const int window = std::max(1, std::min(K, g.threads));
  const size_t R = g.rows.size();
  for (int k0 = 0; k0 < K; k0 += window) {
    const int W = std::min(window, K - k0);
    // Phase A: one task per seed.
    std::vector<SeedTrace> traces(W);
    const int innerA = innerThreads(g.threads, W);
    const PhaseTime a = timedParallelFor(shared ? W : 0, g.threads, innerA,
                                         [&](int i) { traces[i] = traceSampleSet(g, k0 + i, innerA); });
    PhaseTimes<Step> times;  // the window's tasks' phases, added in task order
    for (const SeedTrace& t : traces) times += t.times;
    if (shared) {
      g.sum.sampleSetsTraced += W;
      foldSpent(g, traces, k0);
    }
    g.phases.waiting += a.idle;
    // Phase B: one task per (seed, row).
    std::vector<RowImage> images(size_t(W) * R);
    const int innerB = innerThreads(g.threads, images.size());
    const PhaseTime b = timedParallelFor(int(images.size()), g.threads, innerB, [&](int n) {
      const int i = n / int(R);
      const size_t r = size_t(n) % R;
      images[n] = reconstructRow(g, traces[i], weightedIndex[r], g.rows[r], k0 + i, innerB);
    });
    for (size_t n = 0; n < images.size(); ++n) {
      times += images[n].times;
      if (g.rows[n % R].mode == ReconMode::ImportanceSampled) ++g.sum.importanceTraces;
    }
    g.phases.trace += times.wall(Step::Trace), g.phases.splat += times.wall(Step::Splat);
    g.phases.resolve += times.wall(Step::Resolve), g.phases.flip += times.wall(Step::Flip);
    g.phases.waiting += b.idle;
    for (SeedTrace& t : traces) {
      g.inFlight.remove(bufferBytes(t.samples) + (t.weighted ? t.weighted->bytes() : 0));
      t = SeedTrace();
    }
    // Phase C: one task per row, seeds folded in order.
    const PhaseTime c = timedParallelFor(int(R), g.threads, 1, [&](int r) {
      std::vector<RowImage*> seedImages;
      for (int i = 0; i < W; ++i) seedImages.push_back(&images[size_t(i) * R + r]);
      foldSeeds(g, g.rows[r], seedImages, k0);
    });
    g.phases.metrics += c.work, g.phases.waiting += c.idle;
    g.inFlight.remove(images.size() * imageBytes(g.scene.width, g.scene.height));
    advance(W);
  }
}

}  // namespace aliaslab
