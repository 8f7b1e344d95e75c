#include "study/sweep_rows.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/format.h"
#include "core/parallel.h"
#include "study/contact.h"
#include "study/spectrum_files.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
std::string supersampleParams(int spp) {
  const int k = static_cast<int>(std::lround(std::sqrt(spp)));
  return "supersample " + std::to_string(k) + "x" + std::to_string(k) + " sub-pixels, binomial 1-2-1, box";
}

// The row of a configuration before measurement (identifying columns only).
CsvRow templateRow(const StudyConfig& c, const Target& target, const std::string& stem, SceneSize size,
                   const SampleSetGroup& g, const Configuration& cfg) {
  CsvRow r;
  r.scene = stem, r.width = size.width, r.height = size.height;
  r.sampler = g.sampler, r.spp = g.spp;
  r.filter = cfg.filter.spec.first, r.radius = cfg.filter.spec.second;
  r.filterParams = cfg.mode == ReconMode::Supersample ? supersampleParams(g.spp) : cfg.filter.filter->describe();
  r.reconstruction = toString(cfg.mode);
  r.seeds = c.seeds, r.refSpp = c.refSpp, r.threads = resolveThreads(c.threads);
  r.target = target.label;
  r.prefilter = g.prefilter;
  return r;
}
}  // namespace

std::vector<std::vector<PendingRow>> planRows(const StudyConfig& config, const Target& target, const std::string& stem,
                                              SceneSize size, const std::vector<const SampleSetGroup*>& groups,
                                              const CsvAppender* out, std::vector<FilterSpec>& specs, size_t& skipped) {
  std::vector<std::vector<PendingRow>> pending(groups.size());
  for (size_t g = 0; g < groups.size(); ++g)
    for (const Configuration& cfg : groups[g]->configs) {
      PendingRow p;
      p.mode = cfg.mode;
      p.filter = cfg.filter;
      p.row = templateRow(config, target, stem, size, *groups[g], cfg);
      if (out && out->has(csvKey(p.row))) {
        ++skipped;
        continue;
      }
      if (std::find(specs.begin(), specs.end(), cfg.filter.spec) == specs.end()) specs.push_back(cfg.filter.spec);
      pending[g].push_back(std::move(p));
    }
  return pending;
}

void finishRow(PendingRow& p, const fs::path& imageDir, bool images, const GroupSpent& spent, int seeds,
               SpectrumMetrics& sm) {
  const Metrics m = p.metrics->result();
  CsvRow& r = p.row;
  const TargetMetrics& t = m.targets[0];  // the study's target T (startRows), then the area reference A
  r.mse = m.mse, r.aliasing = m.aliasing, r.noise = m.noise, r.mseArea = m.targets[1].mseTarget, r.psnr = m.psnr;
  r.mseTarget = t.mseTarget, r.blur = t.blur, r.cross = t.cross;
  r.mseSe = m.mseSe, r.noiseSe = m.noiseSe, r.aliasingSe = m.aliasingSe, r.mseTargetSe = t.mseTargetSe;
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

void writeRows(const StudyConfig& config, const std::vector<CsvRow>& rows, const std::vector<SpectrumMetrics>& spectra,
               CsvAppender& out, std::set<std::string>& spectraWritten) {
  std::map<std::string, std::vector<std::pair<std::string, const SpectrumMetrics*>>> byFile;
  for (size_t i = 0; i < rows.size(); ++i) {
    const CsvRow& r = rows[i];
    byFile[spectrumCsvPath(csvPath(config), r.scene)].emplace_back(
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

}  // namespace aliaslab
