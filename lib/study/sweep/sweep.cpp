#include "study/sweep/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>

#include "core/files.h"
#include "core/huge_pages.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "study/sweep/alignment.h"
#include "study/sweep/contact.h"
#include "study/records/csv.h"
#include "study/sweep/group_writer.h"
#include "study/records/lock.h"
#include "study/records/spectrum_files.h"
#include "study/records/spectrum_key.h"
#include "study/sweep/sweep_group.h"
#include "study/sweep/sweep_motion.h"
#include "study/sweep/sweep_rows.h"
#include "study/sweep/sweep_scene.h"
#include "study/validate.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {

// The CSV a run appends to (null with refsOnly), checked to hold the same study; then the temporaries of killed
// runs ("*.partial.<pid>.*" whose process is gone) are removed from the output and cache folders.
std::unique_ptr<CsvAppender> openCsv(const StudyConfig& config, const StudyPlan& plan, const std::string& csv) {
  std::unique_ptr<CsvAppender> out;
  if (!config.refsOnly) {
    out = std::make_unique<CsvAppender>(csv, config.frames > 1);
    checkSameStudy(csv, out->resumedLines(), config, plan.targets);
  }
  for (const std::string& dir : {config.out, config.cache})
    if (const size_t n = removeStaleTemporaries(dir))
      std::fprintf(stderr, "note: removed %zu unfinished file(s) left by an interrupted run in %s\n", n, dir.c_str());
  return out;
}

// What the sweep keeps from its first scene to its end: the CSV it resumes and appends to (one run per CSV:
// study/records/lock.h), the count of in-flight task state, the progress bar and the background writer.
struct SweepRun {
  SweepRun(const StudyConfig& c, const StudyPlan& p, SweepSummary& s, size_t groups)
      : config(c), plan(p), sum(s), threads(resolveThreads(c.threads)), csv(csvPath(c)),
        lock(c.refsOnly ? nullptr : std::make_unique<CsvLock>(csv, "sweep")), out(openCsv(c, p, csv)),
        progress(double(groups) * c.seeds, "sweep", c.progress && !c.refsOnly) {}

  const StudyConfig& config;
  const StudyPlan& plan;
  SweepSummary& sum;
  const int threads;  // resolved, >= 1
  const std::string csv;
  std::unique_ptr<CsvLock> lock;
  std::unique_ptr<CsvAppender> out;      // null with refsOnly
  InFlight inFlight;
  ProgressBar progress;                  // one unit per seed of a group
  std::set<std::string> spectraWritten;  // spectrum CSVs to put in canonical order at the end
  GroupWriter writer;                    // last: joined before what its jobs touch (out, spectraWritten) goes
};

// Plan: this shard's groups, the summary's counts, and the notes of the plan on stderr.
std::vector<SampleSetGroup> planShard(const StudyConfig& config, const StudyPlan& plan, SweepSummary& sum) {
  sum.notes = plan.notes;
  for (const std::string& n : sum.notes) std::fprintf(stderr, "note: %s\n", n.c_str());
  std::vector<SampleSetGroup> groups = shardGroups(plan.groups, config.shardIndex, config.shardCount);
  size_t total = 0;
  for (const auto& g : plan.groups) total += g.configs.size();
  sum.groups = groups.size();
  for (const auto& g : groups) sum.configurations += g.configs.size();
  sum.images = config.images ? *config.images : total <= 200;
  return groups;
}

