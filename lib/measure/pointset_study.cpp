#include "measure/pointset_study.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/format.h"
#include "core/image.h"
#include "core/parallel.h"
#include "measure/pointset.h"
#include "sampling/sampler.h"

namespace aliaslab {

namespace {
std::string fmt(double v) { return formatNumber(v, "%.6g"); }

std::string picturePath(const std::string& folder, const std::string& kind, const PointSetStats& r) {
  return (std::filesystem::path(folder) / (kind + "_" + r.sampler + "_" + std::to_string(r.n) + ".png")).string();
}
}  // namespace

std::vector<PointSetStats> measurePointSets(const PointSetStudy& study, const std::string& imageFolder) {
  // One job per (sampler, N); each writes only its own result and pictures.
  const size_t counts = study.counts.size();
  std::vector<PointSetStats> results(study.samplers.size() * counts);
  parallelFor(static_cast<int>(results.size()), study.threads, [&](int job) {
    PointSetStats& r = results[job];
    r.sampler = study.samplers[job / counts];
    r.n = study.counts[job % counts];
    auto sampler = makeSampler(r.sampler, r.n, study.seed);
    r.warning = sampler->warning();
    Periodogram pg(static_cast<int>(std::lround(study.extent * std::sqrt(double(r.n)))));
    std::vector<Vec2> pts(r.n);
    double l2 = 0, l2sq = 0;
    r.distMin = 1e300;
    for (int k = 0; k < study.sets; ++k) {
      sampler->generate(k % 8, k / 8, pts.data());
      const double d = l2StarDiscrepancy(pts), md = minToroidalDistance(pts);
      l2 += d, l2sq += d * d, r.distMean += md, r.distMin = std::min(r.distMin, md);
      pg.add(pts);
      if (k == 0) writeImage(picturePath(imageFolder, "points", r), plotPointSet(pts, r.n > 256 ? 512 : 320));
    }
    r.l2Mean = l2 / study.sets;
    r.l2Sd = study.sets > 1 ? std::sqrt(std::max(0.0, (l2sq - l2 * l2 / study.sets) / (study.sets - 1))) : 0.0;
    r.distMean /= study.sets;
    r.radial = radialSpectrum(pg);
    writeImage(picturePath(imageFolder, "periodogram", r), plotPeriodogram(pg));
  });
  return results;
}

std::string pointSetTableCsv(const std::vector<PointSetStats>& stats, int sets) {
  std::ostringstream table;
  table << "sampler,n,sets,l2star_mean,l2star_sd,min_dist_mean,min_dist_min,min_dist_norm_mean,warning\n";
  for (const PointSetStats& r : stats) {
    std::string warning = r.warning;
    std::replace(warning.begin(), warning.end(), ',', ';');
    table << r.sampler << ',' << r.n << ',' << sets << ',' << fmt(r.l2Mean) << ',' << fmt(r.l2Sd) << ','
          << fmt(r.distMean) << ',' << fmt(r.distMin) << ',' << fmt(r.distMean / idealPackingDistance(r.n)) << ','
          << warning << '\n';
  }
  return table.str();
}

std::string pointSetSpectraCsv(const std::vector<PointSetStats>& stats, int sets) {
  std::ostringstream spectra;
  spectra << "sampler,n,sets,k,k_norm,power\n";
  for (const PointSetStats& r : stats)
    for (size_t k = 1; k < r.radial.size(); ++k)
      spectra << r.sampler << ',' << r.n << ',' << sets << ',' << k << ',' << fmt(k / std::sqrt(double(r.n))) << ','
              << fmt(r.radial[k]) << '\n';
  return spectra.str();
}

}  // namespace aliaslab
