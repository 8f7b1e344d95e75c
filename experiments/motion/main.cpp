// motion: aliasing in motion (docs/science.md, "Motion"; lib/study/motion_study.h). For one scene, F frames of
// a camera moving by dx,dy pixels per frame, every sampler x spp x filter:radius rendered with K seeds in every
// frame, against per-frame references; writes one CSV row per configuration (shimmer, flickers, blur, noise,
// the still image's mse_target). Bad options exit 2 before any work; progress goes to stderr. The quick
// one-scene form of `sweep --frames F --motion dx,dy` (study/sweep_motion.h), which adds the same measures to
// the study CSV for every scene, target and reconstruction mode; both use measure/motion.h.
//
//   motion --scene scenes/motion/grating.txt --filters box:0.5,gaussian:1,gaussian:1.5,gaussian:2
//          --frames 8 --motion 0.25,0 --output results/motion/grating.csv
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "common/cli.h"
#include "common/front_end.h"
#include "core/error.h"
#include "core/files.h"
#include "study/motion_study.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {
const FrontEnd kMotion{"motion",
                       {{"frames", "--frames"}, {"motion", "--motion"}, {"seeds", "--seeds"}, {"spp", "--spp"},
                        {"size", "--size"}, {"sampler", "--samplers"}, {"filter", "--filters"},
                        {"radius", "--filters"}, {"filter-param", "--filters"}, {"ref-spp", "--ref-spp"},
                        {"ref-batch", "--ref-spp"}, {"threads", "--threads"}}};
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"motion: shimmer and flicker of a moving camera, beside blur and noise (aliaslab)"};
  setupCommandLine(app, "motion");
  MotionStudyConfig c;
  c.reference.spp = 1024;
  std::vector<std::string> filters = {"box:0.5", "gaussian:1", "gaussian:1.5", "gaussian:2"};
  std::vector<double> motion = {0.25, 0};
  std::string out = "motion.csv";  // --output: the CSV file
  app.add_option("--scene", c.scene, "scene file")->required();
  app.add_option("--samplers", c.samplers, "sampler names")->delimiter(',')->capture_default_str();
  app.add_option("--spp", c.spp, "samples per pixel (list)")->delimiter(',')->capture_default_str();
  app.add_option("--filters", filters, "filter:radius pairs, e.g. gaussian:1.5")->delimiter(',')->capture_default_str();
  app.add_option("--seeds", c.seeds, "K independent seeds per frame")->capture_default_str();
  app.add_option("--frames", c.frames, "F frames (at least 2)")->capture_default_str();
  app.add_option("--motion", motion, "dx,dy: camera motion in pixels per frame")->delimiter(',')->expected(2)
      ->capture_default_str();
  app.add_option("--size", c.size, "longer side in pixels (0: the scene's # render: line)")->capture_default_str();
  app.add_option("--ref-spp", c.reference.spp, "samples per pixel of each frame's references")->capture_default_str();
  app.add_option("--cache", c.cache, "reference cache folder (shared with sweep --cache)");
  app.add_option("--threads", c.threads, "worker threads (0 = all cores; results do not depend on it)")
      ->capture_default_str();
  app.add_option("--output", out, "the CSV file")->capture_default_str();
  bool quiet = false;
  app.add_flag("--quiet", quiet, "no progress on stderr");
  if (const int rc = parseCommandLine(app, argc, argv, "motion"); rc >= 0) return rc;

  return runFrontEnd(kMotion, [&] {
    c.filters.clear();
    for (const std::string& f : filters) c.filters.push_back(parseFilterSpec(f));
    c.dx = motion[0], c.dy = motion[1];
    c.progress = !quiet;
    c.reference.threads = c.threads;
    if (c.threads < 0) throw OptionError("--threads", "must be >= 0 (0 = all cores)");
    if (!fs::is_regular_file(c.scene)) throw FileError(c.scene, "scene file not found (--scene)");
    const fs::path dir = fs::path(out).parent_path();
    if (!dir.empty() && !fs::is_directory(dir)) throw OptionError("--output", "'" + out + "': folder does not exist");
    validateMotionStudy(c);
    const std::vector<MotionRow> rows = runMotionStudy(c, std::cerr);
    writeTextFile(out, motionCsv(rows));
    if (!quiet) std::cerr << "motion: " << rows.size() << " rows -> " << out << "\n";
    return 0;
  });
}
