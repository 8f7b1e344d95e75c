// sweep: scenes x samplers x spp x prefilter x filters x radii x reconstruction modes,
// K seeds each, one CSV row per configuration (lib/study/sweep.h).
//
//   sweep --scenes scenes/zoneplate.txt --samplers uniform,jittered --spp 16
//         --filters box,tent --radii 0.5,1,1.5 --seeds 8 --out results/mystudy   (one command)
//   sweep --preset default                     (the default study, results/study)
//   sweep --preset full                        (the full reference study, results/study_full;
//                                               run it sharded: experiments/run_full_study.sh)
//   sweep ... --target gaussian:1.5            (decompose the error against another common target)
//   sweep ... --shard 2/8                      (a deterministic eighth of the groups; i from 0 to N-1)
//   sweep --merge out.csv shard0.csv shard1.csv ...   (join shards, canonical order)
// Rerunning the same command resumes. Exit codes: 0 done, 2 bad input, 1 failure.
#include "aliaslab_paths.h"
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/cli.h"
#include "core/error.h"
#include "filter/filter.h"
#include "sampling/sampler.h"
#include "study/config.h"
#include "study/contact.h"
#include "study/csv.h"
#include "study/lock.h"
#include "study/spectrum_files.h"
#include "study/sweep.h"

using namespace aliaslab;

namespace {
constexpr int kFullRefSpp = 8192;

// The default study: every scene, small sizes, course + modern samplers and
// filters; measured to finish in under 10 minutes on 2 cores (results/study_speed.md).
void applyDefaultPreset(StudyConfig& c) {
  c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes"};
  c.samplers = {"random",  "uniform", "jittered",
                "sobol",   "pmj02",   "bluenoise",
                "zsobol",  "bluenoise-dither:random", "adaptive-contrast:jittered"};
  c.spp = {4, 16, 64};
  c.filters = {"box", "tent", "gaussian", "mitchell", "lanczos"};
  c.radii = {0.5, 1.0, 2.0};
  c.reconstruction = {"weighted"};
  c.seeds = 8;
  c.refSpp = 512;
  c.maxSize = 48;
  c.out = "results/study";
  c.images = true;
}

// The full reference study (docs/science.md, "The full study"): every bundled scene at 256 px on the
// larger side, every sampler and filter, radii 0.5-2, spp 4, 16, 64, 8 seeds, references at 8192 spp.
// Hours on 2 cores (results/study_speed.md, "The full study"): run it sharded.
void applyFullPreset(StudyConfig& c) {
  c.scenes = {std::string(ALIASLAB_SOURCE_DIR) + "/scenes"};
  c.samplers = samplerNames();
  c.spp = {4, 16, 64};
  c.filters = filterNames();
  c.radii = {0.5, 1.0, 1.5, 2.0};
  c.reconstruction = {"weighted"};
  c.seeds = 8;
  c.refSpp = kFullRefSpp;
  c.longSide = 256;
  c.out = "results/study_full";
  c.images = false;
}
}  // namespace

