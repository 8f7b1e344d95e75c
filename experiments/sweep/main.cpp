// sweep: scenes x samplers x spp x prefilter x filters x radii x reconstruction modes,
// K seeds each, one CSV row per configuration and target (lib/study/sweep.h).
//
//   sweep --scenes scenes/zoneplate.txt --samplers uniform,jittered --spp 16
//         --filters box,tent --radii 0.5,1,1.5 --seeds 8 --out results/mystudy   (one command)
//   sweep --preset default                     (the quick study: every bundled scene at 48 px, results/study)
//   sweep --preset presented                   (the presented study: every bundled scene at 256 px,
//                                               results/presented; sharded: experiments/run_presented_study.sh)
//   sweep ... --radii 0.5,1,2,natural          (every filter also at its own natural radius)
//   sweep ... --align-offsets 8                (the fixed grid's error over 8 seeded sub-pixel camera offsets)
//   sweep ... --target area,gaussian:1.5       (the targets the error is decomposed against; first = primary)
//   sweep ... --frames 8 --motion 0.25,0       (aliasing in motion: 8 frames of a camera moving 0.25 px per frame)
//   sweep ... --shard 2/8                      (a deterministic eighth of the groups; i from 0 to N-1)
//   sweep --merge out.csv shard0.csv shard1.csv ...   (join shards, canonical order)
// Rerunning the same command resumes. Exit codes: 0 done, 2 bad input, 1 failure.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "common/cli.h"
#include "common/front_end.h"
#include "core/error.h"
#include "study/config.h"
#include "study/contract.h"
#include "study/merge.h"
#include "study/motion_frame.h"
#include "study/presets.h"
#include "study/sweep.h"

using namespace aliaslab;

namespace {
// The samplers' bounds on the finished CSV (study/contract.h): a summary line, and every violation as a warning.
void printContract(const std::vector<ContractCheck>& checks) {
  if (checks.empty()) return;
  std::printf("%s\n", contractSummary(checks).c_str());
  for (const std::string& v : contractViolations(checks))
    std::fprintf(stderr, "warning: sampler bound violated (the pattern misbehaves in this render): %s\n", v.c_str());
}

// The library's keys in this program's flags (factory keys: the lists they are checked from).
const FrontEnd kSweep{"sweep",
                      {{"scenes", "--scenes"},       {"samplers", "--samplers"},     {"sampler", "--samplers"},
                       {"spp", "--spp"},             {"filters", "--filters"},       {"filter", "--filters"},
                       {"radii", "--radii"},         {"radius", "--radii"},          {"filter-param", "--filters"},
                       {"reconstruction", "--reconstruction"}, {"prefilter", "--prefilter"},
                       {"seeds", "--seeds"},         {"ref-spp", "--ref-spp"},       {"ref-batch", "--ref-batch"},
                       {"ref-sampler", "--ref-sampler"}, {"size", "--size"},        {"max-size", "--max-size"},
                       {"long-side", "--long-side"}, {"target", "--target"},         {"out", "--out"},
                       {"csv", "--csv"},             {"cache", "--cache"},           {"threads", "--threads"},
                       {"shard", "--shard"},         {"merge", "--merge"},           {"grid", "-grid"},
                       {"frames", "--frames"},       {"motion", "--motion"},         {"align-offsets", "--align-offsets"},
                       {"align-ref-spp", "--align-ref-spp"}}};
}  // namespace

