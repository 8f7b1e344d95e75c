#include "study/sweep.h"

#include "study/flip.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <atomic>

#include "core/format.h"
#include "core/huge_pages.h"
#include "core/files.h"
#include "core/parallel.h"
#include "filter/filter.h"
#include "render/adaptive.h"
#include "render/render.h"
#include "render/sample_source.h"
#include "sampling/sampler.h"
#include "study/contact.h"
#include "study/csv.h"
#include "study/lock.h"
#include "study/metrics.h"
#include "study/progress.h"
#include "study/reference.h"
#include "study/spectrum.h"
#include "study/study_scene.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

const FilterSpec kArea{"box", 0.5};

std::string supersampleParams(int spp) {
  const int k = static_cast<int>(std::lround(std::sqrt(spp)));
  return "supersample " + std::to_string(k) + "x" + std::to_string(k) + " sub-pixels, binomial 1-2-1, box";
}

// The row of a configuration before measurement (identifying columns only).
CsvRow templateRow(const StudyConfig& c, const StudyScene& s, const SampleSetGroup& g, const Configuration& cfg,
                   const Filter& filter) {
  CsvRow r;
  r.scene = s.stem, r.width = s.width, r.height = s.height;
  r.sampler = g.sampler, r.spp = g.spp;
  r.filter = cfg.filter, r.radius = cfg.radius;
  r.filterParams = cfg.mode == ReconMode::Supersample ? supersampleParams(g.spp) : filter.describe();
  r.reconstruction = toString(cfg.mode);
  r.seeds = c.seeds, r.refSpp = c.refSpp, r.threads = resolveThreads(c.threads);
  r.target = targetLabel(c.target);
  r.prefilter = g.prefilter;
  return r;
}

// The per-scene spectrum CSV beside the study CSV (study/spectrum.h spectrumCsvPath).
std::string spectrumPath(const StudyConfig& c, const std::string& scene) { return spectrumCsvPath(csvPath(c), scene); }

ReferenceOptions referenceOptions(const StudyConfig& c) {
  ReferenceOptions o;
  o.spp = c.refSpp, o.sampler = c.refSampler, o.batchSpp = c.refBatch, o.threads = c.threads;
  o.progress = c.progress;
  return o;
}



// ---------------------------------------------------------------------------
// The steps of the sweep, in the order runSweep calls them:
//   planScene        which rows of a scene are still missing (resume), each with its filter built once
//   sceneReferences  the references those rows need (cache or one pass), manifest, reference-area.png
//   runGroup         one (scene, sampler, spp) group, seeds in windows of at most `threads` sample sets:
//     traceSampleSet   phase A, one task per seed: "trace this sample set" (+ the shared Accumulator pass)
//     reconstructRow   phase B, one task per (seed, row): that row's image of that seed
//     foldSeeds        phase C, one task per row: the window's images added to its metrics IN SEED ORDER
//   finishRow          one task per row at the end of its group: "row finished" (metrics, spectra, images)
//   writeRows          serial: the group's spectra and CSV lines, in row order, one write each
// Every task writes only its own slot; slots are folded in (seed, row) order, so nothing depends on which
// thread ran what or when it finished (tests/sweep_parallel_test.cpp runs the tasks in a shuffled order).
// ---------------------------------------------------------------------------

// One configuration (row) in flight: its row, filter (built once, here), reference and running metrics.
struct Pending {
  CsvRow row;
  ReconMode mode;
  std::unique_ptr<Filter> filter;
  const ReferenceImage* reference = nullptr;
  std::unique_ptr<MetricAccumulator> metrics;
  std::unique_ptr<SpectrumAccumulator> spectrum;
  ReconStats stats;
  double traceMs = 0, reconMs = 0;
  Image seed0;
  const FlipReference* flipTarget = nullptr;  ///< what the flip column compares against (the study's target)
  double flipSum = 0;                         ///< sum over the seeds of meanFlip(I_k, target), in seed order
};

// What an adaptive sampler actually spent in a group (mean over seeds of the mean spp, max over seeds),
// folded in seed order; a fixed-count sampler spends exactly its spp.
struct GroupSpent {
  double meanSpp;
  int maxSpp;
  Image density0;  ///< seed 0's samples per pixel (adaptive samplers, images on)
};

