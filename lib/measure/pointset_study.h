// The point-set experiment's statistics (experiments/pointsets; docs/science.md,
// "Point-set measures"): per (sampler, N), averages of the measures of
// pointset.h over many independent sets, and the tables made of them.
//
// Protocol: fill a PointSetStudy (every sampler valid at every count), then
// measurePointSets() draws, for each (sampler, N), `sets` independent sets
// (those of pixels (k mod 8, k / 8), k < sets) and returns one PointSetStats
// per pair, sampler-major in the study's order; the pairs are measured in
// parallel and the result does not depend on the thread count. It also
// writes each pair's pictures into a folder: points_<sampler>_<N>.png (the
// set of pixel (0, 0), plotPointSet) and periodogram_<sampler>_<N>.png (the
// mean periodogram, plotPeriodogram, of half-width round(extent sqrt(N))).
// pointSetTableCsv() and pointSetSpectraCsv() give the texts of
// pointsets.csv and spectra.csv.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace aliaslab {

struct PointSetStudy {
  std::vector<std::string> samplers;  ///< sampler names, in table order
  std::vector<int> counts = {16, 64, 256, 1024};  ///< point counts N
  int sets = 64;                      ///< independent sets averaged per (sampler, N)
  double extent = 3.0;                ///< periodogram half-width in units of sqrt(N)
  uint64_t seed = 1;                  ///< sampler seed
  int threads = 0;                    ///< 0 = all cores
};

/// The statistics of one (sampler, N) over the study's sets.
struct PointSetStats {
  std::string sampler;
  std::string warning;  ///< the sampler's warning() at N (empty when none)
  int n = 0;
  double l2Mean = 0, l2Sd = 0;      ///< mean and sample sd of the L2-star discrepancy
  double distMean = 0, distMin = 0;  ///< mean and minimum of the minimum toroidal distance
  std::vector<double> radial;        ///< radialSpectrum of the mean periodogram
};

/// Measures every (sampler, N) of `study`, writing the pictures into `imageFolder` (an existing folder).
std::vector<PointSetStats> measurePointSets(const PointSetStudy& study, const std::string& imageFolder);

/// pointsets.csv: "sampler,n,sets,l2star_mean,l2star_sd,min_dist_mean,min_dist_min,min_dist_norm_mean,warning"
/// (min_dist_norm = distMean / idealPackingDistance(N); commas in the warning become semicolons).
std::string pointSetTableCsv(const std::vector<PointSetStats>& stats, int sets);

/// spectra.csv: "sampler,n,sets,k,k_norm,power", one line per radial frequency k >= 1 (k_norm = k / sqrt(N)).
std::string pointSetSpectraCsv(const std::vector<PointSetStats>& stats, int sets);

}  // namespace aliaslab
