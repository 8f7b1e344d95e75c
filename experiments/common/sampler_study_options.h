// The command line the samplers' own studies (convergence, pointsets) share, set up in one call: the help
// layout and --version (setupCommandLine), then --out (folder), --seed, --samplers (default: all), --threads and
// --no-chart (ignored, kept for old scripts: the charts are drawn by `python3 -m analysis <program>`).
// `Study` has the fields seed, samplers and threads (measure/convergence_study.h, measure/pointset_study.h).
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "common/cli.h"

namespace aliaslab {

template <class Study>
void addSamplerStudyOptions(CLI::App& app, const std::string& program, std::string& out, Study& study) {
  setupCommandLine(app, program);
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_option("--seed", study.seed, "Sampler seed")->check(kSeed)->capture_default_str();
  app.add_option("--samplers", study.samplers, "Samplers to run (default: all)")->delimiter(',');
  app.add_option("--threads", study.threads, "Threads (0 = all cores)")->capture_default_str();
  app.add_flag("--no-chart")
      ->description("Ignored, kept for old scripts: the charts are drawn by `python3 -m analysis " + program + "`");
}

}  // namespace aliaslab
