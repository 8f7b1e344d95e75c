// pointsets: point-set measures of every sampler at a few counts.
//
// For each (sampler, N) it draws --sets independent sets (the sets of pixels
// (k mod 8, k / 8), k < sets) and writes to --out:
//   pointsets.csv  sampler,n,sets,l2star_mean,l2star_sd,min_dist_mean,
//                  min_dist_min,min_dist_norm_mean,warning
//                  (min_dist_norm = min toroidal distance / sqrt(2 / (sqrt(3) N)))
//   spectra.csv    sampler,n,sets,k,k_norm,power  (radial mean periodogram;
//                  k in cycles per unit, k_norm = k / sqrt(N))
//   points_<sampler>_<N>.png       the set of pixel (0, 0)
//   periodogram_<sampler>_<N>.png  mean 2-D periodogram, DC at the centre,
//                  grey = 0.5 + 0.25 log2 P (P = 1, white noise, is mid-grey)
// and (unless --no-chart) spectra.png/.svg via analysis/pointset_chart.py.
#include "aliaslab_paths.h"
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/cli.h"
#include "study/reference.h"
#include "core/error.h"
#include "core/image.h"
#include "core/parallel.h"
#include "core/files.h"
#include "core/format.h"
#include "sampling/sampler.h"
#include "study/config.h"
#include "study/pointset.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {

struct Params {
  std::string out = "results/pointsets";  // output folder
  std::vector<int> counts = {16, 64, 256, 1024};
  int sets = 64;                      // independent sets averaged per (sampler, N)
  double extent = 3.0;                // periodogram half-width in units of sqrt(N)
  uint64_t seed = 1;                  // sampler seed
  std::vector<std::string> samplers;  // default: every registered sampler
  int threads = 0;                    // 0 = all cores
  bool chart = true;                  // run analysis/pointset_chart.py
};

struct Result {
  std::string sampler, warning;
  int n = 0;
  double l2Mean = 0, l2Sd = 0, distMean = 0, distMin = 0;
  std::vector<double> radial;
};

std::string fmt(double v) { return formatNumber(v, "%.6g"); }

}  // namespace

int main(int argc, char** argv) {
  Params p;
  CLI::App app{"pointsets: discrepancy, minimum distance and power spectra of every sampler (aliaslab)"};
  setupCommandLine(app, "pointsets");
  app.add_option("--out", p.out, "Output folder")->capture_default_str();
  app.add_option("--counts", p.counts, "Point counts")->delimiter(',')->capture_default_str()->check(CLI::Range(2, 1 << 16));
  app.add_option("--sets", p.sets, "Independent sets per (sampler, N)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--extent", p.extent, "Periodogram half-width in units of sqrt(N)")
      ->capture_default_str()
      ->check(CLI::Range(0.5, 16.0));
  app.add_option("--seed", p.seed, "Sampler seed")->check(kSeed)->capture_default_str();
  app.add_option("--samplers", p.samplers, "Samplers (default: all)")->delimiter(',');
  app.add_option("--threads", p.threads, "Threads (0 = all cores)")->capture_default_str();
  app.add_flag("!--no-chart", p.chart, "Skip the chart (analysis/pointset_chart.py)");
  if (const int rc = parseCommandLine(app, argc, argv, "pointsets"); rc >= 0) return rc;

  try {
    // Validate everything before work: every sampler at every count.
    if (p.samplers.empty()) p.samplers = samplerNames();
    for (const auto& s : p.samplers)
      for (int n : p.counts)
        relabelOption("--sampler", "--samplers",
                      [&] { relabelOption("--spp", "--counts", [&] { makeSampler(s, n, p.seed); }); });
    if (p.threads < 0) throw OptionError("--threads", "must be >= 0, found " + std::to_string(p.threads));
    requireOutputFolders({{p.out, "--out"}});

    // One job per (sampler, N); each writes only its own result and images.
    std::vector<Result> results(p.samplers.size() * p.counts.size());
    parallelFor(static_cast<int>(results.size()), p.threads, [&](int job) {
      Result& r = results[job];
      r.sampler = p.samplers[job / p.counts.size()];
      r.n = p.counts[job % p.counts.size()];
      auto sampler = makeSampler(r.sampler, r.n, p.seed);
      r.warning = sampler->warning();
      Periodogram pg(static_cast<int>(std::lround(p.extent * std::sqrt(double(r.n)))));
      std::vector<Vec2> pts(r.n);
      double l2 = 0, l2sq = 0;
      r.distMin = 1e300;
      for (int k = 0; k < p.sets; ++k) {
        sampler->generate(k % 8, k / 8, pts.data());
        const double d = l2StarDiscrepancy(pts), md = minToroidalDistance(pts);
        l2 += d, l2sq += d * d, r.distMean += md, r.distMin = std::min(r.distMin, md);
        pg.add(pts);
        if (k == 0)
          writeImage((fs::path(p.out) / ("points_" + r.sampler + "_" + std::to_string(r.n) + ".png")).string(),
                     plotPointSet(pts, r.n > 256 ? 512 : 320));
      }
      r.l2Mean = l2 / p.sets;
      r.l2Sd = p.sets > 1 ? std::sqrt(std::max(0.0, (l2sq - l2 * l2 / p.sets) / (p.sets - 1))) : 0.0;
      r.distMean /= p.sets;
      r.radial = radialSpectrum(pg);
      writeImage((fs::path(p.out) / ("periodogram_" + r.sampler + "_" + std::to_string(r.n) + ".png")).string(),
                 plotPeriodogram(pg));
    });

    // Tables.
    std::ostringstream table, spectra;
    table << "sampler,n,sets,l2star_mean,l2star_sd,min_dist_mean,min_dist_min,min_dist_norm_mean,warning\n";
    spectra << "sampler,n,sets,k,k_norm,power\n";
    for (const Result& r : results) {
      std::string warning = r.warning;
      std::replace(warning.begin(), warning.end(), ',', ';');
      table << r.sampler << ',' << r.n << ',' << p.sets << ',' << fmt(r.l2Mean) << ',' << fmt(r.l2Sd) << ','
            << fmt(r.distMean) << ',' << fmt(r.distMin) << ',' << fmt(r.distMean / idealPackingDistance(r.n)) << ','
            << warning << '\n';
      for (size_t k = 1; k < r.radial.size(); ++k)
        spectra << r.sampler << ',' << r.n << ',' << p.sets << ',' << k << ',' << fmt(k / std::sqrt(double(r.n))) << ','
                << fmt(r.radial[k]) << '\n';
    }
    writeTextFile((fs::path(p.out) / "pointsets.csv").string(), table.str());
    writeTextFile((fs::path(p.out) / "spectra.csv").string(), spectra.str());

    // Charts through the Python plotter (arguments passed as they are: no shell).
    if (p.chart && runProgram({"/usr/bin/python3", std::string(ALIASLAB_SOURCE_DIR) + "/analysis/pointset_chart.py",
                               p.out, "--out", p.out}) != 0)
      std::cerr << "pointsets: warning: the chart failed (analysis/pointset_chart.py); the CSVs and images are written\n";
    std::cout << "wrote " << p.out << "/pointsets.csv, spectra.csv and images\n";
  } catch (const InputError& e) {
    std::cerr << "pointsets: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pointsets: failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