int main(int argc, char** argv) {
  StudyConfig c;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--preset" && std::string(argv[i + 1]) == "default") applyDefaultPreset(c);
    else if (std::string(argv[i]) == "--preset" && std::string(argv[i + 1]) == "full") applyFullPreset(c);

  CLI::App app{"sweep: measure aliasing, noise and time over samplers x filters x radii (aliaslab)"};
  setupCommandLine(app, "sweep");
  std::string preset, shard;
  std::vector<int> size;
  std::vector<std::string> merge;
  app.set_config("--config", "", "read options from a TOML/INI file (keys = long option names)");
  app.add_option("--preset", preset,
                 "'default': the quick default study (results/study); 'full': the full reference study at 256 px "
                 "(results/study_full, hours: run experiments/run_full_study.sh); explicit options still override")
      ->check(CLI::IsMember({"default", "full"}));
  app.add_option("--scenes", c.scenes, "scene files or folders of *.txt")->delimiter(',');
  app.add_option("--samplers", c.samplers, "sampler names")->delimiter(',')->capture_default_str();
  app.add_option("--spp", c.spp, "samples per pixel list")->delimiter(',')->capture_default_str();
  app.add_option("--filters", c.filters, "filter names")->delimiter(',')->capture_default_str();
  app.add_option("--radii", c.radii, "filter radii in pixels (box also gets its classic 0.5)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--reconstruction", c.reconstruction, "weighted|classic|importance|supersample")
      ->delimiter(',')->capture_default_str();
  app.add_option("--prefilter", c.prefilter,
                 "none|footprint: texture pre-filtering over each hit's pixel footprint, crossed with the rest "
                 "(references stay un-prefiltered; docs/prefiltering.md)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--seeds", c.seeds, "K independent seeds per configuration (>= 2)")->capture_default_str();
  app.add_option("--ref-spp", c.refSpp, "reference samples per pixel")->capture_default_str();
  app.add_option("--ref-sampler", c.refSampler, "reference sampler")->capture_default_str();
  app.add_option("--size", size, "W H: image size for every scene (default: each scene's # render: line)")
      ->expected(2);
  app.add_option("--max-size", c.maxSize, "scale scenes down so the larger side is at most this (0 = off)")
      ->capture_default_str();
  app.add_option("--long-side", c.longSide,
                 "scale scenes up or down so the larger side is exactly this (0 = off; overrides --max-size)")
      ->capture_default_str();
  app.add_option("--target", c.target,
                 "the common target T of mse_target, blur and cross: 'area' (the pixel-area reference, box r=0.5, "
                 "written box:0.5) or filter:radius, e.g. gaussian:1.5 or lanczos:2, rendered and cached with the "
                 "references (definitions: docs/science.md)")
      ->capture_default_str();
  app.add_option("--out", c.out, "output folder (CSV, images, reference manifests)")->capture_default_str();
  app.add_option("--csv", c.csv, "CSV path (default OUT/study.csv, or OUT/study.shard-i-of-N.csv)");
  app.add_option("--cache", c.cache, "reference cache folder")->capture_default_str();
  app.add_option("--threads", c.threads, "worker threads (0 = all cores)")->capture_default_str();
  bool imagesOn = false, imagesOff = false, quiet = false;
  app.add_flag("--images", imagesOn, "write images (default: when the study has at most 200 configurations)");
  app.add_flag("--no-images", imagesOff, "write no images");
  app.add_option("--shard", shard, "i/N, i = 0..N-1: run the groups g with g mod N == i");
  app.add_flag("--refs-only", c.refsOnly, "render and cache the references, then stop");
  app.add_flag("--quiet", quiet, "no progress output");
  app.add_option("--merge", merge, "merge the shard CSVs IN1 IN2 ... into OUT in canonical order, then stop")
      ->expected(2, -1)->option_text("OUT IN1 [IN2 ...]");
  if (const int rc = parseCommandLine(app, argc, argv, "sweep"); rc >= 0) return rc;

  try {
    if (!merge.empty()) {
      checkShardSet(std::vector<std::string>(merge.begin() + 1, merge.end()));
      const CsvLock lock(merge[0], "sweep --merge");
      mergeCsvFiles(merge[0], std::vector<std::string>(merge.begin() + 1, merge.end()));
      // and the shards' spectra (spectra/<scene>.<shard>.csv) into the merged CSV's
      mergeSpectrumFiles(merge[0], std::vector<std::string>(merge.begin() + 1, merge.end()));
      // Contact sheets of the whole study when the shards wrote images beside it.
      const auto images = std::filesystem::path(merge[0]).parent_path() / "images";
      if (std::filesystem::is_directory(images)) writeContactSheets(merge[0], images.string());
      std::printf("merged %zu files into %s\n", merge.size() - 1, merge[0].c_str());
      return 0;
    }
    if (imagesOn && imagesOff) throw OptionError("--images", "give --images or --no-images, not both");
    if (imagesOn || imagesOff) c.images = imagesOn;
    c.progress = !quiet;
    if (!size.empty()) c.width = size[0], c.height = size[1];
    if (!shard.empty()) parseShard(shard, c.shardIndex, c.shardCount);
    const SweepSummary s = runSweep(c);
    if (!c.refsOnly)
      std::printf("%zu rows written, %zu resumed, %zu sample sets traced (%llu primary rays) in %.1f s -> %s\n",
                  s.rowsWritten, s.rowsSkipped, s.sampleSetsTraced + s.importanceTraces,
                  static_cast<unsigned long long>(s.primaryRays), s.seconds, csvPath(c).c_str());
    if (!c.refsOnly && s.sampleSetsTraced + s.importanceTraces > 0) {  // where the time went (work of this run)
      const SweepPhases& p = s.phases;
      std::printf("thread-seconds: trace %.1f, splat %.1f, resolve %.1f, flip %.1f, metrics and spectra %.1f, "
                  "set-up %.1f, finish %.1f, idle %.1f; main thread: references %.1f s, output %.1f s\n",
                  p.trace, p.splat, p.resolve, p.flip, p.metrics, p.setup, p.finish, p.waiting, p.references, p.io);
    }
    if (c.refsOnly)
      std::printf("references ready in %s (%.1f s)\n", c.cache.c_str(), s.seconds);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: failed: %s\n", e.what());
    return 1;
  }
}
