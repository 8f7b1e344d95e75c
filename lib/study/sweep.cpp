#include "study/sweep.h"

#include "study/flip.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include "core/format.h"
#include "core/files.h"
#include "core/parallel.h"
#include "filter/filter.h"
#include "render/adaptive.h"
#include "render/render.h"
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

// One configuration in flight: its row, filter, reference and running metrics.
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
  const Image* flipTarget = nullptr;  ///< what the flip column compares against (the pixel-area reference for now)
  double flipSum = 0;                 ///< sum over the seeds of meanFlip(I_k, *flipTarget)
};

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

// The per-scene spectrum CSV (study/spectrum.h) beside the study CSV: <csv folder>/spectra/<scene>.csv, or
// <scene>.<csv stem>.csv when the CSV is not the default study.csv (shards, --csv), so shards never share one.
std::string spectrumPath(const StudyConfig& c, const std::string& scene) {
  const fs::path csv(csvPath(c));
  const std::string stem = csv.filename() == "study.csv" ? "" : "." + csv.stem().string();
  return (csv.parent_path() / "spectra" / (scene + stem + ".csv")).string();
}

ReferenceOptions referenceOptions(const StudyConfig& c) {
  ReferenceOptions o;
  o.spp = c.refSpp, o.sampler = c.refSampler, o.batchSpp = c.refBatch, o.threads = c.threads;
  o.progress = c.progress;
  return o;
}
}  // namespace

size_t countConfigurations(const StudyConfig& config) {
  size_t n = 0;
  for (const SampleSetGroup& g : expandStudy(config)) n += g.configs.size();
  return n;
}