// A traced sample set of one seed (phase A's slot).
struct SeedTrace {
  SampleBuffer samples;
  std::unique_ptr<Accumulator> weighted;  ///< every weighted-average row of the set in one pass
  std::vector<double> splatSeconds;       ///< per weighted row, its share of the Accumulator pass
  double traceMs = 0, splatS = 0;
  SpentSamples spent;  ///< samples per pixel actually traced (adaptive samplers vary)
  Image density;       ///< per-pixel sample count (adaptive sampler, seed 0, images on)
};

// One (seed, row) image (phase B's slot).
struct RowImage {
  Reconstruction r;
  double flip = 0;  ///< meanFlip(image, target), computed in the (seed, row) task
  double traceMs = 0, reconMs = 0;
};

// The scheduler's count of in-flight task state (sample sets, accumulators, images), and its peak.
class InFlight {
 public:
  void add(size_t bytes) {
    const size_t now = bytes_.fetch_add(bytes) + bytes;
    size_t peak = peak_.load();
    while (now > peak && !peak_.compare_exchange_weak(peak, now)) {
    }
  }
  void remove(size_t bytes) { bytes_.fetch_sub(bytes); }
  size_t peak() const { return peak_.load(); }

 private:
  std::atomic<size_t> bytes_{0}, peak_{0};
};

size_t imageBytes(int w, int h) { return size_t(w) * h * 3 * sizeof(float); }
size_t bufferBytes(const SampleBuffer& b) { return b.samples().size() * sizeof(FilmSample); }

struct GroupContext {
  const StudyConfig& config;
  const StudyScene& scene;
  const SampleSetGroup& group;
  const Tracer& tracer;  ///< the scene's tracer, or its pre-filtering twin for prefilter=footprint groups
  std::vector<Pending>& rows;
  int threads;  ///< resolved, >= 1
  bool images;
  InFlight& inFlight;
  SweepPhases& phases;
  SweepSummary& sum;
  GroupSpent& spent;
};

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Phase A: trace the sample set of seed k once and, when there are weighted-average rows, splat it into one
// Accumulator holding all of them. The sample buffer is kept for the classic and supersample rows.
SeedTrace traceSampleSet(const GroupContext& g, int k, int innerThreads) {
  SeedTrace t;
  auto t0 = Clock::now();
  const auto source = makeSampleSource(g.group.sampler, g.group.spp, static_cast<uint64_t>(k));
  t.samples = source->trace(g.tracer, g.scene.width, g.scene.height, innerThreads);
  t.traceMs = msSince(t0);
  t.spent = spentSamples(t.samples);
  if (k == 0 && g.images && source->adaptive()) t.density = sampleDensity(t.samples);
  g.inFlight.add(bufferBytes(t.samples));
  std::vector<const Filter*> filters;
  for (const Pending& p : g.rows)
    if (p.mode == ReconMode::WeightedAverage) filters.push_back(p.filter.get());
  if (!filters.empty()) {
    t0 = Clock::now();
    t.weighted = std::make_unique<Accumulator>(g.scene.width, g.scene.height, filters);
    g.inFlight.add(t.weighted->bytes());
    t.weighted->add(t.samples, innerThreads, &t.splatSeconds);
    t.splatS = secondsSince(t0);
  }
  return t;
}

// Phase B: row `p`'s image of the set `t` (weighted: resolve from the shared Accumulator; classic and
// supersample: from the sample buffer; importance: its own trace with the row's filter).
RowImage reconstructRow(const GroupContext& g, const SeedTrace& t, size_t weightedIndex, const Pending& p, int k,
                        int innerThreads, double* traceS, double* resolveS, double* flipS) {
  RowImage out;
  if (p.mode == ReconMode::ImportanceSampled) {
    const auto source = makeSampleSource(g.group.sampler, g.group.spp, static_cast<uint64_t>(k));
    auto t0 = Clock::now();
    const SampleBuffer samples = source->traceImportance(g.tracer, *p.filter, g.scene.width, g.scene.height,
                                                         innerThreads);
    out.traceMs = msSince(t0);
    *traceS += out.traceMs / 1000;
    g.inFlight.add(bufferBytes(samples));
    t0 = Clock::now();
    out.r = reconstruct(samples, *p.filter, p.mode, innerThreads);
    out.reconMs = msSince(t0);
    *resolveS += out.reconMs / 1000;
    g.inFlight.remove(bufferBytes(samples));
  } else {
    const auto t0 = Clock::now();
    out.r = p.mode == ReconMode::WeightedAverage ? t.weighted->resolve(weightedIndex)
                                                 : reconstruct(t.samples, *p.filter, p.mode, innerThreads);
    out.traceMs = t.traceMs;
    out.reconMs = msSince(t0);
    *resolveS += out.reconMs / 1000;
    if (p.mode == ReconMode::WeightedAverage) out.reconMs += 1000.0 * t.splatSeconds[weightedIndex];
  }
  const auto tf = Clock::now();
  out.flip = p.flipTarget->mean(out.r.image);
  *flipS += secondsSince(tf);
  g.inFlight.add(imageBytes(g.scene.width, g.scene.height));
  return out;
}

