// convergence: RMSE against N for every sampler on the analytic integrands
// of docs/science.md, the fitted log-log slopes, and a table comparing them with
// the slopes theory expects.
//
// Output in --out: convergence.csv (sampler,integrand,n,rmse,realisations) and
// slopes.md; the chart convergence.png is drawn from the CSV by
// `/usr/bin/python3 -m analysis convergence` (the command is printed at the end).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "common/cli.h"
#include "common/front_end.h"
#include "common/sampler_study_options.h"
#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "measure/convergence_study.h"
#include "sampling/sampler.h"
#include "study/validate.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {
// The library's keys in this program's flags.
const FrontEnd kConvergence{"convergence", {{"sampler", "--samplers"}, {"out", "--out"}, {"threads", "--threads"}}};
}  // namespace

int main(int argc, char** argv) {
  ConvergenceStudy p;
  std::string out = "results/convergence";  // output folder
  CLI::App app{"convergence: RMSE against N of every sampler on the analytic integrands, with fitted slopes (aliaslab)"};
  addSamplerStudyOptions(app, "convergence", out, p);
  app.add_option("--realisations", p.realisations, "Independent sets per (sampler, N)")->capture_default_str()
      ->check(CLI::Range(2, 1 << 20));
  app.add_option("--max-n", p.maxN, "Largest N")->capture_default_str()->check(CLI::Range(16, 1 << 16));
  auto* fitMinOpt = app.add_option("--fit-min", p.fitMin, "Smallest N in the slope fit (at most --max-n / 2 by default)")
                        ->capture_default_str();
  app.add_option("--fit-max", p.fitMax, "Largest N in the slope fit")->capture_default_str();
  if (const int rc = parseCommandLine(app, argc, argv, "convergence"); rc >= 0) return rc;

  return runFrontEnd(kConvergence, [&] {
    // Validate everything before work.
    if (p.samplers.empty()) p.samplers = samplerNames();
    for (const auto& s : p.samplers)  // unknown names fail before any work
      makeSampler(s, 1 << 4, p.seed);
    if (p.threads < 0) throw OptionError("--threads", "must be >= 0, found " + std::to_string(p.threads));
    if (!(std::isfinite(p.fitMin) && p.fitMin >= 1))
      throw OptionError("--fit-min", "must be a number >= 1, found " + formatNumber(p.fitMin));
    if (!(std::isfinite(p.fitMax) && p.fitMax >= 1))
      throw OptionError("--fit-max", "must be a number >= 1, found " + formatNumber(p.fitMax));
    p.fitMax = std::min<double>(p.fitMax, p.maxN);  // the fit can only use measured N
    if (!fitMinOpt->count()) p.fitMin = std::min<double>(p.fitMin, p.maxN / 2);
    if (powersOfTwoInRange(convergenceSampleCounts(p.maxN), p.fitMin, p.fitMax) < 2)
      throw OptionError("--fit-min", "the fit range [" + formatNumber(p.fitMin) + ", " + formatNumber(p.fitMax) +
                                         "] (--fit-max capped at --max-n) holds fewer than two powers of two");
    requireOutputFolders({{out, "out"}});

    // Measure: one CSV row per (sampler, integrand, N); then the fitted slopes against theory.
    const auto rows = measureConvergence(p, std::cerr);
    writeTextFile((fs::path(out) / "convergence.csv").string(), convergenceCsv(rows, p.realisations));
    writeTextFile((fs::path(out) / "slopes.md").string(), slopesTable(p, rows));

    std::cout << "wrote " << out << "/convergence.csv and slopes.md; the chart, from the repository root:\n"
              << "  /usr/bin/python3 -m analysis convergence " << (fs::path(out) / "convergence.csv").string()
              << " --out " << out << " --fit-min " << formatNumber(p.fitMin) << " --fit-max " << formatNumber(p.fitMax)
              << "\n";
    return 0;
  });
}
