// sweep: scenes x samplers x spp x prefilter x filters x radii x reconstruction modes,
// K seeds each, one CSV row per configuration and target (lib/study/sweep/sweep.h).
//
//   sweep --scenes scenes/zoneplate.txt --samplers uniform,jittered --spp 16
//         --filters box,tent --radii 0.5,1,1.5 --seeds 8 --out results/mystudy   (one command)
//   sweep --preset default                     (the quick study: every bundled scene at most 48 px, results/study)
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
#include "core/files.h"
#include "study/config.h"
#include "study/records/contract.h"
#include "study/records/merge.h"
#include "study/sweep/motion_frame.h"
#include "study/presets.h"
#include "study/sweep/sweep.h"
#include "options.h"

using namespace aliaslab;

namespace {
// The samplers' bounds on the finished CSV (study/records/contract.h): a summary line, and every violation as a warning.
void printContract(const std::vector<ContractCheck>& checks, std::FILE* summary = stdout) {
  if (checks.empty()) return;
  std::fprintf(summary, "%s\n", contractSummary(checks).c_str());
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
  // The preset first, read by the same parser as every option (--preset X, --preset=X, preset = X in --config),
  // so that the options given explicitly override it.
  SweepArgs a;
  if (const std::string preset = commandLinePreset(argc, argv); !preset.empty()) applyStudyPreset(preset, a.c);
  CLI::App app{"sweep: measure aliasing, noise and time over samplers x filters x radii (aliaslab)"};
  setupCommandLine(app, "sweep");
  addSweepOptions(app, a);
  if (const int rc = parseCommandLine(app, argc, argv, "sweep"); rc >= 0) return rc;

  StudyConfig& c = a.c;
  return runFrontEnd(kSweep, [&] {
    if (!a.merge.empty()) {
      mergeStudy(a.merge[0], std::vector<std::string>(a.merge.begin() + 1, a.merge.end()), "sweep --merge");
      // Messages on stderr: the output may be stdout or a pipe, which must carry the CSV alone.
      std::fprintf(stderr, "merged %zu files into %s\n", a.merge.size() - 1, a.merge[0].c_str());
      if (outputTarget(a.merge[0]).special)  // a stream cannot be read back (and has no spectra beside it)
        std::fprintf(stderr, "note: %s is not a regular file: the CSV only (no spectra, contact sheets or sampler "
                     "bound check)\n", a.merge[0].c_str());
      else
        printContract(checkContract(contractRows(a.merge[0])), stderr);
      return 0;
    }
    if (a.imagesOn && a.imagesOff) throw OptionError("--images", "give --images or --no-images, not both");
    if (a.imagesOn || a.imagesOff) c.images = a.imagesOn;
    c.progress = !a.quiet;
    if (!a.size.empty() && (a.size[0] <= 0 || a.size[1] <= 0))  // (0 0 would silently mean "each scene's own size")
      throw OptionError("size", "expected two positive numbers W H, found " + std::to_string(a.size[0]) + " " +
                                    std::to_string(a.size[1]) + " (leave --size out for each scene's own size)");
    if (!a.size.empty()) c.width = a.size[0], c.height = a.size[1];
    if (!a.shard.empty()) parseShard(a.shard, c.shardIndex, c.shardCount);
    if (!a.motion.empty()) std::tie(c.motionDx, c.motionDy) = parseMotion(a.motion), c.motionGiven = true;
    if (app.count("--radii")) setStudyRadii(c, a.radii);
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
