// The convergence experiment's tables (experiments/convergence; docs/science.md,
// "Convergence on analytic integrands"): the RMSE of every sampler at a range
// of N on every integrand of convergence.h, and the fitted log-log slopes set
// beside the slopes theory expects.
//
// Protocol: fill a ConvergenceStudy (every sampler name valid, the fit range
// holding at least two powers of two of convergenceSampleCounts(maxN):
// powersOfTwoInRange counts them), measureConvergence() measures every
// (sampler, N) and returns the rows in sampler, N, integrand order; then
// convergenceCsv() and slopesTable() give the texts of convergence.csv and
// slopes.md. The slope of a (sampler, integrand) is fitted on the powers of
// two with fitMin <= N <= fitMax; "agrees" means within kSlopeTolerance of the
// expected slope.
#pragma once
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace aliaslab {

inline constexpr double kSlopeTolerance = 0.15;  ///< |measured - expected| for the verdict "agrees"

struct ConvergenceStudy {
  std::vector<std::string> samplers;  ///< sampler names, in table order
  int realisations = 256;             ///< independent sets per (sampler, N)
  int maxN = 4096;                    ///< largest N (see convergenceSampleCounts)
  double fitMin = 16, fitMax = 4096;  ///< N range of the slope fit (powers of two only)
  uint64_t seed = 1;                  ///< sampler seed
  int threads = 0;                    ///< 0 = all cores
};

/// One measurement: the RMSE of `sampler` with N = n points on `integrand`.
struct ConvergenceRow {
  std::string sampler, integrand;
  int n = 0;
  double rmse = 0;
};

/// The N measured: the powers of two 1 .. maxN and 3, 10, 48, 100, 1000 (those <= maxN), ascending.
std::vector<int> convergenceSampleCounts(int maxN);

/// How many of `ns` are powers of two with fitMin <= n <= fitMax.
int powersOfTwoInRange(const std::vector<int>& ns, double fitMin, double fitMax);

/// Measures every (sampler, N <= maxN) on every integrand. A sampler that cannot make N points (an
/// OptionError from makeSampler) is skipped at that N with a line on `log`; each sampler's time goes to
/// `log` too.
std::vector<ConvergenceRow> measureConvergence(const ConvergenceStudy& study, std::ostream& log);

/// convergence.csv: "sampler,integrand,n,rmse,realisations" and one line per row.
std::string convergenceCsv(const std::vector<ConvergenceRow>& rows, int realisations);

/// slopes.md: per (sampler, integrand) the fitted slope with its standard error, the expected slope, its
/// source and the verdict, under a paragraph stating the fit.
std::string slopesTable(const ConvergenceStudy& study, const std::vector<ConvergenceRow>& rows);

}  // namespace aliaslab
