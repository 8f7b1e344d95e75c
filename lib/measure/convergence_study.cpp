#include "measure/convergence_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/error.h"
#include "core/format.h"
#include "measure/convergence.h"
#include "sampling/sampler.h"

namespace aliaslab {

namespace {
std::string fmt(double v, const char* f) { return formatNumber(v, f); }
}  // namespace

std::vector<int> convergenceSampleCounts(int maxN) {
  std::vector<int> ns;
  for (int n = 1; n <= maxN; n *= 2) ns.push_back(n);
  for (int n : {3, 10, 48, 100, 1000})
    if (n <= maxN) ns.push_back(n);
  std::sort(ns.begin(), ns.end());
  return ns;
}

int powersOfTwoInRange(const std::vector<int>& ns, double fitMin, double fitMax) {
  return static_cast<int>(
      std::count_if(ns.begin(), ns.end(), [&](int n) { return (n & (n - 1)) == 0 && n >= fitMin && n <= fitMax; }));
}

std::vector<ConvergenceRow> measureConvergence(const ConvergenceStudy& study, std::ostream& log) {
  const auto& fs = integrands();
  const auto ns = convergenceSampleCounts(study.maxN);
  std::vector<ConvergenceRow> rows;
  for (const auto& s : study.samplers) {
    const auto start = std::chrono::steady_clock::now();
    for (int n : ns) {
      std::unique_ptr<Sampler> sampler;
      try {
        sampler = makeSampler(s, n, study.seed);
      } catch (const OptionError& e) {
        log << "skipped " << s << " N=" << n << ": " << e.message() << "\n";
        continue;
      }
      const auto rmse = convergenceRmse(*sampler, fs, study.realisations, study.threads);
      for (size_t i = 0; i < fs.size(); ++i) rows.push_back({s, fs[i].name, n, rmse[i]});
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log << s << ": " << fmt(secs, "%.1f") << " s\n";
  }
  return rows;
}

std::string convergenceCsv(const std::vector<ConvergenceRow>& rows, int realisations) {
  std::ostringstream csv;
  csv << "sampler,integrand,n,rmse,realisations\n";
  for (const ConvergenceRow& r : rows)
    csv << r.sampler << ',' << r.integrand << ',' << r.n << ',' << formatReal(r.rmse) << ',' << realisations << '\n';
  return csv.str();
}

std::string slopesTable(const ConvergenceStudy& study, const std::vector<ConvergenceRow>& rows) {
  // (sampler, integrand) -> (N, RMSE) in measurement order
  std::map<std::pair<std::string, std::string>, std::pair<std::vector<double>, std::vector<double>>> series;
  for (const ConvergenceRow& r : rows) {
    auto& ser = series[{r.sampler, r.integrand}];
    ser.first.push_back(r.n), ser.second.push_back(r.rmse);
  }
  std::ostringstream md;
  md << "# Convergence slopes\n\nRMSE of the mean of f over N points against the exact integral, over "
     << study.realisations << " independent sets (pixels) per N, seed " << study.seed << ". Slope: least squares of "
     << "log RMSE on log N over the powers of two with " << fmt(study.fitMin, "%g") << " <= N <= "
     << fmt(study.fitMax, "%g") << " (± its standard error). 'agrees' means |measured - expected| <= "
     << fmt(kSlopeTolerance, "%g") << ".\n\n"
     << "| sampler | integrand | measured slope | expected | source | verdict |\n"
     << "|---|---|---|---|---|---|\n";
  for (const auto& s : study.samplers)
    for (const auto& f : integrands()) {
      const auto& ser = series[{s, f.name}];
      const ExpectedSlope e = expectedSlope(s, f);
      std::string measured = "n/a (fewer than two nonzero points)", verdict = "-";
      try {
        const SlopeFit fit = fitLogLogSlope(ser.first, ser.second, study.fitMin, study.fitMax, true);
        measured = fmt(fit.slope, "%.2f") + " ± " + fmt(fit.slopeError, "%.2f");
        if (e.slope) verdict = std::abs(fit.slope - *e.slope) <= kSlopeTolerance ? "agrees" : "differs";
      } catch (const std::invalid_argument&) {
      }
      md << "| " << s << " | " << f.name << " | " << measured << " | "
         << (e.slope ? fmt(*e.slope, "%.2f") : std::string("-")) << " | " << e.source << " | " << verdict << " |\n";
    }
  return md.str();
}

}  // namespace aliaslab
