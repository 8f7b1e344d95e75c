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
// --dump FILE also writes every point measured, as CSV sampler,n,px,py,k,x,y (the set of pixel (px, py), point
// k at (x, y) in [0,1)^2, %.9g: the floats exactly), e.g. for the Python module's test of points().
// The charts spectra.png and discrepancy.png are drawn from the CSVs by
// `/usr/bin/python3 -m analysis pointsets` (the command is printed at the end).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "common/cli.h"
#include "common/front_end.h"
#include "common/sampler_study_options.h"
#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "measure/pointset_study.h"
#include "sampling/sampler.h"
#include "study/validate.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {
// The library's keys in this program's flags.
const FrontEnd kPointsets{"pointsets", {{"sampler", "--samplers"}, {"spp", "--counts"}, {"out", "--out"}, {"threads", "--threads"}}};

/// The --dump table: every point of every set the study measures (measurePointSets' pixels (k mod 8, k / 8)).
std::string pointDump(const PointSetStudy& p) {
  std::ostringstream os;
  os << "sampler,n,px,py,k,x,y\n";
  for (const auto& name : p.samplers)
    for (int n : p.counts) {
      const auto sampler = makeSampler(name, n, p.seed);
      std::vector<Vec2> pts(n);
      for (int set = 0; set < p.sets; ++set) {
        sampler->generate(set % 8, set / 8, pts.data());
        for (int k = 0; k < n; ++k)
          os << name << ',' << n << ',' << set % 8 << ',' << set / 8 << ',' << k << ',' << formatNumber(pts[k].x(), "%.9g")
             << ',' << formatNumber(pts[k].y(), "%.9g") << '\n';
      }
    }
  return os.str();
}
}  // namespace

int main(int argc, char** argv) {
  PointSetStudy p;
  std::string out = "results/pointsets";  // output folder
  CLI::App app{"pointsets: discrepancy, minimum distance and power spectra of every sampler (aliaslab)"};
  addSamplerStudyOptions(app, "pointsets", out, p);
  app.add_option("--counts", p.counts, "Point counts")->delimiter(',')->capture_default_str()->check(CLI::Range(2, 1 << 16));
  app.add_option("--sets", p.sets, "Independent sets per (sampler, N)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--extent", p.extent, "Periodogram half-width in units of sqrt(N)")
      ->capture_default_str()
      ->check(CLI::Range(0.5, 16.0));
  std::string dump;
  app.add_option("--dump", dump, "Also write every point measured to this CSV (sampler,n,px,py,k,x,y)");
  if (const int rc = parseCommandLine(app, argc, argv, "pointsets"); rc >= 0) return rc;

  return runFrontEnd(kPointsets, [&] {
    // Validate everything before work: every sampler at every count.
    if (p.samplers.empty()) p.samplers = samplerNames();
    for (const auto& s : p.samplers)
      for (int n : p.counts)
        makeSampler(s, n, p.seed);
    if (p.threads < 0) throw OptionError("--threads", "must be >= 0, found " + std::to_string(p.threads));
    requireOutputFolders({{out, "out"}});
    if (!dump.empty() && fs::is_directory(dump)) throw OptionError("--dump", "'" + dump + "' is a folder; give a CSV file name");

    // Every (sampler, N) measured (its pictures written), then the tables.
    const auto stats = measurePointSets(p, out);
    writeTextFile((fs::path(out) / "pointsets.csv").string(), pointSetTableCsv(stats, p.sets));
    writeTextFile((fs::path(out) / "spectra.csv").string(), pointSetSpectraCsv(stats, p.sets));
    if (!dump.empty()) writeTextFile(dump, pointDump(p));

    std::cout << "wrote " << out << "/pointsets.csv, spectra.csv and images; the charts, from the repository root:\n"
              << "  /usr/bin/python3 -m analysis pointsets " << out << " --out " << out << "\n";
    return 0;
  });
}