// Phase C: row p's images of seeds k0, k0+1, ... added in seed order.
void foldSeeds(const GroupContext& g, Pending& p, std::vector<RowImage*> seedImages, int k0) {
  for (size_t i = 0; i < seedImages.size(); ++i) {
    RowImage& img = *seedImages[i];
    p.metrics->add(img.r.image);
    p.spectrum->add(img.r.image);
    p.flipSum += img.flip;
    p.stats += img.r.stats;
    p.traceMs += img.traceMs / g.config.seeds, p.reconMs += img.reconMs / g.config.seeds;
    if (k0 + int(i) == 0 && g.images) p.seed0 = std::move(img.r.image);
  }
}

// The threads one of `tasks` concurrent tasks may use inside itself (results do not depend on it).
int innerThreads(int threads, size_t tasks) { return std::max(1, threads / int(std::max<size_t>(tasks, 1))); }

// Runs the K seeds of one group, at most `threads` sample sets in flight at a time.
void runGroup(const GroupContext& g, const std::function<void(double)>& advance) {
  const int K = g.config.seeds;
  const bool shared = std::any_of(g.rows.begin(), g.rows.end(),
                                  [](const Pending& p) { return p.mode != ReconMode::ImportanceSampled; });
  std::vector<size_t> weightedIndex(g.rows.size(), 0);
  for (size_t i = 0, w = 0; i < g.rows.size(); ++i)
    if (g.rows[i].mode == ReconMode::WeightedAverage) weightedIndex[i] = w++;
  const int window = std::max(1, std::min(K, g.threads));
  const size_t R = g.rows.size();
  for (int k0 = 0; k0 < K; k0 += window) {
    const int W = std::min(window, K - k0);
    // Phase A: one task per seed.
    std::vector<SeedTrace> traces(W);
    std::vector<double> busyA(W, 0);
    auto t0 = Clock::now();
    if (shared)
      parallelFor(W, g.threads, [&](int i) {
        const auto t = Clock::now();
        traces[i] = traceSampleSet(g, k0 + i, innerThreads(g.threads, W));
        busyA[i] = secondsSince(t) * innerThreads(g.threads, W);
      });
    double wallA = secondsSince(t0), busy = 0;
    for (int i = 0; i < W; ++i) {
      busy += busyA[i];
      g.phases.trace += traces[i].traceMs / 1000, g.phases.splat += traces[i].splatS;
    }
    if (shared) {
      g.sum.sampleSetsTraced += W;
      for (int i = 0; i < W; ++i) {  // in seed order
        const int k = k0 + i;
        g.spent.meanSpp = (k == 0 ? 0.0 : g.spent.meanSpp) + traces[i].spent.mean / K;
        g.spent.maxSpp = k == 0 ? traces[i].spent.max : std::max(g.spent.maxSpp, traces[i].spent.max);
        if (k == 0) g.spent.density0 = std::move(traces[i].density);
      }
    }
    g.phases.waiting += std::max(0.0, wallA * g.threads - busy);
    // Phase B: one task per (seed, row).
    std::vector<RowImage> images(size_t(W) * R);
    std::vector<double> traceB(images.size(), 0), resolveB(images.size(), 0), flipB(images.size(), 0),
        busyB(images.size(), 0);
    const int inner = innerThreads(g.threads, images.size());
    t0 = Clock::now();
    parallelFor(int(images.size()), g.threads, [&](int n) {
      const auto t = Clock::now();
      const int i = n / int(R);
      const size_t r = size_t(n) % R;
      images[n] = reconstructRow(g, traces[i], weightedIndex[r], g.rows[r], k0 + i, inner, &traceB[n], &resolveB[n],
                                 &flipB[n]);
      busyB[n] = secondsSince(t) * inner;
    });
    const double wallB = secondsSince(t0);
    busy = 0;
    for (size_t n = 0; n < images.size(); ++n) {
      busy += busyB[n], g.phases.trace += traceB[n], g.phases.resolve += resolveB[n], g.phases.flip += flipB[n];
      if (g.rows[n % R].mode == ReconMode::ImportanceSampled) ++g.sum.importanceTraces;
    }
    g.phases.waiting += std::max(0.0, wallB * g.threads - busy);
    for (SeedTrace& t : traces) {
      g.inFlight.remove(bufferBytes(t.samples) + (t.weighted ? t.weighted->bytes() : 0));
      t = SeedTrace();
    }
    // Phase C: one task per row, seeds folded in order.
    std::vector<double> busyC(R, 0);
    t0 = Clock::now();
    parallelFor(int(R), g.threads, [&](int r) {
      const auto t = Clock::now();
      std::vector<RowImage*> seedImages;
      for (int i = 0; i < W; ++i) seedImages.push_back(&images[size_t(i) * R + r]);
      foldSeeds(g, g.rows[r], seedImages, k0);
      busyC[r] = secondsSince(t);
    });
    const double wallC = secondsSince(t0);
    busy = 0;
    for (double b : busyC) busy += b, g.phases.metrics += b;
    g.phases.waiting += std::max(0.0, wallC * g.threads - busy);
    g.inFlight.remove(images.size() * imageBytes(g.scene.width, g.scene.height));
    advance(W);
  }
}