// One group: its rows' accumulators, its seeds (study/sweep/sweep_group.h), its rows finished, then handed to the writer.
void runGroupRows(SweepRun& run, StudyScene& scene, const SampleSetGroup& group, std::vector<PendingRow>& rows,
                  const RowReferences& refs, const MotionReferences& motion, const std::vector<ReferenceSet>& align) {
  if (rows.empty()) {
    run.progress.advance(run.config.seeds);
    return;
  }
  // Pre-filtered groups trace with the same scene and flags, footprints on (1/sqrt(spp) pixels a side);
  // references never do.
  std::optional<Tracer> prefilterTracer;
  if (parsePrefilter(group.prefilter)) {
    TraceOptions options = scene.tracer->options();
    options.prefilter = true;
    options.footprintPixels = 1.f / std::sqrt(static_cast<float>(group.spp));
    prefilterTracer.emplace(scene.scene, *scene.aggregate, options);
  }
  const Tracer& tracer = prefilterTracer ? *prefilterTracer : *scene.tracer;
  SweepPhases& phases = run.sum.phases;
  const PhaseTime setup = startRows(rows, refs, run.threads);
  phases.setup += setup.work, phases.waiting += setup.idle;

  GroupSpent spent{double(group.spp), group.spp, Image()};
  const GroupContext ctx{run.config, scene, group, tracer, rows, run.threads, run.sum.images, run.inFlight, phases,
                         run.sum, spent};
  const uint64_t rays0 = tracer.counters().total().primary;
  runGroup(ctx, [&](double u) { run.progress.advance(u); });
  if (run.config.frames > 1) {  // the frames: every seed's F frames into each row's motion columns
    const Stopwatch frames;
    measureGroupMotion(run.config, scene, tracer, group, rows, motion, run.plan.targets, run.threads);
    phases.motion += frames.seconds();
  }
  if (group.sampler == kFixedGridSampler && !align.empty()) {  // the grid at every camera offset
    const Stopwatch offsets;
    measureGroupAlignment(scene, tracer, group, rows, align, run.threads);
    phases.alignment += offsets.seconds();
  }
  run.sum.primaryRays += tracer.counters().total().primary - rays0;

  // Results and images one task per row, then the CSV lines in row order on the writer's thread.
  const fs::path imageDir = fs::path(run.config.out) / "images" / scene.stem;
  if (run.sum.images) fs::create_directories(imageDir);
  std::vector<SpectrumMetrics> spectra(rows.size());
  const PhaseTime finish = timedParallelFor(int(rows.size()), run.threads, 1, [&](int i) {
    finishRow(rows[i], run.plan.targets, refs.areaIndex(), imageDir, run.sum.images, spent, run.config.seeds,
              spectra[i]);
  });
  phases.finish += finish.work, phases.waiting += finish.idle;
  std::vector<std::vector<CsvRow>> csvRows;
  size_t written = 0;
  for (PendingRow& p : rows) {
    if (!p.rows.empty()) run.sum.nonFiniteSamples += static_cast<size_t>(p.rows.front().nonFiniteSamples);
    written += p.rows.size(), csvRows.push_back(std::move(p.rows));
  }
  phases.io += run.writer.submit([&config = run.config, csvRows = std::move(csvRows), spectra = std::move(spectra),
                                  out = run.out.get(), &written = run.spectraWritten] {
    writeRows(config, csvRows, spectra, *out, written);
  });
  run.sum.rowsWritten += written;
}

// A resumed scene's spectra: configurations whose rows the CSV holds but whose spectra are not whole (a kill or a
// full disk during their write) are measured again; the file is put in canonical order at the end either way.
void resumeSpectra(SweepRun& run, const std::string& stem) {
  const std::string path = spectrumCsvPath(run.csv, stem);
  std::error_code ec;
  // No file at all is not a kill's doing (the file is created before the scene's first rows): a CSV copied or
  // edited without its spectra. Its rows are kept; a merge of it is refused (study/records/spectrum_files.h).
  if (!fs::exists(path, ec)) return;
  // Configurations with some lines but not whole ones: a kill or a full disk in their write. (A configuration with
  // no line at all and rows in the CSV is not a kill's doing either: the spectra are written before the rows.)
  std::set<std::string> present;
  const std::set<std::string> done = completeSpectra(path, &present);
  std::set<std::string> lost;
  for (const std::string& line : run.out->resumedLines()) {
    const auto f = splitCsvLine(line);
    if (!isStudyRow(f) || f[csvColumn("scene")] != stem) continue;
    if (done.count(spectrumKeyOfCsvRow(f)) || !present.count(spectrumKeyOfCsvRow(f))) continue;
    lost.insert(spectrumKeyOfCsvRow(f));
    run.out->forget(csvKey(f));
  }
  if (!lost.empty())
    std::fprintf(stderr, "note: %s lacks the whole spectra of %zu configuration(s) the CSV holds; measuring them again\n",
                 path.c_str(), lost.size());
  run.spectraWritten.insert(path);
}

