// convergence: RMSE against N for every sampler on the analytic integrands
// of docs/science.md, the fitted log-log slopes, and a table comparing them with
// the slopes theory expects.
//
// Output in --out: convergence.csv (sampler,integrand,n,rmse,realisations),
// slopes.md, and (unless --no-chart) convergence.png/.svg drawn by
// analysis/convergence_chart.py.
#include "aliaslab_paths.h"
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "core/cli.h"
#include "study/reference.h"
#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "sampling/sampler.h"
#include "study/config.h"
#include "study/convergence.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {

struct Params {
  std::string out = "results/convergence";  // output folder
  int realisations = 256;                   // independent sets per (sampler, N)
  int maxN = 4096;                          // largest N (powers of two 1 .. maxN, plus a few non-powers)
  double fitMin = 16, fitMax = 4096;        // N range of the slope fit (powers of two only)
  uint64_t seed = 1;                        // sampler seed
  std::vector<std::string> samplers;        // default: every registered sampler
  int threads = 0;                          // 0 = all cores
  bool chart = true;                        // run analysis/convergence_chart.py
};

std::vector<int> sampleCounts(int maxN) {
  std::vector<int> ns;
  for (int n = 1; n <= maxN; n *= 2) ns.push_back(n);
  for (int n : {3, 10, 48, 100, 1000}) if (n <= maxN) ns.push_back(n);
  std::sort(ns.begin(), ns.end());
  return ns;
}

std::string fmt(double v, const char* f = "%.3f") { return formatNumber(v, f); }

}  // namespace