// "Row finished": a configuration's metrics into its CSV row, its spectra, and (images on) its images.
// One task per row (each writes only its own files); the CSV and spectra lines are written by writeRows.
void finishRow(Pending& p, const fs::path& imageDir, bool images, const GroupSpent& spent, int seeds,
               SpectrumMetrics& sm) {
  const Metrics m = p.metrics->result();
  CsvRow& r = p.row;
  r.mse = m.mse, r.aliasing = m.aliasing, r.noise = m.noise, r.mseArea = m.mseArea, r.psnr = m.psnr;
  r.mseTarget = m.mseTarget, r.blur = m.blur, r.cross = m.cross;
  r.mseSe = m.mseSe, r.noiseSe = m.noiseSe, r.aliasingSe = m.aliasingSe, r.mseTargetSe = m.mseTargetSe;
  r.refError = p.reference->error;
  r.flip = p.flipSum / seeds;
  r.meanSpp = spent.meanSpp, r.maxSpp = spent.maxSpp;
  r.flagged = m.mse < 4.0 * p.reference->error ? 1 : 0;
  r.nanPixels = static_cast<long long>(p.stats.nanPixels);
  r.negativePixels = static_cast<long long>(p.stats.negativePixels);
  r.undefinedPixels = static_cast<long long>(p.stats.undefinedPixels);
  r.traceMs = p.traceMs, r.reconstructMs = p.reconMs;
  sm = p.spectrum->result();
  r.lowfreqError = sm.lowfreqError, r.lowfreqErrorSe = sm.lowfreqErrorSe, r.blurredMse = sm.blurredMse;
  if (images)
    writeConfigurationImages(imageDir.string(), configurationImageBase(r), p.seed0, p.reference->image,
                             p.metrics->noiseMap(), spent.density0);
  p.metrics.reset(), p.spectrum.reset(), p.seed0 = Image();  // a finished row's K images and sums are not needed again
}

// A finished group's rows, in row order: spectra first (a row in the study CSV always has its spectra; a
// repeat is dropped at the end), then the CSV rows, each file with one write (the CSV with one fsync).
// Runs on the GroupWriter's thread: it gets copies and touches only the files, `out` and `spectraWritten`.
void writeRows(const StudyConfig& config, const std::vector<CsvRow>& rows, const std::vector<SpectrumMetrics>& spectra,
               CsvAppender& out, std::set<std::string>& spectraWritten) {
  std::map<std::string, std::vector<std::pair<std::string, const SpectrumMetrics*>>> byFile;
  for (size_t i = 0; i < rows.size(); ++i) {
    const CsvRow& r = rows[i];
    byFile[spectrumPath(config, r.scene)].emplace_back(
        r.scene + ',' + r.sampler + ',' + std::to_string(r.spp) + ',' + r.filter + ',' +
            formatNumber(r.radius, "%.9g") + ',' + r.reconstruction + ',' + r.prefilter,
        &spectra[i]);
  }
  for (const auto& [path, lines] : byFile) {
    fs::create_directories(fs::path(path).parent_path());
    appendSpectrumCsv(path, lines);
    spectraWritten.insert(path);
  }
  out.append(rows);
}