// One scene (its groups): the rows still missing, the scene built and its references, then each group.
void runScene(SweepRun& run, const std::vector<const SampleSetGroup*>& groups) {
  const Stopwatch clock;
  const StudyConfig& config = run.config;
  const std::string& path = groups.front()->scene;
  const std::string stem = fs::path(path).stem().string();
  const SceneSize size = run.plan.sceneSizes.at(path);  // read by validateStudy from the render line
  if (run.out) checkSameSceneSize(run.csv, run.out->resumedLines(), stem, size.width, size.height);

  std::vector<StudyFilter> specs{run.plan.area};  // the area, every target, then the rows' (filter, radius)
  for (const Target& t : run.plan.targets) addFilterOnce(specs, t.filter);
  run.sum.phases.io += run.writer.wait();  // `out`'s keys are read by planRows and added to by the writer
  if (run.out) resumeSpectra(run, stem);
  auto pending = planRows(config, run.plan.targets, stem, size, groups, run.out.get(), specs, run.sum.rowsSkipped);
  bool any = config.refsOnly;
  for (const auto& p : pending) any = any || !p.empty();
  if (!any) {
    run.progress.advance(double(groups.size()) * config.seeds);
    return;
  }
  // The scene's acceleration structure and tracer: built once, here.
  const auto scene = loadStudyScene(path, config.width, config.height, config.maxSize, config.longSide);
  const ReferenceSet refs = sceneReferences(config, *scene, specs, referenceOptions(config), run.sum.images);
  auto countReferences = [&p = run.sum.phases](const ReferenceSet& r) {
    p.refTrace += r.traceSeconds, p.refSplat += r.splatSeconds, p.refResolve += r.resolveSeconds;
  };
  countReferences(refs);
  // With frames: every later frame's target references too, and the targets' own shimmer (study/sweep/sweep_motion.h).
  MotionReferences motion;
  if (config.frames > 1) {
    std::vector<StudyFilter> targetFilters;
    for (const Target& t : run.plan.targets) addFilterOnce(targetFilters, t.filter);
    const std::vector<ReferenceSet> later = frameReferences(config, *scene, targetFilters, referenceOptions(config));
    for (const ReferenceSet& r : later) countReferences(r);
    motion = motionReferences(config, refs, later, run.plan.targets);
  }
  run.sum.phases.references += clock.seconds();
  // The fixed grid's alignment: the targets' references at every camera offset (study/sweep/alignment.h).
  bool grid = false;
  for (size_t g = 0; g < groups.size(); ++g)
    grid = grid || (groups[g]->sampler == kFixedGridSampler && (config.refsOnly || !pending[g].empty()));
  std::vector<ReferenceSet> align;
  if (grid && config.alignOffsets > 0) {
    const Stopwatch offsets;
    std::vector<StudyFilter> targets;
    for (const Target& t : run.plan.targets) targets.push_back(t.filter);
    align = alignmentReferences(config, *scene, targets, alignmentReferenceOptions(config));
    run.sum.phases.alignmentReferences += offsets.seconds();
  }
  if (config.refsOnly) return;
  const RowReferences rowRefs(refs, run.plan.targets);
  for (size_t g = 0; g < groups.size(); ++g) runGroupRows(run, *scene, *groups[g], pending[g], rowRefs, motion, align);
}

// The groups of `groups` from `first` that share its scene (groups come scene by scene).
std::vector<const SampleSetGroup*> sceneGroups(const std::vector<SampleSetGroup>& groups, size_t first) {
  std::vector<const SampleSetGroup*> out;
  for (size_t g = first; g < groups.size() && groups[g].scene == groups[first].scene; ++g) out.push_back(&groups[g]);
  return out;
}

// Finish: the writer joined, the CSV and spectra in canonical order, contact sheets from the finished rows.
void finishSweep(SweepRun& run) {
  run.progress.finish();
  const Stopwatch clock;
  run.writer.wait();
  run.sum.phases.writer = run.writer.seconds();
  if (run.out) {
    run.out.reset();
    canonicaliseCsv(run.csv);
    run.sum.contract = checkContract(contractRows(run.csv));  // every row of the CSV, resumed ones too
    for (const std::string& spectra : run.spectraWritten) canonicaliseSpectrumCsv(spectra);
    if (run.sum.images) writeContactSheets(run.csv, (fs::path(run.config.out) / "images").string());
  }
  run.sum.phases.io += clock.seconds();
  run.sum.peakInFlightBytes = run.inFlight.peak();
}

}  // namespace

SweepSummary runSweep(const StudyConfig& config) {
  keepMediumBlocks();  // core/huge_pages.h: a row's image freed per window is not returned to the kernel
  const StudyPlan plan = validateStudy(config);  // InputError before any work; filters built, sizes read
  const Stopwatch clock;
  SweepSummary sum;
  const std::vector<SampleSetGroup> groups = planShard(config, plan, sum);
  SweepRun run(config, plan, sum, groups.size());
  try {
    for (size_t gi = 0; gi < groups.size();) {
      const auto scene = sceneGroups(groups, gi);  // per scene: its references, then each group run and written
      runScene(run, scene);
      gi += scene.size();
    }
  } catch (...) {  // a refusal after the CSV was opened (e.g. a scene rendering to NaN) leaves no header-only CSV
    try {
      run.writer.wait();
    } catch (...) {  // the first error is the one reported
    }
    if (run.out) run.out->discardIfUnused();
    throw;
  }
  finishSweep(run);
  sum.seconds = clock.seconds();
  return sum;
}

}  // namespace aliaslab
