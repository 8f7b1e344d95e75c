#include "study/sweep/sweep_rows.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/parallel.h"
#include "filter/filter.h"
#include "study/sweep/contact.h"
#include "study/records/spectrum_files.h"
#include "study/records/spectrum_key.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
/// Mean over the seeds and its standard error (sd over the seeds / sqrt K; NaN for K < 2).
void cpuMeanAndSe(const std::vector<double>& v, double& mean, double& se) {
  const double k = double(v.size());
  mean = 0, se = NAN;
  for (double x : v) mean += x / k;
  if (v.size() < 2) return;
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  se = std::sqrt(ss / (k - 1) / k);
}

std::string supersampleParams(int spp) {
  const int k = static_cast<int>(std::lround(std::sqrt(spp)));
  return "supersample " + std::to_string(k) + "x" + std::to_string(k) + " sub-pixels, binomial 1-2-1, box";
}

// The row of a configuration before measurement (identifying columns only).
CsvRow templateRow(const StudyConfig& c, const std::string& stem, SceneSize size,
                   const SampleSetGroup& g, const Configuration& cfg) {
  CsvRow r;
  r.scene = stem, r.width = size.width, r.height = size.height;
  r.sampler = g.sampler, r.spp = g.spp;
  r.filter = cfg.filter.spec.first, r.radius = cfg.filter.spec.second;
  r.filterParams = cfg.mode == ReconMode::Supersample ? supersampleParams(g.spp) : cfg.filter.filter->describe();
  r.reconstruction = toString(cfg.mode);
  r.seeds = c.seeds, r.refSpp = c.refSpp, r.threads = resolveThreads(c.threads);
  r.prefilter = g.prefilter;
  r.naturalRadius = defaultFilterRadius(r.filter);
  return r;
}
}  // namespace

std::vector<std::vector<PendingRow>> planRows(const StudyConfig& config, const std::vector<Target>& targets,
                                              const std::string& stem, SceneSize size,
                                              const std::vector<const SampleSetGroup*>& groups, const CsvAppender* out,
                                              std::vector<StudyFilter>& specs, size_t& skipped) {
  std::vector<std::vector<PendingRow>> pending(groups.size());
  for (size_t g = 0; g < groups.size(); ++g)
    for (const Configuration& cfg : groups[g]->configs) {
      PendingRow p;
      p.mode = cfg.mode;
      p.filter = cfg.filter;
      p.row = templateRow(config, stem, size, *groups[g], cfg);
      bool any = false;
      for (const Target& t : targets) {
        CsvRow keyed = p.row;
        keyed.target = t.label;
        if (config.frames > 1) keyed.motion = MotionColumns{config.frames, config.motionDx, config.motionDy};  // its key
        p.missing.push_back(!out || !out->has(csvKey(keyed)));
        any = any || p.missing.back();
        skipped += p.missing.back() ? 0 : 1;
      }
      if (!any) continue;
      addFilterOnce(specs, cfg.filter);
      pending[g].push_back(std::move(p));
    }
  return pending;
}

void finishRow(PendingRow& p, const std::vector<Target>& targets, size_t areaIndex, const fs::path& imageDir,
               bool images, const GroupSpent& spent, int seeds, SpectrumMetrics& sm) {
  const RowResult result = p.measure->result();
  const Metrics& m = result.metrics;
  CsvRow base = p.row;
  base.mse = m.mse, base.aliasing = m.aliasing, base.noise = m.noise, base.psnr = m.psnr;
  base.mseArea = m.targets[areaIndex].mseTarget;
  base.mseSe = m.mseSe, base.noiseSe = m.noiseSe, base.aliasingSe = m.aliasingSe;
  base.refError = m.refVar;
  base.deterministic = m.deterministic ? 1 : 0;
  base.meanSpp = spent.meanSpp, base.maxSpp = spent.maxSpp;
  base.nanPixels = static_cast<long long>(p.stats.nanPixels);
  base.negativePixels = static_cast<long long>(p.stats.negativePixels);
  base.undefinedPixels = static_cast<long long>(p.stats.undefinedPixels);
  base.nonFiniteSamples = static_cast<long long>(p.stats.nonFiniteSamples);
  base.traceMs = p.traceMs, base.reconstructMs = p.reconMs;
  cpuMeanAndSe(p.cpuMs, base.cpuMs, base.cpuMsSe);
  sm = result.spectrum;
  base.lowfreqErrorOwn = sm.lowfreqError, base.lowfreqErrorOwnSe = sm.lowfreqErrorSe;
  base.blurredMseOwn = sm.blurredMse;
  p.rows.clear();
  for (size_t j = 0; j < targets.size(); ++j) {
    if (!p.missing[j]) continue;
    const TargetMetrics& t = m.targets[j];
    const SpectrumTargetMetrics& st = sm.targets[j];
    CsvRow r = base;
    r.target = targets[j].label;
    r.mseTarget = t.mseTarget, r.mseTargetSe = t.mseTargetSe, r.blur = t.blur, r.blurSe = t.blurSe, r.cross = t.cross;
    r.targetRefError = t.refVar;
    r.mseTargetSeeds = t.perSeed;
    r.lowfreqError = st.lowfreqError, r.lowfreqErrorSe = st.lowfreqErrorSe, r.blurredMse = st.blurredMse;
    r.blurRatio = st.blurRatio, r.blurRatioSe = st.blurRatioSe;
    r.flip = p.flipSums[j] / seeds;
    r.flagged = r.mseTarget < 2.0 * r.mseTargetSe ? 1 : 0;
    if (!p.motion.empty()) r.motion = p.motion[j];
    if (!p.align.empty()) r.align = p.align[j];
    p.rows.push_back(std::move(r));
  }
  if (images)
    writeConfigurationImages(imageDir.string(), configurationImageBase(base), p.seed0, p.reference->image,
                             p.measure->noiseMap(), spent.density0);
  p.measure.reset(), p.seed0 = Image();  // a finished configuration's K images and sums are not needed again
}

void writeRows(const StudyConfig& config, const std::vector<std::vector<CsvRow>>& rows,
               const std::vector<SpectrumMetrics>& spectra, CsvAppender& out, std::set<std::string>& spectraWritten) {
  std::map<std::string, std::vector<std::pair<std::string, const SpectrumMetrics*>>> byFile;
  std::vector<CsvRow> all;
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].empty()) continue;
    const CsvRow& r = rows[i].front();
    byFile[spectrumCsvPath(csvPath(config), r.scene)].emplace_back(spectrumKeyOfRow(r), &spectra[i]);
    all.insert(all.end(), rows[i].begin(), rows[i].end());
  }
  for (const auto& [path, lines] : byFile) {
    fs::create_directories(fs::path(path).parent_path());
    appendSpectrumCsv(path, lines);
    spectraWritten.insert(path);
  }
  out.append(all);
}

}  // namespace aliaslab