int main(int argc, char** argv) {
  StudyConfig c;  // a preset first, so that explicit options override it
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--preset") applyStudyPreset(argv[i + 1], c);

  CLI::App app{"sweep: measure aliasing, noise and time over samplers x filters x radii (aliaslab)"};
  setupCommandLine(app, "sweep");
  std::string preset, shard, motion;
  std::vector<int> size;
  std::vector<std::string> merge;
  app.set_config("--config", "", "read options from a TOML/INI file (keys = long option names)");
  app.add_option("--preset", preset,
                 "'default': the quick study, every bundled scene at 48 px (results/study); 'presented': the study "
                 "results/index.html presents, every bundled scene at 256 px, every sampler and filter at radii "
                 "0.5,1,2,natural (results/presented; over an hour on 2 cores: experiments/run_presented_study.sh shards "
                 "it); both with spp 4,16,64, 8 seeds, references at 4096 spp, the fixed grid at 8 camera offsets "
                 "(their references at 256 spp) and three "
                 "targets (docs/science.md \"The bundled studies\"); explicit options still override")
      ->check(CLI::IsMember(studyPresetNames()));
  app.add_option("--scenes", c.scenes, "scene files or folders of *.txt")->delimiter(',');
  app.add_option("--samplers", c.samplers, "sampler names")->delimiter(',')->capture_default_str();
  app.add_option("--spp", c.spp, "samples per pixel list")->delimiter(',')->capture_default_str();
  app.add_option("--filters", c.filters, "filter names")->delimiter(',')->capture_default_str();
  std::vector<std::string> radii = studyRadiusTokens(c);
  app.add_option("--radii", radii,
                 "filter radii in pixels, and 'natural': every filter also at its own natural radius (box 0.5, "
                 "tent 1, gaussian 1.5, mitchell, catmullrom and blackmanharris 2, lanczos and hann 3), each "
                 "(filter, radius) once; box also gets its classic 0.5")
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
  app.add_option("--target", c.targets,
                 "the targets T of mse_target, blur, cross, blurred_mse and lowfreq_error, a comma list (first = "
                 "primary; one CSV row per configuration and target): 'area' (the pixel-area reference, box r=0.5, "
                 "written box:0.5) or filter:radius, e.g. gaussian:1.5 or lanczos:3; each is another reference "
                 "rendered and cached with the others (definitions: docs/science.md)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--frames", c.frames,
                 "F frames of a moving camera per configuration and seed (1: a still study; F > 1 adds the CSV's "
                 "motion columns: shimmer and flicker, docs/science.md \"Motion\")")
      ->capture_default_str();
  app.add_option("--motion", motion, "dx,dy: the camera's motion in pixels per frame (with --frames; default 0.25,0)");
  app.add_option("--align-offsets", c.alignOffsets,
                 "K: the fixed grid (sampler uniform) also measured over K seeded sub-pixel camera offsets, each "
                 "against the targets rendered at that offset (CSV columns align_*; 0 = off; docs/science.md \"The "
                 "grid and alignment\")")
      ->capture_default_str();
  app.add_option("--align-ref-spp", c.alignRefSpp, "samples per pixel of the references at each alignment offset")
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

  return runFrontEnd(kSweep, [&] {
    if (!merge.empty()) {
      mergeStudy(merge[0], std::vector<std::string>(merge.begin() + 1, merge.end()), "sweep --merge");
      std::printf("merged %zu files into %s\n", merge.size() - 1, merge[0].c_str());
      printContract(checkContract(contractRows(merge[0])));
      return 0;
    }
    if (imagesOn && imagesOff) throw OptionError("--images", "give --images or --no-images, not both");
    if (imagesOn || imagesOff) c.images = imagesOn;
    c.progress = !quiet;
    if (!size.empty() && (size[0] <= 0 || size[1] <= 0))  // (0 0 would silently mean "each scene's own size")
      throw OptionError("size", "expected two positive numbers W H, found " + std::to_string(size[0]) + " " +
                                    std::to_string(size[1]) + " (leave --size out for each scene's own size)");
    if (!size.empty()) c.width = size[0], c.height = size[1];
    if (!shard.empty()) parseShard(shard, c.shardIndex, c.shardCount);
    if (!motion.empty()) std::tie(c.motionDx, c.motionDy) = parseMotion(motion), c.motionGiven = true;
    if (app.count("--radii")) setStudyRadii(c, radii);
    const SweepSummary s = runSweep(c);
    if (!c.refsOnly)
      std::printf("%zu rows written, %zu resumed, %zu sample sets traced (%llu primary rays) in %.1f s -> %s\n",
                  s.rowsWritten, s.rowsSkipped, s.sampleSetsTraced + s.importanceTraces,
                  static_cast<unsigned long long>(s.primaryRays), s.seconds, csvPath(c).c_str());
    printContract(s.contract);
    if (s.nonFiniteSamples > 0)
      std::fprintf(stderr, "warning: %zu NaN or infinite samples (light or colour beyond float range, about 3.4e38) "
                   "were left out of this run's images; the CSV's nonfinite_samples column counts them per row\n",
                   s.nonFiniteSamples);
    if (!c.refsOnly && s.sampleSetsTraced + s.importanceTraces > 0) {  // where the time went (work of this run)
      const SweepPhases& p = s.phases;
      std::printf("thread-seconds: trace %.1f, splat %.1f, resolve %.1f, flip %.1f, metrics and spectra %.1f, "
                  "set-up %.1f, finish %.1f, idle %.1f; main thread: references %.1f s, output %.1f s\n",
                  p.trace, p.splat, p.resolve, p.flip, p.metrics, p.setup, p.finish, p.waiting, p.references, p.io);
      if (c.frames > 1) std::printf("frames: %.1f s of the frames pass (%d frames per seed)\n", p.motion, c.frames);
      if (p.alignment > 0 || p.alignmentReferences > 0)
        std::printf("alignment: the fixed grid at %d camera offsets: references %.1f s, the grid's passes %.1f s\n",
                    c.alignOffsets, p.alignmentReferences, p.alignment);
    }
    if (const SweepPhases& p = s.phases; p.refTrace + p.refSplat + p.refResolve > 0)  // references rendered here
      std::printf("references' thread-seconds: trace %.1f, splat %.1f, resolve %.1f (splat / trace %.2f)\n",
                  p.refTrace, p.refSplat, p.refResolve, p.refTrace > 0 ? p.refSplat / p.refTrace : 0.0);
    if (c.refsOnly)
      std::printf("references ready in %s (%.1f s)\n", c.cache.c_str(), s.seconds);
    return 0;
  });
}