// Writes finished groups on one background thread while the next group computes, in submission order. At
// most one group is in the writer: submit() first waits for the previous one (and rethrows its error), so
// an interrupted run loses at most the group being written besides the one computing; both are recomputed
// on resume (a torn CSV tail is cut). Declared after what its jobs touch, so it is joined before they go.
class GroupWriter {
 public:
  ~GroupWriter() {
    if (job_.valid()) job_.wait();
  }
  /// Waits for the write in progress; returns the main thread's seconds spent waiting. Rethrows its error.
  double wait() {
    if (!job_.valid()) return 0;
    const auto t0 = Clock::now();
    job_.get();
    return secondsSince(t0);
  }
  double submit(std::function<void()> job) {
    const double waited = wait();
    job_ = std::async(std::launch::async, [job = std::move(job), this] {
      const auto t0 = Clock::now();
      job();
      seconds_ += secondsSince(t0);  // read only after wait()
    });
    return waited;
  }
  /// Seconds the writer spent writing (off the critical path); read after wait().
  double seconds() const { return seconds_; }

 private:
  std::future<void> job_;
  double seconds_ = 0;
};

// Resume: the rows of groups [gi, gend) (one scene) still missing from the CSV; adds the (filter, radius) of
// each to `specs` (the references to render).
std::vector<std::vector<Pending>> planScene(const StudyConfig& config, const StudyScene& scene,
                                            const std::vector<SampleSetGroup>& groups, size_t gi, size_t gend,
                                            const CsvAppender* out, std::vector<FilterSpec>& specs,
                                            SweepSummary& sum) {
  std::vector<std::vector<Pending>> pending(gend - gi);
  for (size_t g = gi; g < gend; ++g)
    for (const Configuration& cfg : groups[g].configs) {
      Pending p;
      p.mode = cfg.mode;
      p.filter = makeFilter(cfg.filter, static_cast<float>(cfg.radius));
      p.row = templateRow(config, scene, groups[g], cfg, *p.filter);
      if (out && out->has(csvKey(p.row))) {
        ++sum.rowsSkipped;
        continue;
      }
      const FilterSpec spec{cfg.filter, cfg.radius};
      if (std::find(specs.begin(), specs.end(), spec) == specs.end()) specs.push_back(spec);
      pending[g - gi].push_back(std::move(p));
    }
  return pending;
}

// The references of `specs` (cache or one pass), their manifest and, with images on, reference-area.png.
ReferenceSet sceneReferences(const StudyConfig& config, const StudyScene& scene, const std::vector<FilterSpec>& specs,
                             const ReferenceOptions& refOpts, bool images) {
  ReferenceSet refs = cachedReferences(scene, specs, refOpts, config.cache);
  if (config.refsOnly) return refs;
  // each image as a path from the manifest's folder to the cached EXR
  const fs::path manifests = fs::path(config.out) / "references";
  std::vector<std::string> names;
  for (const auto& r : refs.images)
    names.push_back((fs::absolute(fs::path(config.cache) / (r.key + ".exr")).lexically_normal())
                        .lexically_relative(fs::absolute(manifests).lexically_normal())
                        .string());
  fs::create_directories(manifests);
  writeTextFile((manifests / (scene.stem + ".json")).string(), referenceManifest(scene, refs, names));
  if (images) {
    const fs::path imageDir = fs::path(config.out) / "images" / scene.stem;
    fs::create_directories(imageDir);
    writeImage((imageDir / "reference-area.png").string(), refs.images[0].image);  // specs[0] is the area
  }
  return refs;
}
}  // namespace

size_t countConfigurations(const StudyConfig& config) {
  size_t n = 0;
  for (const SampleSetGroup& g : expandStudy(config)) n += g.configs.size();
  return n;
}