SweepSummary runSweep(const StudyConfig& config) {
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
  const int threads = config.threads;
  const ReferenceOptions refOpts = referenceOptions(config);
  const auto [targetFilter, targetRadius] = parseTarget(config.target);
  const FilterSpec targetSpec{targetFilter, targetRadius};

  // Work units for the progress bar: one per traced sample set.
  double units = 0;
  std::vector<double> groupUnits;
  for (const auto& g : groups) {
    size_t importance = 0;
    for (const auto& c : g.configs) importance += c.mode == ReconMode::ImportanceSampled;
    groupUnits.push_back(config.seeds * (1.0 + importance));
    units += groupUnits.back();
  }
  ProgressBar progress(units, "sweep", config.progress && !config.refsOnly);

  std::set<std::string> spectraWritten;  // spectrum CSVs to put in canonical order at the end
  for (size_t gi = 0; gi < groups.size();) {
    // One scene at a time: load it and its references once.
    const std::string scenePath = groups[gi].scene;
    size_t gend = gi;
    while (gend < groups.size() && groups[gend].scene == scenePath) ++gend;
    const auto scene = loadStudyScene(scenePath, config.width, config.height, config.maxSize, config.longSide);
    if (out) checkSameSceneSize(csv, out->resumedLines(), scene->stem, scene->width, scene->height);

    // Which configurations are still missing from the CSV?
    std::vector<std::vector<Pending>> pending(gend - gi);
    std::vector<FilterSpec> specs{kArea};
    if (targetSpec != kArea) specs.push_back(targetSpec);
    for (size_t g = gi; g < gend; ++g)
      for (const Configuration& cfg : groups[g].configs) {
        Pending p;
        p.mode = cfg.mode;
        p.filter = makeFilter(cfg.filter, static_cast<float>(cfg.radius));
        p.row = templateRow(config, *scene, groups[g], cfg, *p.filter);
        if (out && out->has(csvKey(p.row))) {
          ++sum.rowsSkipped;
          continue;
        }
        const FilterSpec spec{cfg.filter, cfg.radius};
        if (std::find(specs.begin(), specs.end(), spec) == specs.end()) specs.push_back(spec);
        pending[g - gi].push_back(std::move(p));
      }
    bool any = config.refsOnly;
    for (const auto& p : pending) any = any || !p.empty();
    if (!any) {
      for (size_t g = gi; g < gend; ++g) progress.advance(groupUnits[g]);
      gi = gend;
      continue;
    }

    // References: cached, or rendered together in one pass.
    const ReferenceSet refs = cachedReferences(*scene, specs, refOpts, config.cache);
    std::map<FilterSpec, const ReferenceImage*> refOf;
    for (size_t i = 0; i < specs.size(); ++i) refOf[specs[i]] = &refs.images[i];
    const ReferenceImage& area = *refOf.at(kArea);
    const ReferenceImage& target = *refOf.at(targetSpec);
    const fs::path imageDir = fs::path(config.out) / "images" / scene->stem;
    if (!config.refsOnly) {
      // each image as a path from the manifest's folder to the cached EXR
      const fs::path manifests = fs::path(config.out) / "references";
      std::vector<std::string> names;
      for (const auto& r : refs.images)
        names.push_back((fs::absolute(fs::path(config.cache) / (r.key + ".exr")).lexically_normal())
                            .lexically_relative(fs::absolute(manifests).lexically_normal())
                            .string());
      fs::create_directories(manifests);
      writeTextFile((fs::path(config.out) / "references" / (scene->stem + ".json")).string(),
                    referenceManifest(*scene, refs, names));
      if (sum.images) {
        fs::create_directories(imageDir);
        writeImage((imageDir / "reference-area.png").string(), area.image);
      }
    }
    if (config.refsOnly) {
      gi = gend;
      continue;
    }

    for (size_t g = gi; g < gend; ++g) {
      const SampleSetGroup& group = groups[g];
      // Pre-filtered groups trace with the same scene and flags, footprints on
      // (1/sqrt(spp) pixels a side); references never do.
      TraceOptions prefilterOptions = scene->tracer->options();
      prefilterOptions.prefilter = true;
      prefilterOptions.footprintPixels = 1.f / std::sqrt(static_cast<float>(group.spp));
      const Tracer prefilterTracer(scene->scene, *scene->aggregate, prefilterOptions);
      const Tracer& tracer = parsePrefilter(group.prefilter) ? prefilterTracer : *scene->tracer;
      auto& rows = pending[g - gi];
      double advanced = 0;
      auto step = [&] { progress.advance(1), advanced += 1; };
      if (rows.empty()) {
        progress.advance(groupUnits[g]);
        continue;
      }
      for (Pending& p : rows) {
        p.reference = p.mode == ReconMode::Supersample ? &area : refOf.at({p.row.filter, p.row.radius});
        p.metrics = std::make_unique<MetricAccumulator>(p.reference->image, area.image, target.image);
        p.spectrum = std::make_unique<SpectrumAccumulator>(p.reference->image);
        p.flipTarget = &target.image;
      }
      bool shared = false;
      for (const Pending& p : rows) shared = shared || p.mode != ReconMode::ImportanceSampled;
      // adaptive samplers (render/adaptive.h) trace their own sample set; samples actually spent per pixel
      const bool adaptive = isAdaptiveSamplerName(group.sampler);
      double meanSpp = group.spp;
      int maxSpp = group.spp;
      Image density0;

      // K seeds: trace each sample set once, reconstruct it with every filter.
      for (int k = 0; k < config.seeds; ++k) {
        const auto sampler = adaptive ? nullptr : makeSampler(group.sampler, group.spp, static_cast<uint64_t>(k));
        auto keep = [&](Pending& p, Reconstruction&& r, double traceMs, double reconMs) {
          p.metrics->add(r.image);
          p.spectrum->add(r.image);
          p.flipSum += meanFlip(r.image, *p.flipTarget);
          p.stats += r.stats;
          p.traceMs += traceMs / config.seeds, p.reconMs += reconMs / config.seeds;
          if (k == 0 && sum.images) p.seed0 = std::move(r.image);
        };
        if (shared) {
          const uint64_t rays0 = tracer.counters().total().primary;
          auto t0 = Clock::now();
          const SampleBuffer samples =
              adaptive ? traceAdaptive(tracer, *makeAdaptiveSampler(group.sampler, group.spp, uint64_t(k)),
                                       scene->width, scene->height, threads)
                       : traceSamples(tracer, *sampler, scene->width, scene->height, threads);
          const double traceMs = msSince(t0);
          const SpentSamples spent = spentSamples(samples);
          meanSpp = (k == 0 ? 0.0 : meanSpp) + spent.mean / config.seeds;
          maxSpp = k == 0 ? spent.max : std::max(maxSpp, spent.max);
          if (k == 0 && adaptive && sum.images) density0 = sampleDensity(samples);
          sum.primaryRays += tracer.counters().total().primary - rays0;
          ++sum.sampleSetsTraced;
          // weighted-average rows in one Accumulator pass (shared footprints per radius), the rest one by one
          std::vector<Pending*> weighted;
          std::vector<const Filter*> filters;
          for (Pending& p : rows)
            if (p.mode == ReconMode::WeightedAverage) weighted.push_back(&p), filters.push_back(p.filter.get());
          if (!weighted.empty()) {
            Accumulator acc(scene->width, scene->height, filters);
            std::vector<double> seconds;
            acc.add(samples, threads, &seconds);
            for (size_t i = 0; i < weighted.size(); ++i) {
              t0 = Clock::now();
              Reconstruction r = acc.resolve(i);
              keep(*weighted[i], std::move(r), traceMs, 1000.0 * seconds[i] + msSince(t0));
            }
          }
          for (Pending& p : rows) {
            if (p.mode == ReconMode::ImportanceSampled || p.mode == ReconMode::WeightedAverage) continue;
            t0 = Clock::now();
            Reconstruction r = reconstruct(samples, *p.filter, p.mode, threads);
            keep(p, std::move(r), traceMs, msSince(t0));
          }
          step();
        }
        for (Pending& p : rows) {
          if (p.mode != ReconMode::ImportanceSampled) continue;
          const uint64_t rays0 = tracer.counters().total().primary;
          auto t0 = Clock::now();
          const SampleBuffer samples =
              traceImportanceSamples(tracer, *sampler, *p.filter, scene->width, scene->height, threads);
          const double traceMs = msSince(t0);
          sum.primaryRays += tracer.counters().total().primary - rays0;
          ++sum.importanceTraces;
          t0 = Clock::now();
          Reconstruction r = reconstruct(samples, *p.filter, p.mode, threads);
          keep(p, std::move(r), traceMs, msSince(t0));
          step();
        }
      }

      // Rows (and images) of the group.
      for (Pending& p : rows) {
        const Metrics m = p.metrics->result();
        CsvRow& r = p.row;
        r.mse = m.mse, r.aliasing = m.aliasing, r.noise = m.noise, r.mseArea = m.mseArea, r.psnr = m.psnr;
        r.mseTarget = m.mseTarget, r.blur = m.blur, r.cross = m.cross;
        r.mseSe = m.mseSe, r.noiseSe = m.noiseSe, r.aliasingSe = m.aliasingSe, r.mseTargetSe = m.mseTargetSe;
        r.refError = p.reference->error;
        r.flip = p.flipSum / config.seeds;
        r.flagged = m.mse < 4.0 * p.reference->error ? 1 : 0;
        r.nanPixels = static_cast<long long>(p.stats.nanPixels);
        r.negativePixels = static_cast<long long>(p.stats.negativePixels);
        r.undefinedPixels = static_cast<long long>(p.stats.undefinedPixels);
        r.traceMs = p.traceMs, r.reconstructMs = p.reconMs;
        const SpectrumMetrics sm = p.spectrum->result();
        r.lowfreqError = sm.lowfreqError, r.lowfreqErrorSe = sm.lowfreqErrorSe, r.blurredMse = sm.blurredMse;
        {  // spectra first: a row in the study CSV always has its spectra (a repeat is dropped at the end)
          const std::string spectra = spectrumPath(config, r.scene);
          fs::create_directories(fs::path(spectra).parent_path());
          appendSpectrumCsv(spectra, r.scene + ',' + r.sampler + ',' + std::to_string(r.spp) + ',' + r.filter + ',' +
                                         formatNumber(r.radius, "%.9g") + ',' + r.reconstruction + ',' + r.prefilter, sm);
          spectraWritten.insert(spectra);
        }
        r.meanSpp = meanSpp, r.maxSpp = maxSpp;
        if (sum.images) {
          fs::create_directories(imageDir);
          writeConfigurationImages(imageDir.string(), configurationImageBase(r), p.seed0, p.reference->image,
                                   p.metrics->noiseMap(), density0);
        }
        out->append(r);
        ++sum.rowsWritten;
        p.metrics.reset(), p.spectrum.reset(), p.seed0 = Image();  // a finished row's K images and sums are not needed again
      }
      progress.advance(std::max(0.0, groupUnits[g] - advanced));
    }
    gi = gend;
  }
  progress.finish();

  // Canonical order, then contact sheets from the finished rows.
  if (out) {
    out.reset();
    canonicaliseCsv(csv);
    for (const std::string& spectra : spectraWritten) canonicaliseSpectrumCsv(spectra);
    if (sum.images) writeContactSheets(csv, (fs::path(config.out) / "images").string());
  }
  sum.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return sum;
}

}  // namespace aliaslab