int main(int argc, char** argv) {
  Params p;
  CLI::App app{"convergence: RMSE against N of every sampler on the analytic integrands, with fitted slopes (aliaslab)"};
  setupCommandLine(app, "convergence");
  app.add_option("--out", p.out, "Output folder")->capture_default_str();
  app.add_option("--realisations", p.realisations, "Independent sets per (sampler, N)")->capture_default_str()
      ->check(CLI::Range(2, 1 << 20));
  app.add_option("--max-n", p.maxN, "Largest N")->capture_default_str()->check(CLI::Range(16, 1 << 16));
  auto* fitMinOpt = app.add_option("--fit-min", p.fitMin, "Smallest N in the slope fit (at most --max-n / 2 by default)")
                        ->capture_default_str();
  app.add_option("--fit-max", p.fitMax, "Largest N in the slope fit")->capture_default_str();
  app.add_option("--seed", p.seed, "Sampler seed")->check(kSeed)->capture_default_str();
  app.add_option("--samplers", p.samplers, "Samplers to run (default: all)")->delimiter(',');
  app.add_option("--threads", p.threads, "Threads (0 = all cores)")->capture_default_str();
  app.add_flag("!--no-chart", p.chart, "Skip the chart (analysis/convergence_chart.py)");
  if (const int rc = parseCommandLine(app, argc, argv, "convergence"); rc >= 0) return rc;

  try {
    // Validate everything before work.
    if (p.samplers.empty()) p.samplers = samplerNames();
    for (const auto& s : p.samplers)  // unknown names fail before any work
      relabelOption("--sampler", "--samplers", [&] { makeSampler(s, 1 << 4, p.seed); });
    if (p.threads < 0) throw OptionError("--threads", "must be >= 0, found " + std::to_string(p.threads));
    if (!(std::isfinite(p.fitMin) && p.fitMin >= 1)) throw OptionError("--fit-min", "must be a number >= 1, found " + fmt(p.fitMin, "%g"));
    if (!(std::isfinite(p.fitMax) && p.fitMax >= 1)) throw OptionError("--fit-max", "must be a number >= 1, found " + fmt(p.fitMax, "%g"));
    p.fitMax = std::min<double>(p.fitMax, p.maxN);  // the fit can only use measured N
    if (!fitMinOpt->count()) p.fitMin = std::min<double>(p.fitMin, p.maxN / 2);
    const auto ns = sampleCounts(p.maxN);
    if (std::count_if(ns.begin(), ns.end(), [&](int n) { return (n & (n - 1)) == 0 && n >= p.fitMin && n <= p.fitMax; }) < 2)
      throw OptionError("--fit-min", "the fit range [" + fmt(p.fitMin, "%g") + ", " + fmt(p.fitMax, "%g") +
                                         "] (--fit-max capped at --max-n) holds fewer than two powers of two");
    requireOutputFolders({{p.out, "--out"}});
    const auto& fsList = integrands();

    // Measure: one CSV row per (sampler, integrand, N).
    std::ostringstream csv;
    csv << "sampler,integrand,n,rmse,realisations\n";
    std::map<std::pair<std::string, std::string>, std::pair<std::vector<double>, std::vector<double>>> series;
    for (const auto& s : p.samplers) {
      const auto start = std::chrono::steady_clock::now();
      for (int n : ns) {
        std::unique_ptr<Sampler> sampler;
        try {
          sampler = makeSampler(s, n, p.seed);
        } catch (const OptionError& e) {
          std::cerr << "skipped " << s << " N=" << n << ": " << e.what() << "\n";
          continue;
        }
        const auto rmse = convergenceRmse(*sampler, fsList, p.realisations, p.threads);
        for (size_t i = 0; i < fsList.size(); ++i) {
          csv << s << ',' << fsList[i].name << ',' << n << ',' << fmt(rmse[i], "%.9g") << ',' << p.realisations
              << '\n';
          auto& ser = series[{s, fsList[i].name}];
          ser.first.push_back(n), ser.second.push_back(rmse[i]);
        }
      }
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cerr << s << ": " << fmt(secs, "%.1f") << " s\n";
    }
    writeTextFile((fs::path(p.out) / "convergence.csv").string(), csv.str());

    // Compare fitted slopes with theory.
    std::ostringstream md;
    md << "# Convergence slopes\n\nRMSE of the mean of f over N points against the exact integral, over "
       << p.realisations << " independent sets (pixels) per N, seed " << p.seed << ". Slope: least squares of "
       << "log RMSE on log N over the powers of two with " << fmt(p.fitMin, "%g") << " <= N <= "
       << fmt(p.fitMax, "%g") << " (± its standard error). 'agrees' means |measured - expected| <= 0.15.\n\n"
       << "| sampler | integrand | measured slope | expected | source | verdict |\n"
       << "|---|---|---|---|---|---|\n";
    for (const auto& s : p.samplers)
      for (const auto& f : fsList) {
        const auto& ser = series[{s, f.name}];
        const ExpectedSlope e = expectedSlope(s, f);
        std::string measured = "n/a (fewer than two nonzero points)", verdict = "-";
        try {
          const SlopeFit fit = fitLogLogSlope(ser.first, ser.second, p.fitMin, p.fitMax, true);
          measured = fmt(fit.slope, "%.2f") + " ± " + fmt(fit.slopeError, "%.2f");
          if (e.slope) verdict = std::abs(fit.slope - *e.slope) <= 0.15 ? "agrees" : "differs";
        } catch (const std::invalid_argument&) {
        }
        md << "| " << s << " | " << f.name << " | " << measured << " | "
           << (e.slope ? fmt(*e.slope, "%.2f") : std::string("-")) << " | " << e.source << " | " << verdict
           << " |\n";
      }
    writeTextFile((fs::path(p.out) / "slopes.md").string(), md.str());

    // Chart through the Python plotter (arguments passed as they are: no shell).
    if (p.chart && runProgram({"/usr/bin/python3", std::string(ALIASLAB_SOURCE_DIR) + "/analysis/convergence_chart.py",
                               (fs::path(p.out) / "convergence.csv").string(), "--out", p.out, "--fit-min",
                               fmt(p.fitMin, "%g"), "--fit-max", fmt(p.fitMax, "%g")}) != 0)
      std::cerr << "convergence: warning: the chart failed (analysis/convergence_chart.py); the CSV and slopes.md are written\n";
    std::cout << "wrote " << p.out << "/convergence.csv and slopes.md\n";
  } catch (const InputError& e) {
    std::cerr << "convergence: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "convergence: failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