size_t sweepMemoryBound(int threads, int width, int height, int spp, size_t rowsPerGroup, size_t weightedRows,
                        int seeds) {
  const size_t W = size_t(std::max(1, std::min(seeds, resolveThreads(threads))));
  const size_t T = size_t(resolveThreads(threads));
  const size_t pixels = size_t(width) * height;
  const size_t buffer = pixels * spp * sizeof(FilmSample);
  const size_t accumulator = pixels * (weightedRows + 1) * 4 * sizeof(double);
  // W sample sets with their accumulators, W x rows images, and up to `threads` importance traces at once
  return W * (buffer + accumulator + rowsPerGroup * imageBytes(width, height)) + T * buffer;
}

SweepSummary runSweep(const StudyConfig& config) {
  keepMediumBlocks();  // core/huge_pages.h: a row's image freed per window is not returned to the kernel
  validateStudy(config);
  validateReferenceOptions(referenceOptions(config));
  const auto start = Clock::now();
  SweepSummary sum;
  const auto all = expandStudy(config, &sum.notes);
  for (const std::string& n : sum.notes) std::fprintf(stderr, "note: %s\n", n.c_str());
  const auto groups = shardGroups(all, config.shardIndex, config.shardCount);
  size_t total = 0;
  for (const auto& g : all) total += g.configs.size();
  sum.groups = groups.size();
  for (const auto& g : groups) sum.configurations += g.configs.size();
  sum.images = config.images ? *config.images : total <= 200;

  const std::string csv = csvPath(config);
  std::unique_ptr<CsvLock> lock;
  std::unique_ptr<CsvAppender> out;
  if (!config.refsOnly) {
    lock = std::make_unique<CsvLock>(csv, "sweep");  // one run per CSV (study/lock.h)
    out = std::make_unique<CsvAppender>(csv);
    checkSameStudy(csv, out->resumedLines(), config);
  }
  // Temporaries of killed runs ("*.partial.<pid>.*" whose process is gone).
  for (const std::string& dir : {config.out, config.cache})
    if (const size_t n = removeStaleTemporaries(dir))
      std::fprintf(stderr, "note: removed %zu unfinished file(s) left by an interrupted run in %s\n", n, dir.c_str());
  const int threads = resolveThreads(config.threads);
  const ReferenceOptions refOpts = referenceOptions(config);
  const auto [targetFilter, targetRadius] = parseTarget(config.target);
  const FilterSpec targetSpec{targetFilter, targetRadius};
  InFlight inFlight;

  // Work units for the progress bar: one per seed of a group.
  double units = 0;
  std::vector<double> groupUnits;
  for (size_t g = 0; g < groups.size(); ++g) {
    groupUnits.push_back(config.seeds);
    units += groupUnits.back();
  }
  ProgressBar progress(units, "sweep", config.progress && !config.refsOnly);

  std::set<std::string> spectraWritten;  // spectrum CSVs to put in canonical order at the end
  GroupWriter writer;                    // after `out` and `spectraWritten`: joined before they are destroyed
  for (size_t gi = 0; gi < groups.size();) {
    // One scene at a time: load it and its references once.
    auto t0 = Clock::now();
    const std::string scenePath = groups[gi].scene;
    size_t gend = gi;
    while (gend < groups.size() && groups[gend].scene == scenePath) ++gend;
    const auto scene = loadStudyScene(scenePath, config.width, config.height, config.maxSize, config.longSide);
    if (out) checkSameSceneSize(csv, out->resumedLines(), scene->stem, scene->width, scene->height);

    std::vector<FilterSpec> specs{kArea};
    if (targetSpec != kArea) specs.push_back(targetSpec);
    sum.phases.io += writer.wait();  // `out`'s keys are read by planScene and added to by the writer
    auto pending = planScene(config, *scene, groups, gi, gend, out.get(), specs, sum);
    bool any = config.refsOnly;
    for (const auto& p : pending) any = any || !p.empty();
    if (!any) {
      for (size_t g = gi; g < gend; ++g) progress.advance(groupUnits[g]);
      gi = gend;
      continue;
    }
    const ReferenceSet refs = sceneReferences(config, *scene, specs, refOpts, sum.images);
    sum.phases.references += secondsSince(t0);
    if (config.refsOnly) {
      gi = gend;
      continue;
    }
    std::map<FilterSpec, const ReferenceImage*> refOf;
    for (size_t i = 0; i < specs.size(); ++i) refOf[specs[i]] = &refs.images[i];
    const ReferenceImage& area = *refOf.at(kArea);
    const ReferenceImage& target = *refOf.at(targetSpec);
    const fs::path imageDir = fs::path(config.out) / "images" / scene->stem;
    const FlipReference flipTarget(target.image);  // prepared once per scene, shared by every (seed, row) task

    for (size_t g = gi; g < gend; ++g) {
      const SampleSetGroup& group = groups[g];
      // Pre-filtered groups trace with the same scene and flags, footprints on
      // (1/sqrt(spp) pixels a side); references never do.
      std::optional<Tracer> prefilterTracer;  // built only for the groups that pre-filter
      if (parsePrefilter(group.prefilter)) {
        TraceOptions options = scene->tracer->options();
        options.prefilter = true;
        options.footprintPixels = 1.f / std::sqrt(static_cast<float>(group.spp));
        prefilterTracer.emplace(scene->scene, *scene->aggregate, options);
      }
      const Tracer& tracer = prefilterTracer ? *prefilterTracer : *scene->tracer;
      auto& rows = pending[g - gi];
      if (rows.empty()) {
        progress.advance(groupUnits[g]);
        continue;
      }
      // Each row's accumulators (the spectrum's transforms the reference): one task per row.
      {
        const auto ts = Clock::now();
        std::vector<double> busy(rows.size(), 0);
        parallelFor(int(rows.size()), threads, [&](int i) {
          const auto t = Clock::now();
          Pending& p = rows[i];
          p.reference = p.mode == ReconMode::Supersample ? &area : refOf.at({p.row.filter, p.row.radius});
          p.metrics = std::make_unique<MetricAccumulator>(p.reference->image, area.image, target.image);
          p.spectrum = std::make_unique<SpectrumAccumulator>(p.reference->image);
          p.flipTarget = &flipTarget;
          busy[i] = secondsSince(t);
        });
        double work = 0;
        for (double b : busy) work += b;
        sum.phases.setup += work, sum.phases.waiting += std::max(0.0, secondsSince(ts) * threads - work);
      }
      GroupSpent spent{double(group.spp), group.spp, Image()};
      const GroupContext ctx{config, *scene, group, tracer, rows, threads, sum.images, inFlight, sum.phases, sum, spent};
      const uint64_t rays0 = tracer.counters().total().primary;
      runGroup(ctx, [&](double u) { progress.advance(u); });
      sum.primaryRays += tracer.counters().total().primary - rays0;
      // Rows (and images) of the group: results and images one task per row, then the CSV lines in row order.
      t0 = Clock::now();
      if (sum.images) fs::create_directories(imageDir);
      std::vector<SpectrumMetrics> spectra(rows.size());
      std::vector<double> busy(rows.size(), 0);
      parallelFor(int(rows.size()), threads, [&](int i) {
        const auto t = Clock::now();
        finishRow(rows[i], imageDir, sum.images, spent, config.seeds, spectra[i]);
        busy[i] = secondsSince(t);
      });
      const double wallFinish = secondsSince(t0);
      double work = 0;
      for (double b : busy) work += b;
      sum.phases.finish += work, sum.phases.waiting += std::max(0.0, wallFinish * threads - work);
      std::vector<CsvRow> csvRows;
      for (const Pending& p : rows) csvRows.push_back(p.row);
      sum.phases.io += writer.submit([&config, csvRows = std::move(csvRows), spectra = std::move(spectra),
                                      out = out.get(), &spectraWritten] {
        writeRows(config, csvRows, spectra, *out, spectraWritten);
      });
      sum.rowsWritten += rows.size();
    }
    gi = gend;
  }
  progress.finish();

  // Canonical order, then contact sheets from the finished rows.
  const auto t0 = Clock::now();
  writer.wait();
  sum.phases.writer = writer.seconds();
  if (out) {
    out.reset();
    canonicaliseCsv(csv);
    for (const std::string& spectra : spectraWritten) canonicaliseSpectrumCsv(spectra);
    if (sum.images) writeContactSheets(csv, (fs::path(config.out) / "images").string());
  }
  sum.phases.io += secondsSince(t0);
  sum.peakInFlightBytes = inFlight.peak();
  sum.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return sum;
}

}  // namespace aliaslab
